using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Issue 15 item 4: a free rope falls at the terminal velocity of its drag law, where the drag per metre equals the weight
    /// per metre μ·g: viscous c·v_t = μg (any orientation); across the rope ½·ρ·C_d·2R·v_t² = μg (a horizontal rope falling
    /// broadside); along it ½·ρ·C_f·2πR·v_t² = μg (a vertical rope falling lengthwise). Each rope starts at rest and falls for
    /// ten time constants (v_t/g): v = v_t·tanh(g·t/v_t) is then within 1e-8 of v_t (viscous: 1 − e^−10), and the tolerance is 2 %.
    /// Default rope (2 m, R 8 mm, μ = 0.2292 kg/m, 24 segments, BDF2 at 8 × 1/90 s) unless stated.
    /// </summary>
    public sealed class DragTerminalVelocityTests
    {
        private const double G = 9.81;

        /// <summary>Drops a free rope (horizontal along x, or vertical) from rest for <paramref name="seconds"/>; returns the slowest and fastest fall speeds (m/s).</summary>
        private static (double Slowest, double Fastest) Fall(RopeSettings settings, bool horizontal, double seconds)
        {
            float length = settings.RestLength;
            var rope = new Rope(settings, Float3.Zero, horizontal ? new Float3(length, 0f, 0f) : new Float3(0f, -length, 0f));
            int steps = (int)Math.Ceiling(seconds * 90.0);
            for (int k = 0; k < steps; k++) rope.Step(1f / 90f);
            double slowest = double.MaxValue, fastest = 0.0;
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                double v = -rope.GetVelocity(i).Y;
                slowest = Math.Min(slowest, v);
                fastest = Math.Max(fastest, v);
            }
            return (slowest, fastest);
        }

        private static void AssertTerminal(string what, (double Slowest, double Fastest) v, double expected)
        {
            TestContext.WriteLine($"{what}: {v.Slowest:G6} … {v.Fastest:G6} m/s vs {expected:G6} m/s ({(v.Slowest / expected - 1) * 100:+0.0000;-0.0000} % … {(v.Fastest / expected - 1) * 100:+0.0000;-0.0000} %)");
            Assert.That(v.Slowest, Is.EqualTo(expected).Within(2).Percent, what);
            Assert.That(v.Fastest, Is.EqualTo(expected).Within(2).Percent, what);
        }

        [TestCase(true, TimeIntegrator.Bdf2)]
        [TestCase(false, TimeIntegrator.Bdf2)]
        [TestCase(true, TimeIntegrator.BackwardEuler)]
        public void ViscousTerminalVelocityIsMuGOverC(bool horizontal, TimeIntegrator integrator)
        {
            var settings = new RopeSettings { ViscousDrag = 0.2f, Integrator = integrator };
            double expected = settings.LinearDensity * G / settings.ViscousDrag;
            AssertTerminal($"viscous, {(horizontal ? "broadside" : "lengthwise")}, {integrator}", Fall(settings, horizontal, 10.0 * expected / G), expected);
        }

        [TestCase(TimeIntegrator.Bdf2)]
        [TestCase(TimeIntegrator.BackwardEuler)]
        public void BroadsideTerminalVelocityFollowsTheQuadraticLaw(TimeIntegrator integrator)
        {
            var settings = new RopeSettings { DragCoefficient = 1.2f, Integrator = integrator };
            double expected = Math.Sqrt(2.0 * settings.LinearDensity * G / (settings.AirDensity * settings.DragCoefficient * 2.0 * settings.Radius));
            AssertTerminal($"air drag across (C_d 1.2, ρ 1.2 kg/m³), broadside, {integrator}", Fall(settings, true, 10.0 * expected / G), expected);
        }

        [Test]
        public void LengthwiseTerminalVelocityFollowsTheSkinFriction()
        {
            // in water (ρ 1000 kg/m³, C_f 0.01): v_t ≈ 3 m/s, so the 30 m fall stays where float32 positions are fine
            var settings = new RopeSettings { SkinFriction = 0.01f, DragCoefficient = 1.2f, AirDensity = 1000f };
            double expected = Math.Sqrt(2.0 * settings.LinearDensity * G / (settings.AirDensity * settings.SkinFriction * 2.0 * Math.PI * settings.Radius));
            AssertTerminal("skin friction along (C_f 0.01, water), lengthwise, C_d 1.2 across", Fall(settings, false, 10.0 * expected / G), expected);
        }

        [Test]
        public void DragAcrossTheRopeDoesNotActAlongIt()
        {
            // C_d alone, a vertical rope falling lengthwise: nothing slows it, v = g·t (1 s). The particles' speeds differ by a few
            // 1e-5 of it without drag too: float32 positions 5 m down round the segment lengths by ~5e-7 m, which the chain solve
            // turns into ~h⁻¹·5e-7 m/s
            var v = Fall(new RopeSettings { DragCoefficient = 1.2f }, false, 1.0);
            var free = Fall(new RopeSettings(), false, 1.0);
            TestContext.WriteLine($"C_d only, lengthwise: {v.Slowest:G7} … {v.Fastest:G7} m/s after 1 s vs g·t = {G:G7} m/s (no drag: {free.Slowest:G7} … {free.Fastest:G7} m/s)");
            Assert.That(v.Slowest, Is.EqualTo(G).Within(0.01).Percent);
            Assert.That(v.Fastest, Is.EqualTo(G).Within(0.01).Percent);
        }
    }
}
