using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Issue 17 item 2: a break parts the segment at its middle, and the elastic energy the segment stored goes into the
    /// recoil of its two ends (none vanishes with the segment, as it did before).
    /// </summary>
    public sealed class BreakRecoilTests
    {
        // 2 m rest, 20 segments, E·A 1 kN, 0.2 kg (μ 0.1 kg/m, c = √(E·A/μ) = 100 m/s), held 2.4 m apart: ε = 0.2,
        // T = 200 N, each segment stores ½·C²/α = ½·(0.02 m)²/(1e-4 m/N) = 2 J, the rope 40 J.
        private static Rope Stretched(TimeIntegrator integrator, out double segmentEnergy)
        {
            var settings = RopeTestKit.Settings(2f, 20, 1000f, 0.2f);
            settings.Gravity = Float3.Zero;
            settings.Damping = 0f;
            settings.Integrator = integrator;
            var rope = new Rope(settings, new Float3(-1.2f, 0f, 0f), new Float3(1.2f, 0f, 0f));
            rope.AddPin(0, new Float3(-1.2f, 0f, 0f));
            rope.AddPin(20, new Float3(1.2f, 0f, 0f));
            double c = rope.SegmentLengths[10] - rope.RestLengths[10];
            segmentEnergy = 0.5 * c * c / (rope.RestLengths[10] / 1000.0);
            return rope;
        }

        [TestCase(TimeIntegrator.BackwardEuler)]
        [TestCase(TimeIntegrator.Bdf2)]
        public void TheBrokenSegmentsElasticEnergyBecomesTheRecoilOfItsEnds(TimeIntegrator integrator)
        {
            var rope = Stretched(integrator, out double stored);
            double before = rope.TotalEnergy(), kineticBefore = rope.KineticEnergy();
            RopeBreakEvent seen = default;
            rope.Broken += e => seen = e;
            rope.BreakSegment(10);
            double after = rope.TotalEnergy(), kinetic = rope.KineticEnergy() - kineticBefore;
            Float3 left = rope.GetVelocity(10), right = rope.GetVelocity(11);
            float m = rope.GetParticleMass(10);
            double expected = 100.0 * 0.2 / Math.Sqrt(2.0); // c·ε/√2 = 14.14 m/s
            TestContext.WriteLine($"stored {stored:G6} J, recoil {seen.RecoilEnergy:G6} J, kinetic {kinetic:G6} J; total {before:G7} → {after:G7} J; " +
                                  $"ends {left.X:G6} / {right.X:G6} m/s (c·ε/√2 = {expected:G6})");
            Assert.That(stored, Is.EqualTo(2.0).Within(0.01), "½·C²/α of the segment");
            Assert.That(seen.StoredEnergy, Is.EqualTo(stored).Within(1e-4 * stored));
            Assert.That(seen.RecoilEnergy, Is.EqualTo(stored).Within(1e-4 * stored), "no step yet: nothing caps the recoil");
            Assert.That(kinetic, Is.EqualTo(stored).Within(1e-4 * stored), "the recoil carries the stored energy");
            Assert.That(after, Is.EqualTo(before).Within(1e-5 * before), "no energy vanishes at the break");
            // equal and opposite impulses, apart from the cut, along the rope
            Assert.That(m * left.X + rope.GetParticleMass(11) * right.X, Is.EqualTo(0.0).Within(1e-5 * m * Math.Abs(left.X)));
            Assert.That(left.X, Is.LessThan(0f));
            Assert.That(right.X, Is.GreaterThan(0f));
            Assert.That(Math.Abs(left.Y) + Math.Abs(left.Z), Is.LessThan(1e-6f));
            // the particle carrying the half segment's mass μ·L/2 takes its ¼·E·A·ε²·L: v = c·ε/√2 for m = μ·L
            Assert.That(-left.X, Is.EqualTo(expected).Within(1e-3 * expected));
            Assert.That(right.X, Is.EqualTo(expected).Within(1e-3 * expected));
        }

        [TestCase(TimeIntegrator.BackwardEuler)]
        [TestCase(TimeIntegrator.Bdf2)]
        public void AFreeStretchedSegmentFliesApartWithItsStoredEnergy(TimeIntegrator integrator)
        {
            // one segment, no gravity, no pins, stretched 1.5× and at rest: once cut nothing acts on the two particles, so
            // the kinetic energy after the recoil equals the stored elastic energy for good (before issue 17: 0, they stayed put)
            var settings = RopeTestKit.Settings(1f, 1, 50f, 0.1f);
            settings.Gravity = Float3.Zero;
            settings.Integrator = integrator;
            var rope = new Rope(settings, new Float3(0f, 0f, 0f), new Float3(0f, 1.5f, 0f));
            double stored = rope.ElasticEnergy();
            rope.BreakSegment(0);
            for (int i = 0; i < 90; i++) rope.Step(RopeTestKit.HostStep);
            double kinetic = rope.KineticEnergy();
            TestContext.WriteLine($"stored {stored:G6} J (½·50 N·0.5² m = 6.25 J), kinetic after 1 s of flight {kinetic:G6} J, gap {rope.SegmentLengths[0]:G5} m");
            Assert.That(stored, Is.EqualTo(6.25).Within(1e-4));
            Assert.That(kinetic, Is.EqualTo(stored).Within(1e-5 * stored));
            // v = √(E/m) each (m = 0.05 kg): they separate at 2·11.18 m/s
            Assert.That(rope.SegmentLengths[0], Is.EqualTo(1.5 + 2.0 * Math.Sqrt(6.25 / 0.05) * 1.0).Within(0.01));
            Assert.That(rope.GetVelocity(0).Y, Is.LessThan(0f));
        }

        [Test]
        public void ASlackSegmentReleasesNothing()
        {
            var settings = RopeTestKit.Settings(1f, 4, 50f, 0.1f);
            settings.Gravity = Float3.Zero;
            var rope = new Rope(settings, Float3.Zero, new Float3(0.5f, 0f, 0f));
            RopeBreakEvent seen = default;
            rope.Broken += e => seen = e;
            rope.BreakSegment(2);
            Assert.That(seen.StoredEnergy, Is.EqualTo(0.0));
            Assert.That(rope.KineticEnergy(), Is.EqualTo(0.0));
        }

        [Test]
        public void AKinematicEndLeavesTheWholeRecoilToTheFreeOne()
        {
            // the end pinned by a rigid pin is infinitely heavy: the free particle takes all of E, v = √(2E/m)
            var settings = RopeTestKit.Settings(1f, 1, 50f, 0.1f);
            settings.Gravity = Float3.Zero;
            var rope = new Rope(settings, Float3.Zero, new Float3(1.5f, 0f, 0f));
            rope.AddPin(0, Float3.Zero);
            rope.Step(RopeTestKit.HostStep);
            rope.SetVelocity(1, Float3.Zero);
            double stored = rope.ElasticEnergy();
            rope.BreakSegment(0);
            Assert.That(rope.GetVelocity(0).Length, Is.EqualTo(0f));
            Assert.That(rope.KineticEnergy(), Is.EqualTo(stored).Within(1e-5 * stored));
        }

        [Test]
        public void RecoilOfAPinnedRopeNeverGainsEnergyAndReleasesWhatTheWaveSays()
        {
            // Continuum: from the cut an unloading wave runs to each pin at c; behind it the rope is unstrained and moves at
            // c·ε, so the kinetic energy is E·A·ε²·c·t until the waves reach the pins (all 40 J at t = L_half/c). The break
            // hands over the broken segment's 2 J at once (the wave's first L/(2c)), so KE(t) = E·A·ε²·c·(t + L/(2c)).
            var rope = Stretched(TimeIntegrator.Bdf2, out double stored);
            rope.Settings.Substeps = 16;
            double total = rope.TotalEnergy();
            rope.BreakSegment(10);
            const float dt = 1f / 2000f;
            double c = 100.0, eps = 0.2, ea = 1000.0;
            double highest = 0.0, lowest = double.MaxValue, worst = 0.0;
            // until just before the waves reach the pins (the rest of each half, 0.95 m, at 100 m/s: 9.5 ms)
            for (int i = 1; i <= 18; i++)
            {
                rope.Step(dt);
                double t = i * dt;
                double e = rope.TotalEnergy(), ke = rope.KineticEnergy();
                double wave = ea * eps * eps * c * (t + 0.1 / (2.0 * c));
                highest = Math.Max(highest, e);
                lowest = Math.Min(lowest, e);
                if (t >= 0.002) worst = Math.Max(worst, Math.Abs(ke / wave - 1.0));
                TestContext.WriteLine($"t = {t * 1000:F1} ms: total {e:G6} J ({e / total:P3}), kinetic {ke:G6} J, continuum {wave:G6} J ({ke / wave:P1})");
            }
            // BDF2 at h = 31 µs dissipates 0.02 % of the wave; had the segment's 2 J vanished, 95 % would be left
            Assert.That(lowest, Is.GreaterThan(0.999 * total), "nothing but the integrator's dissipation is lost");
            Assert.That(worst, Is.LessThan(0.1), "the kinetic energy follows the unloading wave from 2 ms on");
            Assert.That(highest, Is.LessThanOrEqualTo(total * (1 + 1e-5)), "no energy gain");
        }

        [Test]
        public void ACoarseStepCapsTheRecoilAndLosesOnlyWhatItCannotCarry()
        {
            // the same rope after one step of 1/90 s at 1 substep (h = 11 ms ≫ L/c = 1 ms): an end at 14 m/s would cross
            // 16 cm in a substep, 8× the 2 cm stretch behind it; the impulse is capped at that stretch per substep
            var rope = Stretched(TimeIntegrator.BackwardEuler, out double stored);
            rope.Settings.Substeps = 1;
            rope.Step(1f / 90f);
            double before = rope.TotalEnergy(), kineticBefore = rope.KineticEnergy();
            double stretch = rope.SegmentLengths[9] - rope.RestLengths[9];
            RopeBreakEvent seen = default;
            rope.Broken += e => seen = e;
            rope.BreakSegment(10);
            double after = rope.TotalEnergy();
            float v = -rope.GetVelocity(10).X;
            TestContext.WriteLine($"stored {seen.StoredEnergy:G5} J, recoil {seen.RecoilEnergy:G5} J; total {before:G7} → {after:G7} J; end {v:G5} m/s × 11.1 ms = {v / 90f * 1000:G4} mm vs stretch {stretch * 1000:G4} mm");
            Assert.That(seen.StoredEnergy, Is.EqualTo(stored).Within(1e-3 * stored));
            Assert.That(seen.RecoilEnergy, Is.LessThan(0.1 * seen.StoredEnergy));
            Assert.That(v / 90.0, Is.EqualTo(stretch).Within(1e-3 * stretch), "the end closes the stretch behind it in one substep, no more");
            Assert.That(after, Is.EqualTo(before - seen.StoredEnergy + seen.RecoilEnergy).Within(1e-5 * before), "only the uncarried part is lost");
            Assert.That(rope.KineticEnergy() - kineticBefore, Is.EqualTo(seen.RecoilEnergy).Within(1e-4 * seen.RecoilEnergy + 1e-9));
        }

        [Test]
        public void ABreakAllocatesNothing()
        {
            // the recoil and the event are computed in place: once breaks have warmed the code up, a break allocates 0 B
            // (the fewest bytes over several breaks, as SteadyStateAllocation: a tiered re-compile may land in one)
            const int ropes = 12;
            var all = new Rope[ropes];
            int seen = 0;
            System.Action<RopeBreakEvent> count = e => seen++;
            for (int i = 0; i < ropes; i++)
            {
                all[i] = Stretched(TimeIntegrator.Bdf2, out _);
                all[i].Broken += count;
                all[i].Step(RopeTestKit.HostStep);
            }
            long fewest = long.MaxValue;
            for (int i = 0; i < ropes; i++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                all[i].BreakSegment(10);
                long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
                if (i >= 4) fewest = Math.Min(fewest, bytes);
            }
            Assert.That(seen, Is.EqualTo(ropes));
            Assert.That(fewest, Is.EqualTo(0), "bytes allocated by BreakSegment");
        }
    }
}
