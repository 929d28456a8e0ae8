using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Bilateral (rod) segments in compression in the exact chain solve (solver.md, "Rods in compression"): a pushing
    /// segment takes no geometric stiffness in the Newton system, and a bilateral segment's XPBD dashpot takes its exact
    /// length change over the substep. The total energy K + G + U (U the least elastic energy within round-off,
    /// <see cref="Rope.ElasticEnergyBounds"/>) never rises above the energy put in by more than the float32 round-off
    /// bound of the stability grid (2⁻²² × (K + |G| + U) per substep), and a straight rod oscillates at √(k/M).
    /// </summary>
    public sealed class RodCompressionTests
    {
        /// <summary>The stability grid's round-off allowance per substep, as a fraction of the energy carried (GridOutcome.RoundOffPerSubstep).</summary>
        private const double RoundOffPerSubstep = 1.0 / 4194304.0;

        /// <summary>
        /// The stability grid's rope (R 5 mm, 1140 kg/m³, 1 m, 8 substeps × 1 iteration, exact chain, bilateral): pinned at
        /// the origin, laid 30° off the vertical at stretch × 1 m, with a load of ratio × one particle's mass at its end.
        /// </summary>
        private static Rope GridRod(float youngsModulus, int segments, float stretch, float ratio, TimeIntegrator integrator, float damping)
        {
            var settings = RopeTestKit.Legacy(segments: segments, youngsModulus: youngsModulus, damping: damping);
            settings.Tension = TensionModel.Bilateral;
            settings.Integrator = integrator;
            var rope = new Rope(settings, Float3.Zero, new Float3(0.5f * stretch, -0.8660254f * stretch, 0f));
            rope.AddPin(0, Float3.Zero);
            rope.AddLoad(rope.ParticleCount - 1, settings.LinearDensity * 1f / segments * ratio);
            return rope;
        }

        /// <summary>
        /// Runs the rope for <paramref name="steps"/> host steps (a drag rate k &gt; 0 multiplies every free particle's
        /// velocity by e^{−kΔt} after each, as the grid's settle cases do); returns the largest excess of the total energy
        /// over the energy put in beyond the round-off allowance accumulated so far (≤ 0: no gain), J.
        /// </summary>
        private static double LargestExcess(Rope rope, int steps, double drag, out double gain, out double largestPush)
        {
            double ceiling = RopeTestKit.TotalEnergy(rope, upper: true), allowance = 0.0, excess = double.NegativeInfinity;
            float decay = (float)Math.Exp(-drag * RopeTestKit.HostStep);
            gain = double.NegativeInfinity;
            largestPush = 0.0;
            for (int s = 0; s < steps; s++)
            {
                StepReport report = rope.Step(RopeTestKit.HostStep);
                if (drag > 0.0)
                    for (int i = 1; i < rope.ParticleCount; i++) rope.SetVelocity(i, rope.GetVelocity(i) * decay);
                Assert.That(RopeTestKit.AllFinite(rope), Is.True, "finite at step " + s);
                for (int j = 0; j < rope.SegmentCount; j++) largestPush = Math.Max(largestPush, -rope.Tensions[j]);
                rope.ElasticEnergyBounds(out double lower, out double upper);
                double k = rope.KineticEnergy(), g = rope.GravitationalEnergy();
                allowance += report.Substeps * RoundOffPerSubstep * (k + Math.Abs(g) + upper);
                gain = Math.Max(gain, k + g + lower - ceiling);
                excess = Math.Max(excess, k + g + lower - ceiling - allowance);
            }
            return excess;
        }

        [Test]
        public void ASwingingDampedSteelRodKeepsItsSegmentsAtTheirForce()
        {
            // the grid's settle case "E 2E+11 Pa, ratio 1, 16 seg, stretch 1, BackwardEuler, Bilateral, damped": β 0.05 s,
            // drag 3.13/s. Its light end segment spins; with XPBD's linearised stretch rate n·Δx in the dashpot (which reads a
            // rotation as a stretch: n·Δx − (l − l₀) = l₀(1 − cos θ)) it shortened by 43 µm at a tension of +0.1 N within
            // 0.58 s, ½C²/α = 0.25 J of elastic energy the motion never had (0.197 J above the energy put in).
            Rope rope = GridRod(2e11f, 16, 1f, 1f, TimeIntegrator.BackwardEuler, 0.05f);
            double alpha = 1.0 / 16 / rope.Settings.AxialStiffness, worst = 0.0;
            double ceiling = RopeTestKit.TotalEnergy(rope, upper: true);
            float decay = (float)Math.Exp(-Math.Sqrt(9.81) * RopeTestKit.HostStep);
            for (int s = 0; s < 135; s++)
            {
                rope.Step(RopeTestKit.HostStep);
                for (int i = 1; i < rope.ParticleCount; i++) rope.SetVelocity(i, rope.GetVelocity(i) * decay);
                for (int j = 0; j < rope.SegmentCount; j++)
                {
                    // the length error against the force: |l − L − α·T| (float positions: 4 ulps of 1 m is 4.8e-7 m)
                    double l = (rope.GetPosition(j + 1) - rope.GetPosition(j)).Length;
                    worst = Math.Max(worst, Math.Abs(l - 1.0 / 16 - alpha * rope.Tensions[j]));
                }
            }
            double final = RopeTestKit.TotalEnergy(rope, upper: false);
            TestContext.WriteLine($"largest |l − L − αT| {worst:G3} m over 1.5 s; total energy {final - ceiling:G4} J from the energy put in");
            Assert.That(worst, Is.LessThan(2e-6), "no segment drifts from the length its force implies");
            Assert.That(final, Is.LessThan(ceiling), "the damped rod only loses energy");
        }

        [TestCase(1e6f, 256, 1f, 1f, TestName = "Soft 256-segment rod laid at rest length (was +4.08 J)")]
        [TestCase(2e11f, 2, 10f, 1e6f, TestName = "Steel 2-segment rod with 1e6 load released 10x stretched (was +3.78 MJ)")]
        public void AnUndampedRodThatPushesGainsNoEnergyBeyondRoundOff(float youngsModulus, int segments, float stretch, float ratio)
        {
            // grid cases (BDF2, 1/90 s, 1 s, no damping): each segment pushes at some point; before the pushing segments took
            // no geometric stiffness (they took +|T|/l, the exact one being −|T|/l) the first two gained the energies named
            Rope rope = GridRod(youngsModulus, segments, stretch, ratio, TimeIntegrator.Bdf2, 0f);
            double excess = LargestExcess(rope, 90, 0.0, out double gain, out double push);
            TestContext.WriteLine($"largest push {push:G4} N; largest gain {gain:G4} J, {excess:G4} J beyond the round-off allowance");
            Assert.That(push, Is.GreaterThan(0.0), "the rod pushes");
            Assert.That(excess, Is.LessThanOrEqualTo(0.0), "no energy gain beyond round-off");
        }

        [Test]
        public void AStraightRodReleasedCompressedOscillatesAtItsAxialFrequency()
        {
            // a weightless straight rod (E 1 MPa, R 5 mm: k = E·A/L = 78.54 N/m; rope 0.0895 kg) pinned at the origin with a
            // 1 kg load, released 10 % compressed: it oscillates axially about its rest length with ω = √(k/(M + m/3))
            // (Rayleigh; the correction's error is O((m/M)²) ≈ 1e-4 here), period 0.7188 s, amplitude 0.1 m, and its energy
            // ½·k·0.1² = 0.3927 J neither rises beyond round-off nor falls by more than BDF2's dissipation at ωh = 0.0121
            var settings = RopeTestKit.Legacy(youngsModulus: 1e6f);
            settings.Tension = TensionModel.Bilateral;
            settings.Integrator = TimeIntegrator.Bdf2;
            settings.Gravity = Float3.Zero;
            var rope = new Rope(settings, Float3.Zero, new Float3(0.9f, 0f, 0f));
            rope.AddPin(0, Float3.Zero);
            int load = rope.AddLoad(rope.ParticleCount - 1, 1f);
            int end = rope.GetLoadParticle(load);
            double k = settings.AxialStiffness / 1.0, ropeMass = settings.LinearDensity * 1.0;
            double omega = Math.Sqrt(k / (1.0 + ropeMass / 3.0)), period = 2.0 * Math.PI / omega;
            // the energy is known within the elastic bounds (|F|·ε per segment each way, ε = 8 ulps of 1 m): a gain compares
            // the lower bound now with the upper one at the start, a loss the upper bound now with the lower one at the start
            double start = RopeTestKit.TotalEnergy(rope, upper: true), startLower = RopeTestKit.TotalEnergy(rope, upper: false);
            double lowest = double.PositiveInfinity, highest = double.NegativeInfinity;
            double previous = rope.GetPosition(end).X - 1.0, firstCrossing = -1.0, lastCrossing = -1.0, maxStretch = 0.0;
            int crossings = 0, steps = (int)Math.Ceiling(4.0 / RopeTestKit.HostStep);
            for (int s = 1; s <= steps; s++)
            {
                rope.Step(RopeTestKit.HostStep);
                double x = rope.GetPosition(end).X - 1.0;
                maxStretch = Math.Max(maxStretch, x);
                if (previous < 0.0 && x >= 0.0)
                {
                    // upward crossing of the rest length, interpolated within the host step
                    double t = (s - 1 + previous / (previous - x)) * RopeTestKit.HostStep;
                    if (crossings == 0) firstCrossing = t;
                    lastCrossing = t;
                    crossings++;
                }
                previous = x;
                lowest = Math.Min(lowest, RopeTestKit.TotalEnergy(rope, upper: true));
                highest = Math.Max(highest, RopeTestKit.TotalEnergy(rope, upper: false));
            }
            double measured = (lastCrossing - firstCrossing) / (crossings - 1);
            // BDF2's energy loss for ẍ = −ω²x is (ωh)⁴ per substep to leading order (|ρ|² = 1 − (ωh)⁴ + …): 4 s × 720/s
            double h = RopeTestKit.HostStep / settings.Substeps, loss = steps * settings.Substeps * Math.Pow(omega * h, 4);
            double allowance = steps * settings.Substeps * RoundOffPerSubstep * start;
            TestContext.WriteLine($"period {measured:G6} s (analytic {period:G6} s) over {crossings - 1} periods; amplitude {maxStretch:G4} m; " +
                $"energy: least upper bound {lowest:G6} J, largest lower bound {highest:G6} J, from [{startLower:G6}, {start:G6}] J (BDF2 loss bound {loss * start:G3} J, round-off {allowance:G3} J)");
            Assert.That(crossings, Is.GreaterThanOrEqualTo(5));
            Assert.That(measured, Is.EqualTo(period).Within(0.3).Percent);
            Assert.That(maxStretch, Is.EqualTo(0.1).Within(2).Percent);
            Assert.That(highest, Is.LessThanOrEqualTo(start + allowance), "no energy gain beyond round-off");
            Assert.That(lowest, Is.GreaterThanOrEqualTo(startLower * (1.0 - 2.0 * loss) - allowance), "no more loss than BDF2 explains");
        }
    }
}
