using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    public sealed class StaticHangTests
    {
        // 2 m lanyard, 0.2 kg, E·A = 100 kN, 100 kg worker: elongation (M + m/2) g L / EA ≈ 19.6 mm
        private const float Length = 2f, RopeMass = 0.2f, AxialStiffness = 1e5f, Load = 100f;

        [TestCase(ConstraintSolverKind.ExactChain)]
        public void HangingRopeWithLoadReachesStaticElongationAndTopTension(ConstraintSolverKind solver)
        {
            var settings = RopeTestKit.Settings(Length, 20, AxialStiffness, RopeMass);
            settings.Solver = solver;
            // damped (ζ ≈ 0.1 on the load's 22 rad/s mode) so that it comes to rest: the static answer does not depend on β
            settings.Damping = 0.01f;
            var rope = RopeTestKit.Hanging(settings, Load, out _);
            for (int i = 0; i < 90 * 60; i++) rope.Step(RopeTestKit.HostStep);

            double expectedElongation = (Load + RopeMass / 2.0) * RopeTestKit.G * Length / AxialStiffness;
            double elongation = -RopeTestKit.Bottom(rope) - Length;
            double expectedTop = (Load + RopeMass) * RopeTestKit.G;
            double top = rope.GetPinForce(0).Length;
            TestContext.WriteLine($"elongation {elongation:G6} m vs {expectedElongation:G6} m; top {top:G6} N vs {expectedTop:G6} N");
            Assert.That(elongation, Is.EqualTo(expectedElongation).Within(0.5).Percent);
            Assert.That(top, Is.EqualTo(expectedTop).Within(0.5).Percent);
        }
    }
}
