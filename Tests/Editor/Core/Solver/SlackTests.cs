using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>A load thrown upward on a light vertical rope: free flight while slack, spring while taut.</summary>
    public sealed class SlackTests
    {
        private const float Mass = 10f, Length = 1f, Stiffness = 500f, RopeMass = 0.005f, ThrowSpeed = 2f;

        // One segment: with several, the light particles fall freely while the rope is slack and the rope
        // folds, which catches the load a little early (physical, but not the formula's spring).
        private static Rope Build(TensionModel model, out int load, out double equilibrium)
        {
            var settings = RopeTestKit.Settings(Length, 1, Stiffness * Length, RopeMass);
            settings.Tension = model;
            var rope = RopeTestKit.Hanging(settings, Mass, out load);
            double stretch = (Mass + RopeMass / 2.0) * RopeTestKit.G / Stiffness;
            equilibrium = -(Length + stretch);
            int n = rope.ParticleCount;
            for (int i = 1; i < n; i++)
                rope.SetPosition(i, new Float3(0f, (float)(equilibrium * i / (n - 1)), 0f));
            rope.SetVelocity(n - 1, new Float3(0f, ThrowSpeed, 0f));
            return rope;
        }

        [Test]
        public void BouncePeriodMatchesFreeFlightPlusSpringPhases()
        {
            var rope = Build(TensionModel.TensionOnly, out int load, out double equilibrium);
            double mg = Mass * RopeTestKit.G;
            double omega = Math.Sqrt(Stiffness / Mass), delta = mg / Stiffness, amplitude = ThrowSpeed / omega;
            double slackSpeed = Math.Sqrt(ThrowSpeed * ThrowSpeed - delta * delta * omega * omega);
            // taut while the SHM phase is in [0, asin(δ/A)] or [π − asin(δ/A), 2π]; parabola in between
            double expected = 2.0 * slackSpeed / RopeTestKit.G + (Math.PI + 2.0 * Math.Asin(delta / amplitude)) / omega;

            double previous = 0.0, time = 0.0, crossing = -1.0, worstFlightForce = 0.0;
            int flightSteps = 0;
            for (int i = 0; i < 200 && crossing < 0.0; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                time += RopeTestKit.HostStep;
                double y = RopeTestKit.Bottom(rope);
                double u = y - equilibrium;
                if (y > -Length + 0.01) // well above the taut point over the whole step: free flight
                {
                    flightSteps++;
                    worstFlightForce = Math.Max(worstFlightForce, rope.GetLoadForce(load).Length);
                }
                if (i > 5 && previous < 0.0 && u >= 0.0) crossing = time - RopeTestKit.HostStep * u / (u - previous);
                previous = u;
            }
            TestContext.WriteLine($"bounce period {crossing:G6} s vs {expected:G6} s ({(crossing / expected - 1) * 100:F3} %); rope force in flight ≤ {worstFlightForce:G3} N over {flightSteps} steps");
            Assert.That(flightSteps, Is.GreaterThan(10));
            Assert.That(worstFlightForce, Is.LessThan(1e-3 * mg), "a slack rope does not push");
            Assert.That(crossing, Is.EqualTo(expected).Within(1).Percent);
        }

        [Test]
        public void BilateralRodPushesTheLoadBack()
        {
            var rope = Build(TensionModel.Bilateral, out int load, out _);
            double highest = double.NegativeInfinity, largestPush = 0.0;
            for (int i = 0; i < 60; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                highest = Math.Max(highest, RopeTestKit.Bottom(rope));
                largestPush = Math.Max(largestPush, -rope.GetLoadForce(load).Y);
            }
            TestContext.WriteLine($"rod: highest {highest:G6} m, largest downward push {largestPush:G6} N");
            // a rod is a linear spring through its rest length: simple harmonic motion about equilibrium
            double omega = Math.Sqrt(Stiffness / Mass), amplitude = ThrowSpeed / omega;
            double delta = (Mass + RopeMass / 2.0) * RopeTestKit.G / Stiffness;
            Assert.That(highest, Is.EqualTo(-(Length + delta) + amplitude).Within(0.005));
            Assert.That(largestPush, Is.EqualTo(Stiffness * (amplitude - delta)).Within(3).Percent, "the rod pushes the load back down");
        }
    }
}
