using System;
using HookeRope.Radius;
using NUnit.Framework;

namespace HookeRope.Tests.Radius
{
    /// <summary>Issue 15: the radius model's neck follows the elastic–plastic material (onset, waist, break at the ultimate strain).</summary>
    public sealed class MaterialNeckTests
    {
        static RadiusModel Model(RadiusSettings settings, int segments = 10)
        {
            var rest = new float[segments];
            for (int j = 0; j < segments; j++) rest[j] = 0.1f;
            return new RadiusModel(settings, 0.01f, rest);
        }

        static float[] Lengths(int segments, float strain)
        {
            var l = new float[segments];
            for (int j = 0; j < segments; j++) l[j] = 0.1f * (1f + strain);
            return l;
        }

        [Test]
        public void BeforeTheMaterialsOnsetNoNeckFormsWhateverTheRadius()
        {
            var model = Model(new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.99f });
            model.FollowMaterial(true, -1f, 0.6f);
            model.Update(Lengths(10, 0.3f), default);   // the threshold alone: onset at 2 % strain
            Assert.That(model.IsNecking, Is.False);
            Assert.That(model.ShouldBreak, Is.False);
            model.FollowMaterial(false, -1f, 0.6f);
            model.Update(Lengths(10, 0.3f), default);
            Assert.That(model.IsNecking, Is.True, "the elastic-rope rule is back");
        }

        [TestCase(0.25f)]
        [TestCase(0.5f)]
        [TestCase(0.75f)]
        public void ZoneWaistAreaFollowsTheNecksForce(float softening)
        {
            var model = Model(new RadiusSettings { PoissonRatio = 0.3f });
            model.FollowMaterial(true, softening, 0.6f);
            model.Update(Lengths(10, 0.2f), default);
            float poisson = model.SegmentRadii[model.DefectSegment];
            Assert.That(model.NeckDepth, Is.EqualTo(softening));
            Assert.That(model.NeckRadius, Is.EqualTo(poisson * Math.Sqrt(1 - softening)).Within(1e-5).Percent, "ρ² = 1 − s");
        }

        [Test]
        public void BreakIsAtTheUltimateStrainInsteadOfTheBreakStrain()
        {
            var settings = new RadiusSettings { BreakStrain = 0.3f, BreakRadiusFraction = 0f };
            var model = Model(settings);
            model.FollowMaterial(true, 0.2f, 0.6f);
            model.Update(Lengths(10, 0.4f), default);
            Assert.That(model.ShouldBreak, Is.False, "40 % is past BreakStrain but short of the ultimate 60 %");
            var l = Lengths(10, 0.4f);
            l[model.DefectSegment] = 0.1f * 1.61f;
            model.Update(l, default);
            Assert.That(model.BreakReason, Is.EqualTo(BreakReason.Strain));
        }

        [Test]
        public void ThinWaistBreaksWithTheRadiusCriterion()
        {
            var model = Model(new RadiusSettings { PoissonRatio = 0.3f, BreakRadiusFraction = 0.25f });
            model.FollowMaterial(true, 0.97f, 0.6f);
            model.Update(Lengths(10, 0.3f), default);
            Assert.That(model.BreakReason, Is.EqualTo(BreakReason.NeckRadius));
        }
    }
}
