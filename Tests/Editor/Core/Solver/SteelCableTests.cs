using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Stiff steel where float32 shows: a strain of ~3e-4 puts a segment's stretch (~5e-5 m) within 50 float steps of its
    /// ends' coordinates 10 m down (1e-6 m). Every case hangs a load on a pinned rope, damped so that it settles, and
    /// compares the settled stretch with (M + m/2)·g·L/(E·A) at every substep count from 1 to 64. Before the positions kept
    /// their sub-float remainder (ChainState.Low), the 10 m cable read −0.29 … +0.23 % depending on the substep count.
    /// </summary>
    public sealed class SteelCableTests
    {
        static readonly int[] SubstepCounts = { 1, 2, 4, 8, 16, 32, 64 };

        [Test]
        public void SteelCableWithHalfATonneIsStableAndSettlesToItsStaticElongation()
        {
            // damped (ζ ≈ 0.14 on the load's 56 rad/s mode) so that the released load comes to rest within the 8 s
            var settings = RopeTestKit.Legacy(length: 10f, segments: 64, radius: 0.005f, youngsModulus: 200e9f, density: 7850f, damping: 0.005f);
            var rope = RopeTestKit.Hanging(settings, 500f, out _);
            double ropeMass = settings.LinearDensity * 10.0;
            double expected = (500.0 + ropeMass / 2.0) * RopeTestKit.G * 10.0 / settings.AxialStiffness;
            double largest = 0.0;
            for (int i = 0; i < 90 * 8; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                largest = Math.Max(largest, -RopeTestKit.Bottom(rope) - 10.0);
            }
            Assert.That(RopeTestKit.AllFinite(rope), Is.True);
            double elongation = -RopeTestKit.Bottom(rope) - 10.0;
            TestContext.WriteLine($"elongation {elongation:G6} m vs {expected:G6} m ({(elongation / expected - 1) * 100:F3} %), largest {largest:G6} m");
            Assert.That(largest, Is.LessThan(2.2 * expected), "overshoot of a released load is at most 2x the static elongation");
            // the load's float position 10 m down resolves the 3.14 mm stretch to ±0.015 %
            Assert.That(elongation, Is.EqualTo(expected).Within(0.1).Percent);
            Assert.That(rope.GetPinForce(0).Length, Is.EqualTo((500.0 + ropeMass) * RopeTestKit.G).Within(0.01).Percent);
        }

        // 10 m steel cable R 5 mm (E·A 15.7 MN) with 500 kg; a 1 mm² steel wire (E·A 200 kN) with 10 kg; a 100 m cable with
        // 500 kg (its 616 kg of rope settle slower: β 0.05 s); 16 and 256 segments
        [TestCase(10f, 64, 0.005f, 500f, 0.005f, 4f, TimeIntegrator.Bdf2)]
        [TestCase(10f, 64, 0.005f, 500f, 0.005f, 4f, TimeIntegrator.BackwardEuler)]
        [TestCase(10f, 64, 0.000564190f, 10f, 0.005f, 4f, TimeIntegrator.Bdf2)]
        [TestCase(100f, 64, 0.005f, 500f, 0.05f, 3f, TimeIntegrator.Bdf2)]
        [TestCase(10f, 16, 0.005f, 500f, 0.005f, 4f, TimeIntegrator.Bdf2)]
        [TestCase(10f, 256, 0.005f, 500f, 0.005f, 2.5f, TimeIntegrator.Bdf2)]
        public void SettledStretchIsTheStaticOneAtEverySubstepCount(float length, int segments, float radius, float load, float damping, float seconds, TimeIntegrator integrator)
        {
            double lowest = double.MaxValue, highest = double.MinValue;
            string row = "";
            foreach (int substeps in SubstepCounts)
            {
                var settings = Steel(length, segments, radius, damping, substeps, integrator);
                var rope = RopeTestKit.Hanging(settings, load, out _);
                Settle(rope, seconds);
                double expected = StaticStretch(settings, load);
                double bottom = -(double)rope.PositionY[segments] - length; // the load's float position
                double total = TotalLength(rope) - length;                 // Σ SegmentLengths: resolved far below the positions' float step
                double tension = WorstTensionError(rope, settings, load);
                row += $" {substeps}: {(bottom / expected - 1) * 100:F3} % / {(total / expected - 1) * 100:F4} %;";
                Assert.That(RopeTestKit.AllFinite(rope), Is.True, $"{substeps} substeps");
                Assert.That(bottom, Is.EqualTo(expected).Within(0.1).Percent, $"load position, {substeps} substeps");
                Assert.That(total, Is.EqualTo(expected).Within(0.005).Percent, $"sum of the segment lengths, {substeps} substeps");
                Assert.That(tension, Is.LessThan(1e-6), $"worst segment tension against its static value, {substeps} substeps");
                lowest = Math.Min(lowest, total / expected);
                highest = Math.Max(highest, total / expected);
            }
            TestContext.WriteLine($"{length} m, {segments} seg, R {radius} m, {load} kg, {integrator}: stretch error load position / sum of lengths per substep count:{row}");
            TestContext.WriteLine($"spread of the summed stretch over 1 … 64 substeps: {(highest - lowest) * 100:F5} %");
            // consistent in the substep count: no substep count's settled state differs from another's (the h² dead band is gone)
            Assert.That(highest - lowest, Is.LessThan(2e-5));
        }

        [TestCase(TimeIntegrator.Bdf2)]
        [TestCase(TimeIntegrator.BackwardEuler)]
        public void CableTenKilometresFromItsOwnOriginSettlesAsAtTheOrigin(TimeIntegrator integrator)
        {
            // particles 10 km from the rope-local origin (a rope carried there after it was built): coordinates step by
            // 1e-3 m, a third of the stretch. Before the sub-float remainders, the load could not move by less than a step
            // and the cable read −100 % … +24 % at 1 … 64 substeps. The positions can only show that step; the lengths show the stretch.
            foreach (int substeps in new[] { 1, 8, 64 })
            {
                var settings = Steel(10f, 64, 0.005f, 0.005f, substeps, integrator);
                var near = RopeTestKit.Hanging(settings, 500f, out _);
                var far = new Rope(settings, Float3.Zero, new Float3(0f, -10f, 0f));
                var anchor = new Float3(0f, 10000f, 0f);
                for (int i = 0; i < far.ParticleCount; i++) far.SetPosition(i, anchor + new Float3(0f, -10f * i / 64, 0f));
                far.AddPin(0, anchor);
                far.AddLoad(64, 500f);
                Settle(near, 4f);
                Settle(far, 4f);
                double expected = StaticStretch(settings, 500f);
                double stretch = TotalLength(far) - 10.0;
                TestContext.WriteLine($"{integrator}, {substeps} substeps: far {(stretch / expected - 1) * 100:F4} %, at the origin {((TotalLength(near) - 10.0) / expected - 1) * 100:F4} %");
                Assert.That(RopeTestKit.AllFinite(far), Is.True);
                Assert.That(stretch, Is.EqualTo(expected).Within(0.005).Percent, $"{substeps} substeps");
                Assert.That(WorstTensionError(far, settings, 500f), Is.LessThan(1e-6), $"{substeps} substeps");
            }
        }

        [Test]
        public void InextensibleRopeReadsItsStaticTensionWithoutRoundOffNoise()
        {
            // α = 0: a length error q changes the force by m·q/h²; segment lengths formed in float (step 1.5e-8 m at 0.125 m)
            // made the 10 kg rope's pin force jump by ±0.5 % from step to step
            var settings = RopeTestKit.Legacy(length: 1f, segments: 8, youngsModulus: float.PositiveInfinity);
            var rope = RopeTestKit.Hanging(settings, 10f, out _);
            double expected = (10.0 + settings.LinearDensity) * RopeTestKit.G, worst = 0.0;
            for (int i = 0; i < 90; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                if (i >= 30) worst = Math.Max(worst, Math.Abs(rope.GetPinForce(0).Length / expected - 1.0));
            }
            TestContext.WriteLine($"inextensible: worst pin force error over the last 60 steps {worst * 100:E2} %");
            Assert.That(worst, Is.LessThan(1e-5));
        }

        static RopeSettings Steel(float length, int segments, float radius, float damping, int substeps, TimeIntegrator integrator)
        {
            var settings = RopeTestKit.Legacy(length: length, segments: segments, radius: radius, youngsModulus: 200e9f, density: 7850f, damping: damping, substeps: substeps);
            settings.Integrator = integrator;
            return settings;
        }

        static double StaticStretch(RopeSettings s, float load) => (load + s.LinearDensity * (double)s.RestLength / 2.0) * RopeTestKit.G * s.RestLength / s.AxialStiffness;

        static void Settle(Rope rope, float seconds)
        {
            for (int i = 0; i < (int)(seconds * 90f); i++) rope.Step(RopeTestKit.HostStep);
        }

        static double TotalLength(Rope rope)
        {
            double total = 0.0;
            foreach (float l in rope.SegmentLengths) total += l;
            return total;
        }

        /// <summary>Largest |T_j / (g·(M + μ(L − (j + ½)ℓ))) − 1| over the segments: each carries the lumped masses below it.</summary>
        static double WorstTensionError(Rope rope, RopeSettings s, float load)
        {
            double segment = (double)s.RestLength / rope.SegmentCount, worst = 0.0;
            for (int j = 0; j < rope.SegmentCount; j++)
            {
                double carried = load + s.LinearDensity * (s.RestLength - (j + 0.5) * segment);
                worst = Math.Max(worst, Math.Abs(rope.Tensions[j] / (RopeTestKit.G * carried) - 1.0));
            }
            return worst;
        }
    }
}
