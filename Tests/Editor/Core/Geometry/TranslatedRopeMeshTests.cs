using System;
using HookeRope.Geometry;
using HookeRope.Solver;
using HookeRope.World;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// Issue 18: a rope's tube mesh does not depend on where in the world the rope sits. The solver works in rope-local
    /// coordinates (world = <see cref="Rope.Origin"/> + local) and the world's mesh slots fill from those, so a goal
    /// lanyard at x = 50 m or 500 m draws the same bits as one at the origin, frame after frame, while its ring budget
    /// steps up and down through the drop (the goal bench's vertex counts differ between rows because the rows end at
    /// different frames of that drop, not because of where the ropes sit). Positions handed over in a far-away caller
    /// frame carry that frame's float32 round-off (half an ulp: 1.9 µm at 50 m, 31 µm at 500 m); the ring need is judged
    /// from vectors relative to the first particle, so the same rings are drawn and the drawn surface stays within the
    /// bound of the smooth tube plus that round-off.
    /// </summary>
    public sealed class TranslatedRopeMeshTests
    {
        private const int Segments = 64;
        private const int Sides = 16;

        // 1.75 m: start + span is exact in float32 at 0, 50 and 500 m, so the three ropes get bit-identical local pins
        private const float Span = 1.75f;

        private static RopeSimulation Lanyard(float x)
        {
            RopeSimulation simulation = GoalLanyard.Pinned(new RopeSettings { SegmentCount = Segments }, x, Span);
            simulation.MeshSettings.RadialSegments = Sides;
            return simulation;
        }

        [Test]
        public void ALanyardAt50And500MetresDrawsTheSameBitsAsOneAtTheOrigin()
        {
            float[] offsets = { 0f, 50f, 500f };
            using (var world = new RopeWorld(1))
            {
                foreach (float x in offsets) world.EnableMesh(world.Add(Lanyard(x)));
                int changes = 0, last = -1, most = 0;
                for (int frame = 1; frame <= 240; frame++)
                {
                    world.StepAndFillMeshes(1f / 90f);
                    RopeMeshSlot origin = world.GetMeshSlot(0);
                    int vertices = origin.Update.VertexCount, indices = origin.Update.IndexCount;
                    if (vertices != last) { changes++; last = vertices; }
                    most = Math.Max(most, vertices);
                    for (int r = 1; r < offsets.Length; r++)
                    {
                        RopeMeshSlot far = world.GetMeshSlot(r);
                        Assert.That(far.Update.VertexCount, Is.EqualTo(vertices), $"vertices at {offsets[r]} m, frame {frame}");
                        Assert.That(far.Update.IndexCount, Is.EqualTo(indices), $"indices at {offsets[r]} m, frame {frame}");
                        Assert.That(MeshChecks.DifferingVertices(origin.Vertices, far.Vertices, vertices), Is.EqualTo(0), $"differing vertices at {offsets[r]} m, frame {frame}");
                        Assert.That(DifferingIndices(origin.Indices, far.Indices, indices), Is.EqualTo(0), $"differing indices at {offsets[r]} m, frame {frame}");
                    }
                }
                TestContext.WriteLine($"240 frames: {changes} vertex counts in turn, up to {most} vertices");
                // the budget really moved through the drop (the comparison covered several topologies)
                Assert.That(changes, Is.GreaterThanOrEqualTo(4));
            }
        }

        [TestCase(50f)]
        [TestCase(500f)]
        public void PositionsInAFarCallerFrameDrawTheSameRingsWithinTheBound(float offset)
        {
            RopeSimulation simulation = Lanyard(0f);
            const float radius = 0.008f;
            double polygon = radius * (1.0 - Math.Cos(Math.PI / Sides));
            double bound = polygon + RingNeed.Tolerance(Sides) * radius;
            // the caller frame's round-off: half an ulp of the input positions and half an ulp of the written vertices
            double roundOff = (double)BitConverter.Int32BitsToSingle(Bits(offset + Span) + 1) - (offset + Span);
            int frame = 0;
            foreach (int until in new[] { 30, 60, 120, 200 })
            {
                while (frame < until) { simulation.Step(1f / 90f); frame++; }
                RopeShape shape = RopeShape.FromRope(simulation.Rope);
                var shifted = new RopeShape(Segments, 0f);
                for (int i = 0; i <= Segments; i++) { shifted.X[i] = shape.X[i] + offset; shifted.Y[i] = shape.Y[i]; shifted.Z[i] = shape.Z[i]; }
                Array.Copy(shape.Rest, shifted.Rest, Segments);

                TubeMeshBuilder near = Build(shape, radius, out TubeVertex[] nearVertices, out int nearCount);
                TubeMeshBuilder far = Build(shifted, radius, out TubeVertex[] farVertices, out int farCount);
                Assert.That(farCount, Is.EqualTo(nearCount), $"vertices at frame {frame}");
                Assert.That(SameRings(near.Layout, far.Layout), Is.True, $"rings per segment at frame {frame}");

                for (int k = 0; k < farCount; k++) farVertices[k].PX = (float)(farVertices[k].PX - (double)offset);
                double nearDeviation = TubeDeviation.Largest(shape, radius, near.Layout, Sides, nearVertices, out _, out _);
                double farDeviation = TubeDeviation.Largest(shape, radius, far.Layout, Sides, farVertices, out _, out _);
                TestContext.WriteLine($"frame {frame}, {offset} m: {nearCount} vertices; deviation {nearDeviation / radius:F4} R at the origin, " +
                                      $"{farDeviation / radius:F4} R shifted; bound {bound / radius:F4} R + round-off {roundOff / radius:F4} R");
                Assert.That(nearDeviation, Is.LessThanOrEqualTo(bound * 1.0001));
                Assert.That(farDeviation, Is.LessThanOrEqualTo(bound * 1.0001 + roundOff));
            }
        }

        private static TubeMeshBuilder Build(RopeShape shape, float radius, out TubeVertex[] vertices, out int count)
        {
            var builder = TubeMeshBuilder.Adaptive(new TubeMeshSettings { RadialSegments = Sides }, Segments, radius, null);
            var broken = new bool[Segments];
            builder.PrimeRings(shape.X, shape.Y, shape.Z, broken, false, radius);
            vertices = new TubeVertex[builder.GetVertexCapacity(broken)];
            var indices = new int[builder.GetIndexCapacity(broken)];
            builder.PlanRings(shape.X, shape.Y, shape.Z, broken, false, radius, vertices.Length, indices.Length);
            var radii = new float[builder.Layout.RingCount];
            Array.Fill(radii, radius);
            count = builder.BuildWithRingRadii(shape.X, shape.Y, shape.Z, shape.Rest, radii, broken, vertices, indices).VertexCount;
            return builder;
        }

        private static bool SameRings(RingLayout a, RingLayout b)
        {
            if (a.RingCount != b.RingCount) return false;
            for (int j = 0; j < Segments; j++)
                if (a.RingsIn(j) != b.RingsIn(j)) return false;
            return true;
        }

        private static int DifferingIndices(int[] a, int[] b, int count)
        {
            int differing = 0;
            for (int k = 0; k < count; k++) if (a[k] != b[k]) differing++;
            return differing;
        }

        private static int Bits(float v) => BitConverter.SingleToInt32Bits(v);
    }
}
