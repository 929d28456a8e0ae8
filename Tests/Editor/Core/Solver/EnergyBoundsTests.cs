using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// <see cref="Rope.ElasticEnergyBounds"/>: the elastic energy of every state within float32 round-off of the rope's
    /// lies between the bounds, which bracket Σ ½C²/α, and the lower one does not read position round-off as energy.
    /// </summary>
    public sealed class EnergyBoundsTests
    {
        [TestCase(TensionModel.TensionOnly)]
        [TestCase(TensionModel.Bilateral)]
        public void BoundsBracketTheElasticEnergyOfAStretchedRope(TensionModel tension)
        {
            // 1 m, E·A = 78.5 N (1 MPa, R 5 mm), laid 10 % stretched: U = ½·E·A·0.1²/1 = 0.3927 J
            var settings = RopeTestKit.Legacy(youngsModulus: 1e6f);
            settings.Tension = tension;
            var rope = new Rope(settings, Float3.Zero, new Float3(0f, -1.1f, 0f));
            rope.ElasticEnergyBounds(out double lower, out double upper);
            double exact = 0.5 * settings.AxialStiffness * 0.1 * 0.1;
            TestContext.WriteLine($"lower {lower:G9} J, Σ½C²/α {rope.ElasticEnergy():G9} J, upper {upper:G9} J, ½EAε² {exact:G9} J");
            Assert.That(rope.ElasticEnergy(), Is.EqualTo(exact).Within(1e-4).Percent);
            Assert.That(lower, Is.LessThanOrEqualTo(rope.ElasticEnergy()));
            Assert.That(upper, Is.GreaterThanOrEqualTo(rope.ElasticEnergy()));
            // the bounds are |F|·ε apart: ε = 8·2⁻²³·1.1 m ≈ 1 µm on a 6.25 mm stretch, 0.02 % of the energy each way
            Assert.That(lower, Is.EqualTo(exact).Within(0.05).Percent);
            Assert.That(upper, Is.EqualTo(exact).Within(0.05).Percent);
        }

        [Test]
        public void ASlackTensionOnlyRopeStoresNothing()
        {
            var rope = new Rope(RopeTestKit.Legacy(youngsModulus: 1e6f), Float3.Zero, new Float3(0f, -0.9f, 0f));
            rope.ElasticEnergyBounds(out double lower, out double upper);
            Assert.That(lower, Is.EqualTo(0.0));
            Assert.That(upper, Is.EqualTo(0.0));
        }

        [Test]
        public void CompliantPinsAreCounted()
        {
            // a 1 MPa rope at rest length hangs from a compliant pin (α = 1e-3 m/N) displaced 10 cm: ½·0.1²/1e-3 = 5 J
            var rope = new Rope(RopeTestKit.Legacy(youngsModulus: 1e6f), Float3.Zero, new Float3(0f, -1f, 0f));
            rope.AddPin(0, new Float3(0.1f, 0f, 0f), compliance: 1e-3f);
            rope.ElasticEnergyBounds(out double lower, out double upper);
            // ε = 8·2⁻²³·1 m = 9.5e-7 m on 0.1 m: each bound within 2ε/0.1 = 0.0019 % of 5 J
            Assert.That(lower, Is.EqualTo(5.0).Within(0.003).Percent);
            Assert.That(upper, Is.EqualTo(5.0).Within(0.003).Percent);
            Assert.That(lower, Is.LessThan(rope.ElasticEnergy()));
            Assert.That(upper, Is.GreaterThan(rope.ElasticEnergy()));
        }

        [Test]
        public void BoundsBracketASteelRopesSolvedEnergy()
        {
            // a 1 m steel rope (E 200 GPa, R 5 mm, 256 segments, α = 2.5e-10 m/N) hanging still with 1 kg: since the
            // positions carry sub-float remainders, Σ ½C²/α from the positions equals Σ ½·α·T_j² from the solved tensions
            // (a few µJ: 2.5 nm per segment); the bounds bracket both, the upper one by Σ ½(|C| + ε)²/α with ε = 8 ulps of
            // 1 m (9.5e-7 m, ½ε²/α = 1.8 mJ per segment: the slack the sweep's energy ceiling has for this rope)
            var settings = RopeTestKit.Legacy(segments: 256, youngsModulus: 2e11f, damping: 0.01f);
            var rope = RopeTestKit.Hanging(settings, 1f, out _);
            for (int i = 0; i < 180; i++) rope.Step(RopeTestKit.HostStep);
            double alpha = settings.RestLength / settings.SegmentCount / settings.AxialStiffness, solved = 0.0;
            for (int j = 0; j < rope.SegmentCount; j++) solved += 0.5 * alpha * rope.Tensions[j] * rope.Tensions[j];
            rope.ElasticEnergyBounds(out double lower, out double upper);
            TestContext.WriteLine($"Σ½αT² {solved:G4} J, Σ½C²/α {rope.ElasticEnergy():G4} J, bounds [{lower:G4}, {upper:G4}] J");
            Assert.That(rope.ElasticEnergy(), Is.EqualTo(solved).Within(1).Percent, "the positions resolve the stretch");
            Assert.That(lower, Is.LessThanOrEqualTo(solved));
            Assert.That(upper, Is.GreaterThanOrEqualTo(solved));
            double eps = Rope.RoundOffUlps / 8388608.0 * 1.0;
            Assert.That(upper, Is.LessThan(256 * 0.5 * (eps + 1e-8) * (eps + 1e-8) / alpha * 1.1));
        }
    }
}
