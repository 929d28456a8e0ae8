using System;
using System.Collections.Generic;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Coulomb friction against the capstan equation (issue 15 item 3, <see cref="CapstanScenes"/>): a light rope wrapped by
    /// θ round a fixed collider with friction μ, loads m1 and m2 at its ends. The friction the exact chain solve applies is
    /// bounded by μ times the normal impulse the solve itself produces (tension × wrap), so the wrap holds a load ratio
    /// 2 % below e^{μθ} and slides 2 % above it, with the capstan acceleration g (m1 − m2 e^{μθ}) / (m1 + m2 e^{μθ});
    /// friction never adds energy.
    /// </summary>
    public sealed class CapstanTests
    {
        /// <summary>All 18 cases with friction, met both ways (Documentation~/solver.md, "Friction and the capstan equation", lists every measured case).</summary>
        private static IEnumerable<TestCaseData> Cases()
        {
            foreach (double theta in new[] { Math.PI / 2, Math.PI, 2 * Math.PI })
                foreach (float mu in new[] { 0.1f, 0.3f, 0.6f })
                    yield return new TestCaseData(false, theta, mu).SetName($"Cylinder θ {theta / Math.PI:0.#}π μ {mu}");
            foreach (float mu in new[] { 0.1f, 0.3f, 0.6f })
                yield return new TestCaseData(true, Math.PI / 2, mu).SetName($"Box edge θ 0.5π μ {mu}");
            foreach (float mu in new[] { 0.1f, 0.3f, 0.6f })
                yield return new TestCaseData(true, Math.PI, mu).SetName($"Box edges θ 1π μ {mu}");
            foreach (float mu in new[] { 0.1f, 0.3f, 0.6f })
                yield return new TestCaseData(true, 2 * Math.PI, mu).SetName($"Box edges θ 2π μ {mu}");
        }

        private static void Holds(bool box, double theta, float mu)
        {
            var shape = Shape(box);
            double grip = Math.Exp(mu * theta);
            var held = CapstanScenes.Run(shape, theta, mu, 0.98 * grip);
            TestContext.WriteLine($"{shape} θ {theta:F4} μ {mu}: e^μθ {grip:F4}; ratio 0.98 e^μθ slides {held.Slide * 100:F3} cm in 2 s, energy gain {held.EnergyGain:E2} J");
            Assert.That(held.Finite, Is.True);
            Assert.That(Math.Abs(held.Slide), Is.LessThan(0.01), "2 % below e^{μθ} the wrap holds (under 1 cm in 2 s)");
            Assert.That(held.EnergyGain, Is.LessThan(1e-6), "friction adds no energy");
        }

        [TestCaseSource(nameof(Cases))]
        public void TwoPercentBelowTheCapstanRatioHolds(bool box, double theta, float mu) => Holds(box, theta, mu);

        private static CapstanScenes.Shape Shape(bool box) => box ? CapstanScenes.Shape.BoxEdges : CapstanScenes.Shape.Cylinder;

        [TestCaseSource(nameof(Cases))]
        public void TwoPercentAboveTheCapstanRatioSlidesWithTheCapstanAcceleration(bool box, double theta, float mu)
        {
            var shape = Shape(box);
            double ratio = 1.02 * Math.Exp(mu * theta);
            var slid = CapstanScenes.Run(shape, theta, mu, ratio);
            double expected = CapstanScenes.Acceleration(theta, mu, ratio);
            TestContext.WriteLine($"{shape} θ {theta:F4} μ {mu}: ratio 1.02 e^μθ slides {slid.Slide * 100:F2} cm in 2 s, acceleration {slid.Acceleration:F5} m/s² (capstan {expected:F5}, {(slid.Acceleration / expected - 1) * 100:F2} %), energy gain {slid.EnergyGain:E2} J");
            Assert.That(slid.Finite, Is.True);
            Assert.That(slid.Acceleration, Is.EqualTo(expected).Within(5).Percent, "capstan dynamics");
            Assert.That(slid.EnergyGain, Is.LessThan(1e-6), "friction adds no energy");
        }

        [TestCase(false)]
        [TestCase(true)]
        public void WithoutFrictionTheRopeSlidesFreely(bool box)
        {
            var shape = Shape(box);
            // μ = 0: any excess slides, with the Atwood acceleration g (m1 − m2)/(m1 + m2) of a massless rope
            var slid = CapstanScenes.Run(shape, Math.PI, 0f, 1.02);
            double expected = CapstanScenes.Acceleration(Math.PI, 0.0, 1.02);
            TestContext.WriteLine($"{shape} μ 0: slides {slid.Slide * 100:F2} cm in 2 s, acceleration {slid.Acceleration:F5} m/s² (Atwood {expected:F5})");
            Assert.That(slid.Acceleration, Is.EqualTo(expected).Within(2).Percent);
            Assert.That(slid.EnergyGain, Is.LessThan(1e-6));
        }

        [Test]
        public void NegativeFrictionIsRejectedWithItsRange()
        {
            var capsule = Assert.Throws<ArgumentOutOfRangeException>(() => ColliderShape.Capsule(Float3.Zero, Quat.Identity, 0.1f, 0.5f, -0.1f));
            Assert.That(capsule.ParamName, Is.EqualTo("friction"));
            Assert.That(capsule.Message, Does.Contain("[0, +inf)"));
            var box = Assert.Throws<ArgumentOutOfRangeException>(() => ColliderShape.Box(Float3.Zero, Quat.Identity, new Float3(1f, 1f, 1f), float.NaN));
            Assert.That(box.ParamName, Is.EqualTo("friction"));
            var stat = Assert.Throws<ArgumentOutOfRangeException>(() => ColliderShape.Sphere(Float3.Zero, 1f, 0.3f).WithStaticFriction(-1f));
            Assert.That(stat.ParamName, Is.EqualTo("staticFriction"));
        }
    }
}
