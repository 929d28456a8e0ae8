using System;
using System.Text;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// Issues 17 and 18: a slack rope that folds tighter than its radius (the recoiling pieces of a broken elastic cord, a
    /// stretched cord let go) is drawn without a single tube or cap triangle wound against its own normals.
    /// </summary>
    public sealed class SlackFoldTests
    {
        private const float R = 0.01f;
        private const float HostStep = 1f / 90f;

        /// <summary>One way of driving the lab's fracture cord (1 m, R = 10 mm, E·A 1 kN, pulled at 0.5 m/s, 90 Hz × 4).</summary>
        public sealed class Case
        {
            public string Name;
            public int Segments = 21;
            public bool Gravity;
            public float Damping = 0.01f;
            public TimeIntegrator Integrator = TimeIntegrator.Bdf2;
            /// <summary>Let the pulled end go at this strain instead of breaking (0 = break).</summary>
            public float ReleaseAtStrain;
            public int Radial = 16;
            public bool Adaptive = true;

            public override string ToString() => Name;
        }

        private static readonly Case[] Cases =
        {
            new Case { Name = "fracture cord" },
            new Case { Name = "fracture cord, gravity", Gravity = true },
            new Case { Name = "fracture cord, undamped", Damping = 0f },
            new Case { Name = "fracture cord, undamped, gravity", Damping = 0f, Gravity = true },
            new Case { Name = "fracture cord, backward Euler", Integrator = TimeIntegrator.BackwardEuler },
            new Case { Name = "fracture cord, backward Euler, gravity", Integrator = TimeIntegrator.BackwardEuler, Gravity = true },
            new Case { Name = "fracture cord, 8 sides", Radial = 8 },
            new Case { Name = "fracture cord, 8 sides, gravity", Radial = 8, Gravity = true },
            new Case { Name = "fracture cord, 4 rings per segment", Adaptive = false },
            new Case { Name = "fracture cord, 4 rings per segment, gravity", Adaptive = false, Gravity = true },
            new Case { Name = "released at 45 % strain", ReleaseAtStrain = 0.45f },
            new Case { Name = "released at 45 % strain, gravity", ReleaseAtStrain = 0.45f, Gravity = true },
            new Case { Name = "80 segments", Segments = 80 },
            new Case { Name = "80 segments, gravity", Segments = 80, Gravity = true },
        };

        private static RopeSimulation Cord(Case c, out int endPin)
        {
            var settings = new RopeSettings
            {
                RestLength = 1f, SegmentCount = c.Segments, Radius = R, AxialStiffness = 1000f, Density = 1100f,
                Gravity = c.Gravity ? new Float3(0f, -9.81f, 0f) : Float3.Zero,
                Substeps = 4, Iterations = 1, Damping = c.Damping, Solver = ConstraintSolverKind.ExactChain, Integrator = c.Integrator,
            };
            var radius = new RadiusSettings
            {
                PoissonRatio = 0.5f, Necking = true, NeckMode = NeckMode.Zone, NeckRadiusFraction = 0.85f, DefectPosition = 0.5f,
                Fracture = c.ReleaseAtStrain == 0f, BreakStrain = 0.5f,
            };
            var mesh = new TubeMeshSettings { RadialSegments = c.Radial, AdaptiveRings = c.Adaptive };
            var rope = new Rope(settings, Float3.Zero, new Float3(1f, 0f, 0f));
            rope.AddPin(0, Float3.Zero);
            endPin = rope.AddPin(c.Segments, new Float3(1f, 0f, 0f));
            return new RopeSimulation(rope, radius, mesh);
        }

        /// <summary>What one host step's mesh shows (areas in R², lengths in R).</summary>
        internal struct Frame
        {
            public int Inverted, Crossings, Tips, BadEdges;
            public double InvertedArea, LeastClearance, LeastNormalCosine;
        }

        /// <summary>The mesh at each host step from the break (or release) to <paramref name="steps"/> after it.</summary>
        internal static Frame[] Census(Case c, int steps, out int triangles)
        {
            var sim = Cord(c, out int pin);
            int step = 0;
            bool Done() => c.ReleaseAtStrain > 0f ? sim.Readouts.Strain >= c.ReleaseAtStrain : sim.IsBroken;
            while (!Done() && step < 400)
            {
                step++;
                sim.Rope.SetPinTarget(pin, new Float3(1f + 0.5f * step * HostStep, 0f, 0f));
                sim.Step(HostStep);
            }
            Assert.That(Done(), Is.True, c.Name + ": breaks or reaches the strain within 400 steps");
            if (c.ReleaseAtStrain > 0f) sim.Rope.ReleasePin(pin);
            var frames = new Frame[steps + 1];
            triangles = 0;
            var vertices = new TubeVertex[0];
            var indices = new int[0];
            var broken = new bool[c.Segments];
            for (int k = 0; k <= steps; k++)
            {
                if (k > 0)
                {
                    step++;
                    if (c.ReleaseAtStrain == 0f) sim.Rope.SetPinTarget(pin, new Float3(1f + 0.5f * step * HostStep, 0f, 0f));
                    sim.Step(HostStep);
                }
                if (vertices.Length < sim.GetVertexCount()) vertices = new TubeVertex[sim.GetVertexCount()];
                if (indices.Length < sim.GetIndexCount()) indices = new int[sim.GetIndexCount()];
                var update = sim.FillMesh(vertices, indices);
                sim.Rope.BrokenSegments.CopyTo(broken);
                ref Frame f = ref frames[k];
                f.Inverted = MeshChecks.Inverted(vertices, indices, 0, update.TubeIndexCount, out double area);
                f.InvertedArea = area / (R * R);
                f.Crossings = MeshChecks.RingCrossings(sim.Mesh.Builder, broken, out double clearance, out f.Tips);
                f.LeastClearance = clearance / R;
                f.LeastNormalCosine = MeshChecks.LeastNormalCosine(vertices, indices, 0, update.TubeIndexCount, 1e-6 * R * R);
                MeshChecks.Topology(vertices, update.VertexCount, indices, 0, update.TubeIndexCount, out _, out _, out _, out f.BadEdges, out int directions);
                f.BadEdges += directions;
                Assert.That(MeshChecks.AllFiniteAndUnit(vertices, update.VertexCount), Is.True, c.Name + ": finite, unit normals and tangents");
                triangles = Math.Max(triangles, update.TubeIndexCount / 3);
            }
            return frames;
        }

        [TestCaseSource(nameof(Cases))]
        public void NoTriangleIsInvertedForTwentyStepsAfterTheBreak(Case c)
        {
            Frame[] frames = Census(c, 20, out int triangles);
            var line = new StringBuilder();
            int total = 0, tips = 0, open = 0;
            double area = 0.0;
            foreach (Frame f in frames)
            {
                line.Append(f.Inverted).Append(' ');
                total += f.Inverted;
                area += f.InvertedArea;
                tips = Math.Max(tips, f.Tips);
                open += f.BadEdges;
            }
            TestContext.WriteLine($"{c.Name}: inverted per step 0-20: {line}(total {total}, {area:F2} R², of up to {triangles} triangles; up to {tips} fold-tip rings)");
            Assert.That(total, Is.EqualTo(0));
            Assert.That(open, Is.EqualTo(0), "every tube and cap edge shared by two triangles, wound one way");
        }

        [TestCaseSource(nameof(Cases))]
        public void ConsecutiveRingsNeverCrossForTwentyStepsAfterTheBreak(Case c)
        {
            Frame[] frames = Census(c, 20, out _);
            int crossings = 0;
            double least = double.MaxValue;
            foreach (Frame f in frames) { crossings += f.Crossings; least = Math.Min(least, f.LeastClearance); }
            TestContext.WriteLine($"{c.Name}: ring pairs crossing over 21 steps {crossings}, least clearance {least:E3} R");
            Assert.That(crossings, Is.EqualTo(0));
            Assert.That(least, Is.GreaterThan(0.0));
        }

        [TestCaseSource(nameof(Cases))]
        public void VertexNormalsFaceEveryTriangleAroundThemForTwentyStepsAfterTheBreak(Case c)
        {
            Frame[] frames = Census(c, 20, out _);
            double least = double.MaxValue;
            foreach (Frame f in frames) least = Math.Min(least, f.LeastNormalCosine);
            TestContext.WriteLine($"{c.Name}: least cosine between a vertex normal and a triangle around it over 21 steps {least:F4}");
            Assert.That(least, Is.GreaterThan(0.0), "no vertex is lit from behind on a triangle it belongs to");
        }
    }
}
