using System;
using HookeRope.Radius;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Radius
{
    public sealed class PoissonRadiusTests
    {
        [TestCase(-0.8, 1.2)]
        [TestCase(-0.8, 1.6)]
        [TestCase(0.0, 1.6)]
        [TestCase(0.3, 1.2)]
        [TestCase(0.3, 2.0)]
        [TestCase(0.5, 1.6)]
        [TestCase(0.5, 10.0)]
        public void SegmentRadiusMatchesEquation16(double nu, double stretch)
        {
            var settings = new RadiusSettings { NeckRadiusFraction = 0.8f, PoissonRatio = (float)nu, Necking = false, Fracture = false };
            const float restRadius = 0.006f;
            var rest = new[] { 0.1f, 0.1f, 0.1f };
            var model = new RadiusModel(settings, restRadius, rest);
            var current = new[] { (float)(0.1 * stretch), 0.1f, (float)(0.1 * stretch) };
            model.Update(current, ReadOnlySpan<bool>.Empty);

            double expected = Math.Sqrt(1.0 + 2.0 * nu * (1.0 / stretch - 1.0));
            Assert.That(model.SegmentRadii[0] / restRadius, Is.EqualTo(expected).Within(1e-6));
            Assert.That(model.SegmentRadii[2] / restRadius, Is.EqualTo(expected).Within(1e-6));
            Assert.That(model.SegmentRadii[1] / restRadius, Is.EqualTo(1.0).Within(1e-6));
        }

        [TestCase(-0.8)]
        [TestCase(0.0)]
        [TestCase(0.3)]
        [TestCase(0.5)]
        public void RatioFunctionMatchesEquation16InDouble(double nu)
        {
            for (double stretch = 1.0; stretch <= 3.0; stretch += 0.25)
            {
                double expected = Math.Sqrt(1.0 + 2.0 * nu * (1.0 / stretch - 1.0));
                Assert.That(PoissonRadius.Ratio(2.0, 2.0 * stretch, nu, true), Is.EqualTo(expected).Within(1e-12));
            }
        }

        [Test]
        public void HalfPoissonRatioKeepsSegmentVolume()
        {
            for (double stretch = 1.0; stretch <= 10.0; stretch += 0.5)
            {
                double ratio = PoissonRadius.Ratio(1.0, stretch, 0.5, true);
                Assert.That(ratio * ratio * stretch, Is.EqualTo(1.0).Within(1e-12));
            }
        }

        [TestCase(-1.0)]
        [TestCase(-0.8)]
        [TestCase(0.5)]
        public void CompressionIsClampedAndNeverNaN(double nu)
        {
            double[] lengths = { 0.9, 0.5, 0.25, 0.1, 1e-9, 0.0, -1.0, double.NaN };
            foreach (double length in lengths)
            {
                double ratio = PoissonRadius.Ratio(1.0, length, nu, false);
                Assert.That(double.IsNaN(ratio), Is.False, "l = " + length);
                Assert.That(ratio, Is.GreaterThanOrEqualTo(0.01 - 1e-12));
                Assert.That(ratio, Is.LessThanOrEqualTo(2.0 + 1e-12));
            }
            // nu = -1 at l = 2L/3 would be sqrt(0): the clamp keeps 1 % of R.
            Assert.That(PoissonRadius.Ratio(1.0, 0.5, -1.0, false), Is.EqualTo(0.01).Within(1e-12));
            // nu = 0.5 at l ≤ L/4 is capped at L/l = 4: sqrt(1 + 3) = 2.
            Assert.That(PoissonRadius.Ratio(1.0, 0.1, 0.5, false), Is.EqualTo(2.0).Within(1e-12));
        }

        [Test]
        public void SlackSegmentKeepsRestRadiusByDefault()
        {
            Assert.That(PoissonRadius.Ratio(1.0, 0.5, 0.5, true), Is.EqualTo(1.0));
            Assert.That(PoissonRadius.Ratio(1.0, 0.5, 0.5, false), Is.EqualTo(Math.Sqrt(2.0)).Within(1e-12));
        }

        [TestCase(0.8, 0.5, 0.5625)]
        [TestCase(0.5, 0.5, 3.0)]
        public void OnsetStrainInvertsEquation16(double fraction, double nu, double expectedStrain)
        {
            double strain = PoissonRadius.StrainAtRatio(fraction, nu);
            Assert.That(strain, Is.EqualTo(expectedStrain).Within(1e-12));
            Assert.That(PoissonRadius.Ratio(1.0, 1.0 + strain, nu, true), Is.EqualTo(fraction).Within(1e-12));
        }

        [Test]
        public void OnsetIsNeverReachedBelowTheAsymptote()
        {
            // nu = 0.3: r/R → sqrt(0.4) ≈ 0.632 as l → ∞, so 0.5 is never reached; nu ≤ 0 never thins.
            Assert.That(PoissonRadius.StrainAtRatio(0.5, 0.3), Is.EqualTo(double.PositiveInfinity));
            Assert.That(PoissonRadius.StrainAtRatio(0.9, 0.0), Is.EqualTo(double.PositiveInfinity));
            Assert.That(PoissonRadius.StrainAtRatio(0.9, -0.5), Is.EqualTo(double.PositiveInfinity));
        }

        [Test]
        public void HangingRopeIsThinnerWhereItIsStretchedMore()
        {
            // Static hanging rope: strain falls linearly from the top (segment 0) to the bottom.
            const int n = 10;
            var rest = new float[n];
            var current = new float[n];
            for (int j = 0; j < n; j++)
            {
                rest[j] = 0.2f;
                current[j] = 0.2f * (1f + 0.3f * (n - j - 0.5f) / n);
            }
            var model = new RadiusModel(new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, Necking = false, BreakStrain = 1000f }, 0.01f, rest);
            model.Update(current, ReadOnlySpan<bool>.Empty);
            for (int i = 1; i <= n; i++)
                Assert.That(model.ParticleRadii[i], Is.GreaterThan(model.ParticleRadii[i - 1]));
            Assert.That(model.ParticleRadii[0], Is.EqualTo(model.SegmentRadii[0]));
            Assert.That(model.ParticleRadii[1], Is.EqualTo(0.5f * (model.SegmentRadii[0] + model.SegmentRadii[1])).Within(1e-9));
            Assert.That(model.MinRadius, Is.EqualTo(model.ParticleRadii[0]));
        }
    }
}
