using System;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;
using HookeRope.Tests.Core.Fracture;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// Ropes that bend no tighter than their radius, drawn: the scenes on which the slack-fold repair (issue 17) must leave
    /// the tube as it was. Each returns the mesh the core fills (vertices, indices and their counts).
    /// </summary>
    internal static class TautTubeScenes
    {
        private const float R = 0.01f;
        private const float HostStep = 1f / 90f;

        public static readonly string[] Names =
        {
            "necked cord at 40 % strain, 16 sides",
            "necked cord at 40 % strain, 8 sides, 4 rings per segment",
            "fracture cord at its break, 16 sides",
            "2 m rope hanging between pins 1.8 m apart, 32 sides",
            "helix of 5 R bend radius, 16 sides, one segment broken",
            "straight rope stretched 1.2, 12 sides, 4 rings per segment",
        };

        public static TubeMeshUpdate Draw(int scene, out TubeVertex[] vertices, out int[] indices, out TubeMeshBuilder builder)
        {
            switch (scene)
            {
                case 0: return Cord(16, true, 0.4f, out vertices, out indices, out builder);
                case 1: return Cord(8, false, 0.4f, out vertices, out indices, out builder);
                case 2: return Cord(16, true, 0f, out vertices, out indices, out builder);
                case 3: return Hanging(out vertices, out indices, out builder);
                case 4: return Shape(RopeShape.Helix(24, 0.03f, 5f * R, 0.05f), 16, 1, true, 9, out vertices, out indices, out builder);
                default: return Shape(RopeShape.Straight(16, 0.05f, 1.2f, 1f, 0.3f, -0.2f), 12, 4, false, -1, out vertices, out indices, out builder);
            }
        }

        /// <summary>The lab's fracture cord pulled at 0.5 m/s to <paramref name="strain"/> (0: until it breaks).</summary>
        private static TubeMeshUpdate Cord(int radial, bool adaptive, float strain, out TubeVertex[] vertices, out int[] indices, out TubeMeshBuilder builder)
        {
            var sim = FractureCord.Build(new TubeMeshSettings { RadialSegments = radial, AdaptiveRings = adaptive }, out int pin);
            Rope rope = sim.Rope;
            for (int step = 1; step <= 400; step++)
            {
                if (strain > 0f ? sim.Readouts.Strain >= strain : sim.IsBroken) break;
                rope.SetPinTarget(pin, new Float3(1f + 0.5f * step * HostStep, 0f, 0f));
                sim.Step(HostStep);
            }
            return Fill(sim, out vertices, out indices, out builder);
        }

        private static TubeMeshUpdate Hanging(out TubeVertex[] vertices, out int[] indices, out TubeMeshBuilder builder)
        {
            var settings = new RopeSettings { RestLength = 2f, SegmentCount = 32, Radius = R, Gravity = new Float3(0f, -9.81f, 0f), Damping = 0.02f };
            var rope = new Rope(settings, Float3.Zero, new Float3(1.8f, 0f, 0f));
            rope.AddPin(0, Float3.Zero);
            rope.AddPin(32, new Float3(1.8f, 0f, 0f));
            var sim = new RopeSimulation(rope, new RadiusSettings(), new TubeMeshSettings { RadialSegments = 32 });
            for (int step = 0; step < 120; step++) sim.Step(HostStep);
            return Fill(sim, out vertices, out indices, out builder);
        }

        private static TubeMeshUpdate Fill(RopeSimulation sim, out TubeVertex[] vertices, out int[] indices, out TubeMeshBuilder builder)
        {
            vertices = new TubeVertex[sim.GetVertexCount()];
            indices = new int[sim.GetIndexCount()];
            TubeMeshUpdate update = sim.FillMesh(vertices, indices);
            builder = sim.Mesh.Builder;
            return update;
        }

        private static TubeMeshUpdate Shape(RopeShape shape, int radial, int rings, bool adaptive, int broken, out TubeVertex[] vertices, out int[] indices, out TubeMeshBuilder result)
        {
            int n = shape.Segments;
            var settings = new TubeMeshSettings { RadialSegments = radial, RingsPerSegment = rings, AdaptiveRings = adaptive };
            TubeMeshBuilder builder = adaptive ? TubeMeshBuilder.Adaptive(settings, n, R, null) : new TubeMeshBuilder(settings, n);
            var brokenSegments = new bool[n];
            if (broken >= 0) brokenSegments[broken] = true;
            if (adaptive)
            {
                builder.PrimeRings(shape.X, shape.Y, shape.Z, brokenSegments, false, R);
                builder.PlanRings(shape.X, shape.Y, shape.Z, brokenSegments, false, R, int.MaxValue, int.MaxValue);
            }
            var radii = new float[n];
            for (int j = 0; j < n; j++) radii[j] = R * (1f - 0.15f * MathF.Exp(-0.5f * (j - 0.5f * n) * (j - 0.5f * n) / 4f));
            vertices = new TubeVertex[builder.GetVertexCount(brokenSegments)];
            indices = new int[builder.GetIndexCount(brokenSegments)];
            result = builder;
            return builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, radii, brokenSegments, vertices, indices);
        }
    }
}
