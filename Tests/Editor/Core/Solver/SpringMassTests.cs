using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    public sealed class SpringMassTests
    {
        // 10 kg on a 1 m light rope (10 g), k = E·A/L chosen for a 0.25 s period.
        private const float Mass = 10f, Length = 1f, RopeMass = 0.01f;
        private static readonly float Stiffness = (float)(4.0 * Math.PI * Math.PI * Mass / (0.25 * 0.25));

        private static Rope Build(float damping, out double equilibrium)
        {
            var settings = RopeTestKit.Settings(Length, 4, Stiffness * Length, RopeMass);
            settings.Damping = damping;
            var rope = RopeTestKit.Hanging(settings, Mass, out _);
            double stretch = (Mass + RopeMass / 2.0) * RopeTestKit.G / Stiffness;
            equilibrium = -(Length + stretch);
            // start 0.5 static stretches below equilibrium, at rest: amplitude 0.5·stretch, never slack
            int n = rope.ParticleCount;
            for (int i = 1; i < n; i++)
            {
                float y = (float)((Length + 1.5 * stretch) * i / (n - 1));
                rope.SetPosition(i, new Float3(0f, -y, 0f));
            }
            return rope;
        }

        [Test]
        public void PeriodMatchesTwoPiSqrtMOverK()
        {
            var rope = Build(0f, out double equilibrium);
            double expected = 2.0 * Math.PI * Math.Sqrt(Mass * Length / (Stiffness * Length));
            double previous = RopeTestKit.Bottom(rope) - equilibrium, time = 0.0, firstCrossing = -1.0, lastCrossing = -1.0;
            int crossings = 0;
            while (crossings < 9)
            {
                rope.Step(RopeTestKit.HostStep);
                time += RopeTestKit.HostStep;
                double u = RopeTestKit.Bottom(rope) - equilibrium;
                if (previous < 0.0 && u >= 0.0)
                {
                    double crossing = time - RopeTestKit.HostStep * u / (u - previous);
                    if (firstCrossing < 0.0) firstCrossing = crossing;
                    lastCrossing = crossing;
                    crossings++;
                }
                previous = u;
            }
            double period = (lastCrossing - firstCrossing) / (crossings - 1);
            TestContext.WriteLine($"period {period:G6} s vs {expected:G6} s ({(period / expected - 1) * 100:F3} %)");
            Assert.That(period, Is.EqualTo(expected).Within(1).Percent);
        }

        [Test]
        public void EnergyNeverRisesOverAThousandPeriodsWithoutDamping()
        {
            var rope = Build(0f, out _);
            double start = rope.TotalEnergy(), previous = start, worstRise = 0.0;
            int steps = (int)Math.Ceiling(1000 * 0.25 / RopeTestKit.HostStep);
            for (int i = 0; i < steps; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                double e = rope.TotalEnergy();
                worstRise = Math.Max(worstRise, (e - previous) / Math.Abs(previous));
                previous = e;
            }
            TestContext.WriteLine($"worst relative rise per step {worstRise:E3}; energy {start:G9} J -> {previous:G9} J");
            Assert.That(worstRise, Is.LessThanOrEqualTo(1e-6));
            Assert.That(previous, Is.LessThanOrEqualTo(start));
        }
    }
}
