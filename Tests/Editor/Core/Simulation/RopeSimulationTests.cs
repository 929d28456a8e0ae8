using System;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;
using HookeRope.Tests.Core.Geometry;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Simulation
{
    public sealed class RopeSimulationTests
    {
        private const float Step = 1f / 90f;
        private const float R = 0.01f;

        private static RopeSettings Soft(float length, int segments, float axialStiffness, float ropeMass)
        {
            var s = new RopeSettings { RestLength = length, SegmentCount = segments, Radius = R };
            s.AxialStiffness = axialStiffness;
            s.LinearDensity = ropeMass / length;
            s.Damping = 0.05f;
            return s;
        }

        [Test]
        public void HangingHeavyRopeIsThinnerAtTheTop()
        {
            // 2 m, 2 kg rope of E·A = 200 N hanging from its top: static strain falls from ≈ 0.096 at the top to 0.
            var settings = Soft(2f, 20, 200f, 2f);
            var radius = new RadiusSettings { NeckMode = NeckMode.Off, BreakEnabled = false };
            var sim = new RopeSimulation(settings, Float3.Zero, new Float3(0f, -2f, 0f), radius);
            sim.Rope.AddPin(0, Float3.Zero);
            for (int i = 0; i < 270; i++) sim.Step(Step);
            ReadOnlySpan<float> particle = sim.ParticleRadii;
            for (int i = 1; i < sim.Rope.ParticleCount; i++)
                Assert.That(particle[i], Is.GreaterThan(particle[i - 1]), "particle " + i);
            // Each segment's radius is eq. 16 of its own stretch (ν = 0.5: r = R·sqrt(L/l)).
            for (int j = 0; j < sim.Rope.SegmentCount; j++)
            {
                double expected = R * Math.Sqrt(sim.Rope.RestLengths[j] / sim.Rope.SegmentLengths[j]);
                Assert.That(sim.SegmentRadii[j], Is.EqualTo(expected).Within(1e-6 * R));
            }
            // Top segment: static strain (m g (1 − 0.5/20))/(E·A) = 0.0956 → r = R/sqrt(1.0956) = 0.9554 R.
            double topStrain = 2.0 * 9.81 * (1.0 - 0.5 / 20.0) / 200.0;
            TestContext.WriteLine("top radius " + (sim.SegmentRadii[0] / R).ToString("F4") + " R, static theory " + (1.0 / Math.Sqrt(1.0 + topStrain)).ToString("F4") + " R");
            Assert.That(sim.SegmentRadii[0] / R, Is.EqualTo(1.0 / Math.Sqrt(1.0 + topStrain)).Within(0.002));
            Assert.That(sim.SegmentRadii[19] / R, Is.GreaterThan(0.995));
            // The collision radius is the radius model's particle radius.
            for (int i = 0; i < sim.Rope.ParticleCount; i++)
                Assert.That(sim.Rope.ParticleRadius[i], Is.EqualTo(particle[i]));
        }

        [Test]
        public void RopeStretchedPastTheThresholdBreaksAtTheDefect()
        {
            var settings = Soft(1f, 20, 500f, 0.05f);
            settings.Gravity = Float3.Zero;
            var radius = new RadiusSettings { NeckMode = NeckMode.Zone, DefectPosition = 0.33f, BreakElongation = 0.5f, BreakRadiusFraction = 0f };
            var sim = new RopeSimulation(settings, Float3.Zero, new Float3(1f, 0f, 0f), radius);
            sim.Rope.AddPin(0, Float3.Zero);
            int end = sim.Rope.AddPin(20, new Float3(1f, 0f, 0f));
            int brokenSegment = -1;
            sim.Rope.Broken += e => brokenSegment = e.Segment;
            float stretchAtBreak = float.NaN;
            for (int i = 1; i <= 200 && !sim.IsBroken; i++)
            {
                float stretch = 1f + 0.005f * i;
                sim.Rope.SetPinTarget(end, new Float3(stretch, 0f, 0f));
                sim.Step(Step);
                if (sim.IsBroken) stretchAtBreak = stretch;
            }
            Assert.That(sim.IsBroken, Is.True);
            Assert.That(brokenSegment, Is.EqualTo(6));
            Assert.That(sim.Rope.IsSegmentBroken(6), Is.True);
            for (int j = 0; j < 20; j++) if (j != 6) Assert.That(sim.Rope.IsSegmentBroken(j), Is.False, "segment " + j);
            Assert.That(stretchAtBreak, Is.EqualTo(1.5f).Within(0.02f));
            Assert.That(sim.RadiusModel.IsBroken, Is.True);
            // The mesh now has two pieces with burrs at the break.
            var vertices = new TubeVertex[sim.GetVertexCount()];
            var indices = new int[sim.GetIndexCount()];
            var update = sim.FillMesh(vertices, indices);
            Assert.That(update.BurrIndexCount, Is.EqualTo(2 * 16 * 9));
            Assert.That(MeshChecks.AllFiniteAndUnit(vertices, update.VertexCount), Is.True);
        }

        [Test]
        public void ThinnedRopeLiesLowerOnTheGround()
        {
            // A rope stretched 1.5× between two pins at the height of its thinned radius, r = R/sqrt(1.5) = 0.8165 R
            // for ν = 0.5, sags onto a plane at y = 0: its particles rest at their own (thinned) radius, not at R.
            float r = R / MathF.Sqrt(1.5f);
            var settings = new RopeSettings { RestLength = 1f, SegmentCount = 20, Radius = R };
            settings.YoungsModulus = 1e7f;
            var radius = new RadiusSettings { NeckMode = NeckMode.Off, BreakEnabled = false };
            var sim = new RopeSimulation(settings, new Float3(0f, r, 0f), new Float3(1.5f, r, 0f), radius);
            Assert.That(sim.Rope.ParticleRadius[10], Is.EqualTo(r).Within(1e-4 * R), "radii applied before the first step");
            sim.Rope.AddPin(0, new Float3(0f, r, 0f));
            sim.Rope.AddPin(20, new Float3(1.5f, r, 0f));
            sim.Rope.AddCollider(ColliderShape.Plane(Float3.Zero, new Float3(0f, 1f, 0f), 0.5f));
            double lowest = double.MaxValue, highest = double.MinValue;
            for (int i = 0; i < 90; i++)
            {
                sim.Step(Step);
                if (i < 45) continue;
                for (int p = 5; p <= 15; p++)
                {
                    lowest = Math.Min(lowest, sim.Rope.GetPosition(p).Y);
                    highest = Math.Max(highest, sim.Rope.GetPosition(p).Y);
                }
            }
            TestContext.WriteLine("middle particles between y = " + (lowest / R).ToString("F4") + " R and " + (highest / R).ToString("F4") + " R; thinned radius " + (r / R).ToString("F4") + " R");
            Assert.That(sim.Rope.ParticleRadius[10], Is.EqualTo(r).Within(1e-3 * R));
            Assert.That(lowest, Is.EqualTo(r).Within(0.01 * R));
            Assert.That(highest, Is.EqualTo(r).Within(0.01 * R)); // R = 1.0 would be 18 % higher
        }

        [Test]
        public void WithoutARadiusModelTheRopeKeepsItsRadiusAndTheMeshStillBuilds()
        {
            var settings = Soft(1f, 10, 100f, 0.1f);
            var sim = new RopeSimulation(settings, Float3.Zero, new Float3(1.5f, 0f, 0f));
            sim.Rope.AddPin(0, Float3.Zero);
            sim.Rope.AddPin(10, new Float3(1.5f, 0f, 0f));
            for (int i = 0; i < 10; i++) sim.Step(Step);
            Assert.That(sim.RadiusModel, Is.Null);
            Assert.That(sim.MinRadius, Is.EqualTo(R));
            Assert.That(sim.NeckRadius, Is.EqualTo(R));
            for (int i = 0; i < 11; i++) Assert.That(sim.Rope.ParticleRadius[i], Is.EqualTo(R));
            var vertices = new TubeVertex[sim.GetVertexCount()];
            var indices = new int[sim.GetIndexCount()];
            var update = sim.FillMesh(vertices, indices);
            Assert.That(update.Origin.X, Is.EqualTo(0f).Within(1e-6));
            for (int k = 0; k < sim.RingRadii.Length; k++) Assert.That(sim.RingRadii[k], Is.EqualTo(R));
        }

        [Test]
        public void StepAndMeshFillAllocateNothing()
        {
            var settings = Soft(2f, 40, 300f, 0.5f);
            var sim = new RopeSimulation(settings, Float3.Zero, new Float3(0f, -2f, 0f), new RadiusSettings { BreakEnabled = false });
            sim.Rope.AddPin(0, Float3.Zero);
            sim.Rope.AddLoad(40, 3f);
            var vertices = new TubeVertex[sim.GetVertexCount()];
            var indices = new int[sim.GetIndexCount()];
            long bytes = SteadyStateAllocation.Bytes(() =>
            {
                sim.Step(Step);
                sim.FillMesh(vertices, indices);
            }, 20);
            Assert.That(bytes, Is.EqualTo(0));
        }
    }
}
