using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    public sealed class DampingTests
    {
        private static Rope Oscillator(float damping, out int load)
        {
            // rope 0.5 kg, load 10 kg: a mass ratio Gauss–Seidel can carry (see MassRatioTests for one it cannot)
            var settings = RopeTestKit.Settings(1f, 8, 2000f, 0.5f);
            settings.Damping = damping;
            var rope = RopeTestKit.Hanging(settings, 10f, out load);
            rope.SetVelocity(8, new Float3(0f, -0.3f, 0f));
            return rope;
        }

        // ExactChain only: Gauss–Seidel with one iteration leaves the 1:20 chain unconverged, and its
        // elastic-energy reading then rises (documented in Documentation~/solver.md).
        [TestCase(ConstraintSolverKind.ExactChain)]
        public void DampingRemovesVibrationEnergyWithoutMovingTheStaticSolution(ConstraintSolverKind solver)
        {
            var plain = Oscillator(0f, out _);
            var damped = Oscillator(0.02f, out _); // ζ = βω/2 ≈ 0.14 at ω = 14 rad/s
            plain.Settings.Solver = solver;
            damped.Settings.Solver = solver;
            TestContext.WriteLine("solver " + solver);
            double e0 = damped.TotalEnergy();
            for (int i = 0; i < 90; i++) { plain.Step(RopeTestKit.HostStep); damped.Step(RopeTestKit.HostStep); }
            double expectedRest = -(1.0 + (10.0 + 0.25) * RopeTestKit.G / 2000.0);
            double energyPlain = plain.KineticEnergy() + plain.ElasticEnergy() + plain.GravitationalEnergy();
            double energyDamped = damped.TotalEnergy();
            Assert.That(energyDamped, Is.LessThan(energyPlain));
            Assert.That(energyDamped, Is.LessThan(e0));
            for (int i = 0; i < 90 * 5; i++) damped.Step(RopeTestKit.HostStep);
            Assert.That(damped.KineticEnergy(), Is.LessThan(1e-6), "at rest");
            TestContext.WriteLine($"rest {RopeTestKit.Bottom(damped):G6} m vs {expectedRest:G6} m");
            Assert.That(RopeTestKit.Bottom(damped), Is.EqualTo(expectedRest).Within(2e-4), "at the undamped static position");
        }
    }
}
