using System;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    public sealed class BreakTests
    {
        [Test]
        public void StrainAtTheDefectBreaksItOnceAndRaisesTheEvent()
        {
            // 1 m, E·A = 10 kN, limit 1 % strain (100 N) at the defect: the load is raised step by step (0.16 kg per
            // host step from 1 kg, about 0.6 s to the limit) until the defect segment breaks. The criterion is the radius model's,
            // checked once per host step by RopeSimulation (issue 12: no per-substep solver check any more).
            var settings = RopeTestKit.Settings(1f, 10, 1e4f, 0.01f);
            var rope = RopeTestKit.Hanging(settings, 1f, out _);
            var radius = new RadiusSettings { PoissonThinning = false, Necking = false, Fracture = true, BreakStrain = 0.01f, DefectPosition = 0.55f };
            var sim = new RopeSimulation(rope, radius);
            var events = new System.Collections.Generic.List<RopeBreakEvent>();
            rope.Broken += e => events.Add(e);
            int last = rope.ParticleCount - 1;
            for (int i = 0; i < 180; i++)
            {
                if (events.Count == 0 && i < 120) rope.AddLoad(last, 0.16f);
                sim.Step(RopeTestKit.HostStep);
            }
            Assert.That(events.Count, Is.EqualTo(1));
            RopeBreakEvent e0 = events[0];
            TestContext.WriteLine($"broke segment {e0.Segment} at t={e0.Time:G4} s, tension {e0.Tension:G5} N, at {e0.Position}");
            Assert.That(e0.Segment, Is.EqualTo(sim.RadiusModel.DefectSegment), "the defect segment breaks");
            Assert.That(e0.Segment, Is.EqualTo(5));
            Assert.That(rope.IsSegmentBroken(e0.Segment), Is.True);
            Assert.That(rope.BrokenSegmentCount, Is.EqualTo(1));
            Assert.That(e0.Tension, Is.GreaterThan(100f * 0.95f), "tension just before ≈ E·A·strain limit");
            Assert.That(e0.Tension, Is.LessThan(100f * 1.1f));
            Assert.That(e0.Time, Is.GreaterThan(0.0));
            Assert.That(e0.Time, Is.LessThan(2.0));
            Assert.That(e0.Position.Y, Is.LessThan(0f));
            Assert.That(e0.Position.Y, Is.GreaterThan(-1.1f));
            // the lower part falls freely, the upper part hangs: no NaN, no force across the break
            Assert.That(RopeTestKit.AllFinite(rope), Is.True);
            Assert.That(rope.Tensions[e0.Segment], Is.EqualTo(0f));
            Assert.That(RopeTestKit.Bottom(rope), Is.LessThan(-2f), "the load fell");
            Assert.That(rope.GetPinForce(0).Length, Is.LessThan(2f), "the anchor carries only the remaining rope");
        }

        [TestCase(ConstraintSolverKind.ExactChain, TimeIntegrator.BackwardEuler)]
        [TestCase(ConstraintSolverKind.GaussSeidel, TimeIntegrator.BackwardEuler)]
        [TestCase(ConstraintSolverKind.ExactChain, TimeIntegrator.Bdf2)]
        public void BreakSegmentSplitsTheChainIntoTwoIndependentRopes(ConstraintSolverKind solver, TimeIntegrator integrator)
        {
            var settings = RopeTestKit.Legacy(length: 2f, segments: 20, solver: solver);
            settings.Integrator = integrator;
            var rope = new Rope(settings, new Float3(-1f, 0f, 0f), new Float3(1f, 0f, 0f));
            rope.AddPin(0, new Float3(-1f, 0f, 0f));
            rope.AddPin(20, new Float3(1f, 0f, 0f));
            for (int i = 0; i < 90; i++) rope.Step(RopeTestKit.HostStep);
            float before = rope.Tensions[10];
            RopeBreakEvent seen = default;
            rope.Broken += e => seen = e;
            rope.BreakSegment(10);
            Assert.That(seen.Segment, Is.EqualTo(10));
            Assert.That(seen.Tension, Is.EqualTo(before));
            Assert.That(seen.Position.X, Is.EqualTo(0f).Within(0.1f));
            // the halves fall as two chain pendulums from their anchors 2 m apart: on the way down the gap
            // between the free ends opens towards 2 m (it closes again as they swing up towards each other)
            float widestGap = 0f;
            for (int i = 0; i < 180; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                widestGap = Math.Max(widestGap, rope.SegmentLengths[10]);
            }
            Assert.That(RopeTestKit.AllFinite(rope), Is.True);
            // each half swings from its own anchor, within its own length of it; the gap opens
            float halfLength = 10 * settings.RestLength / settings.SegmentCount;
            for (int i = 0; i <= 10; i++) Assert.That((rope.GetPosition(i) - new Float3(-1f, 0f, 0f)).Length, Is.LessThanOrEqualTo(halfLength * 1.01f));
            for (int i = 11; i <= 20; i++) Assert.That((rope.GetPosition(i) - new Float3(1f, 0f, 0f)).Length, Is.LessThanOrEqualTo(halfLength * 1.01f));
            Assert.That(widestGap, Is.GreaterThan(1.5f));
            Assert.That(rope.Tensions[10], Is.EqualTo(0f));
            Assert.That(rope.Tensions[0], Is.GreaterThan(0f));
            rope.BreakSegment(10); // breaking again is a no-op
            Assert.That(rope.IsSegmentBroken(10), Is.True);
        }

        [Test]
        public void TautHeavyRopeBrokenInTheMiddleDropsItsLowerHalfFreely()
        {
            // 100 kg on a 2 m rope of 1 g particles (E·A 100 kN): the tension is far above m·l/(3h²), so the exact
            // solve runs its transverse stabilisation. Cut in the middle, the lower half and the load fall freely
            // (internal forces cancel, the 10 g of rope can't hold back 100 kg): Δv = −g·t, and the anchor keeps
            // only the upper half's weight.
            var settings = RopeTestKit.Settings(2f, 20, 1e5f, 0.02f);
            settings.Damping = 0.02f;
            var rope = RopeTestKit.Hanging(settings, 100f, out int load);
            for (int i = 0; i < 90; i++) rope.Step(RopeTestKit.HostStep);
            float v0 = rope.GetLoadVelocity(load).Y;
            rope.BreakSegment(10);
            const int steps = 45;
            for (int i = 0; i < steps; i++) rope.Step(RopeTestKit.HostStep);
            double t = steps * (double)RopeTestKit.HostStep;
            double dv = rope.GetLoadVelocity(load).Y - v0;
            TestContext.WriteLine($"after the cut: Δv {dv:G6} m/s vs {-RopeTestKit.G * t:G6} m/s, anchor {rope.GetPinForce(0).Length:G4} N");
            Assert.That(RopeTestKit.AllFinite(rope), Is.True);
            Assert.That(dv, Is.EqualTo(-RopeTestKit.G * t).Within(0.01 * RopeTestKit.G * t));
            Assert.That(rope.GetPinForce(0).Length, Is.LessThan(1f), "upper half: about 0.1 N of rope");
            for (int i = 0; i <= 10; i++) Assert.That(rope.GetPosition(i).Length, Is.LessThanOrEqualTo(1.05f), "the upper half hangs within its length");
        }
    }
}
