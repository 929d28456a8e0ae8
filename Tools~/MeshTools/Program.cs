using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using HookeRope.Fracture;
using HookeRope.Geometry;
using HookeRope.Radius;

namespace HookeRope.MeshTools
{
    /// <summary>Entry point: "mesh" prints ns per vertex of the tube mesh build; "texture" bakes the burr texture to a PNG.</summary>
    internal static class Program
    {
        private static int Main(string[] args)
        {
            string command = args.Length > 0 ? args[0] : "mesh";
            if (command == "mesh") return MeshBenchmark();
            if (command == "texture") return BakeTexture(args);
            Console.Error.WriteLine("usage: mesh | texture <file.png> [width] [height] [triangles] [seed]");
            return 2;
        }

        private static int MeshBenchmark()
        {
            const int segments = 200;
            var x = new float[segments + 1];
            var y = new float[segments + 1];
            var z = new float[segments + 1];
            var rest = new float[segments];
            var current = new float[segments];
            for (int i = 0; i <= segments; i++)
            {
                float a = 0.05f * i;
                x[i] = 0.3f * MathF.Cos(a); y[i] = 0.3f * MathF.Sin(a); z[i] = 0.004f * i;
            }
            for (int j = 0; j < segments; j++)
            {
                rest[j] = 0.01f;
                float dx = x[j + 1] - x[j], dy = y[j + 1] - y[j], dz = z[j + 1] - z[j];
                current[j] = MathF.Sqrt(dx * dx + dy * dy + dz * dz);
            }
            // The values the benchmark was measured with (the 0.1 core defaults), stated so a default change cannot move it.
            var model = new RadiusModel(new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, NeckMode = NeckMode.Zone, Necking = true, Fracture = true, BreakStrain = 1000f }, 0.005f, rest);
            Console.WriteLine("tube mesh, 200 segments, 4 rings per segment, helix, Zone neck, one break (burr):");
            foreach (int radial in new[] { 8, 16, 32 })
            {
                var settings = new TubeMeshSettings { RadialSegments = radial, RingsPerSegment = 4 };
                var builder = new TubeMeshBuilder(settings, segments);
                var broken = new bool[segments];
                broken[120] = true;
                var vertices = new TubeVertex[builder.GetVertexCount(broken)];
                var indices = new int[builder.GetIndexCount(broken)];
                var radii = new float[builder.Layout.RingCount];
                model.Update(current, broken);
                model.FillRingRadii(builder.Layout.RingSegments, builder.Layout.RingFractions, radii);
                for (int i = 0; i < 200; i++) builder.BuildWithRingRadii(x, y, z, rest, radii, broken, vertices, indices);
                double best = double.MaxValue;
                for (int round = 0; round < 5; round++)
                {
                    const int builds = 200;
                    var watch = Stopwatch.StartNew();
                    for (int i = 0; i < builds; i++)
                    {
                        x[7] += 1e-7f;
                        builder.BuildWithRingRadii(x, y, z, rest, radii, broken, vertices, indices);
                    }
                    watch.Stop();
                    best = Math.Min(best, watch.Elapsed.TotalMilliseconds * 1e6 / builds);
                }
                int count = builder.GetVertexCount(broken);
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                    "  radial {0,2}: {1,6} vertices, {2,8:F1} us per build, {3,5:F2} ns per vertex",
                    radial, count, best / 1000.0, best / count));
            }
            {
                var radii = new float[segments * 4 + 1];
                var layout = new RingLayout(segments, 4);
                for (int i = 0; i < 2000; i++) { model.Update(current, ReadOnlySpan<bool>.Empty); model.FillRingRadii(layout.RingSegments, layout.RingFractions, radii); }
                var watch = Stopwatch.StartNew();
                for (int i = 0; i < 20000; i++) model.Update(current, ReadOnlySpan<bool>.Empty);
                double update = watch.Elapsed.TotalMilliseconds * 1e6 / 20000;
                watch.Restart();
                for (int i = 0; i < 20000; i++) model.FillRingRadii(layout.RingSegments, layout.RingFractions, radii);
                double fill = watch.Elapsed.TotalMilliseconds * 1e6 / 20000;
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                    "radius model, 200 segments: Update {0:F2} ns per segment, FillRingRadii {1:F2} ns per ring", update / segments, fill / radii.Length));
            }
            return 0;
        }

        private static int BakeTexture(string[] args)
        {
            if (args.Length < 2) { Console.Error.WriteLine("texture needs an output file name"); return 2; }
            int width = args.Length > 2 ? int.Parse(args[2], CultureInfo.InvariantCulture) : 256;
            int height = args.Length > 3 ? int.Parse(args[3], CultureInfo.InvariantCulture) : 256;
            int triangles = args.Length > 4 ? int.Parse(args[4], CultureInfo.InvariantCulture) : 16;
            uint seed = args.Length > 5 ? uint.Parse(args[5], CultureInfo.InvariantCulture) : 1u;
            var rgba = new byte[BurrTextureGenerator.ByteCount(width, height)];
            BurrTextureGenerator.Generate(width, height, triangles, seed, 214, 196, 160, rgba);
            File.WriteAllBytes(args[1], PngWriter.Encode(width, height, rgba, true));
            Console.WriteLine("wrote " + args[1] + " (" + width + "x" + height + ", " + triangles + " triangles, seed " + seed + ")");
            return 0;
        }
    }
}
