using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Issue 15 item 4: a rope hanging from a pin in a steady horizontal wind u settles straight, at the angle θ from the vertical
    /// where the drag balances the weight across the rope. A straight rope stays straight only when the load across it vanishes
    /// (T·κ = q⊥): viscous drag acts on the whole relative velocity, a uniform load (c·u, −μg) per metre, so tan θ = c·u/(μ·g);
    /// quadratic drag acts on the wind's component across the rope, u·cos θ, so μ·g·sin θ = ½·ρ·C_d·2R·u²·cos²θ (the component
    /// along is carried by the tension, which then reads μ·g·cos θ per metre). Default rope, BDF2 and backward Euler, 30 s.
    /// </summary>
    public sealed class DragWindTests
    {
        private const double G = 9.81;

        private static Rope Hang(RopeSettings settings, double seconds)
        {
            var rope = new Rope(settings, Float3.Zero, new Float3(0f, -settings.RestLength, 0f));
            rope.AddPin(0, Float3.Zero);
            for (int k = 0; k < (int)(seconds * 90.0); k++) rope.Step(1f / 90f);
            return rope;
        }

        /// <summary>Angle (rad) of the pin → end chord from the downward vertical, towards +x; and the largest distance (m) of a particle from that chord.</summary>
        private static double Angle(Rope rope, out double offLine)
        {
            Float3 end = rope.GetPosition(rope.ParticleCount - 1);
            double angle = Math.Atan2(end.X, -end.Y);
            offLine = 0.0;
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                Float3 p = rope.GetPosition(i);
                offLine = Math.Max(offLine, Math.Abs(p.X * Math.Cos(angle) + p.Y * Math.Sin(angle)));
            }
            return angle;
        }

        [TestCase(TimeIntegrator.Bdf2)]
        [TestCase(TimeIntegrator.BackwardEuler)]
        public void ViscousDragInAWindTiltsTheRopeToTanThetaEqualsCuOverMuG(TimeIntegrator integrator)
        {
            var settings = new RopeSettings { ViscousDrag = 0.5f, Wind = new Float3(3f, 0f, 0f), Integrator = integrator };
            var rope = Hang(settings, 30.0);
            double expected = Math.Atan(settings.ViscousDrag * 3.0 / (settings.LinearDensity * G));
            double angle = Angle(rope, out double offLine);
            // first segment's tension: the load per metre sqrt((μg)² + (cu)²) times the rope below its middle
            double load = Math.Sqrt(Math.Pow(settings.LinearDensity * G, 2) + Math.Pow(settings.ViscousDrag * 3.0, 2));
            double top = load * settings.RestLength * (1.0 - 0.5 / settings.SegmentCount);
            TestContext.WriteLine($"{integrator}: {angle * 180 / Math.PI:F4}° vs atan(cu/μg) = {expected * 180 / Math.PI:F4}° ({(angle / expected - 1) * 100:+0.000;-0.000} %), " +
                $"off the line {offLine * 1000:G3} mm, top tension {rope.Tensions[0]:G5} N vs {top:G5} N");
            Assert.That(angle, Is.EqualTo(expected).Within(0.5).Percent);
            Assert.That(offLine, Is.LessThan(1e-3), "straight");
            Assert.That(rope.Tensions[0], Is.EqualTo(top).Within(1).Percent);
        }

        [TestCase(TimeIntegrator.Bdf2)]
        [TestCase(TimeIntegrator.BackwardEuler)]
        public void AirDragInAWindTiltsTheRopeUntilTheCrossFlowDragCarriesTheWeight(TimeIntegrator integrator)
        {
            var settings = new RopeSettings { DragCoefficient = 1.2f, Wind = new Float3(10f, 0f, 0f), Integrator = integrator };
            var rope = Hang(settings, 30.0);
            // μg·sin θ = ρ·C_d·R·u²·cos²θ → k·s² + s − k = 0 with s = sin θ, k = ρ·C_d·R·u²/(μg)
            double k = settings.AirDensity * settings.DragCoefficient * settings.Radius * 100.0 / (settings.LinearDensity * G);
            double expected = Math.Asin((Math.Sqrt(1.0 + 4.0 * k * k) - 1.0) / (2.0 * k));
            double angle = Angle(rope, out double offLine);
            double top = settings.LinearDensity * G * Math.Cos(expected) * settings.RestLength * (1.0 - 0.5 / settings.SegmentCount);
            TestContext.WriteLine($"{integrator}: {angle * 180 / Math.PI:F4}° vs {expected * 180 / Math.PI:F4}° ({(angle / expected - 1) * 100:+0.000;-0.000} %), " +
                $"off the line {offLine * 1000:G3} mm, top tension {rope.Tensions[0]:G5} N vs μg·cosθ·L = {top:G5} N");
            Assert.That(angle, Is.EqualTo(expected).Within(0.5).Percent);
            Assert.That(offLine, Is.LessThan(1e-3), "straight");
            Assert.That(rope.Tensions[0], Is.EqualTo(top).Within(1).Percent);
        }

        [Test]
        public void WindWithoutDragDoesNothing()
        {
            var still = Hang(new RopeSettings(), 2.0);
            var windy = Hang(new RopeSettings { Wind = new Float3(30f, 0f, -20f) }, 2.0);
            for (int i = 0; i < still.ParticleCount; i++)
                Assert.That(windy.GetPosition(i), Is.EqualTo(still.GetPosition(i)), "particle " + i);
            Assert.That(windy.DragWork, Is.EqualTo(0.0));
        }
    }
}
