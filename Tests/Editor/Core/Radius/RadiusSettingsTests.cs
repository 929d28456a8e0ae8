using System;
using HookeRope.Radius;
using HookeRope.Tests.Core.Geometry;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Radius
{
    public sealed class RadiusSettingsTests
    {
        [TestCase(-1.01f)]
        [TestCase(0.51f)]
        [TestCase(float.NaN)]
        [TestCase(float.PositiveInfinity)]
        public void PoissonRatioOutsideRangeThrows(float value)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, BreakStrain = 1000f }.PoissonRatio = value);
            Assert.That(e.ParamName, Is.EqualTo("PoissonRatio"));
            Assert.That(e.Message, Does.Contain("[-1, 0.5]"));
        }

        [TestCase(0f)]
        [TestCase(0.009f)]
        [TestCase(1.001f)]
        [TestCase(float.NaN)]
        public void NeckRadiusFractionOutsideRangeThrows(float value)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new RadiusSettings().NeckRadiusFraction = value);
            Assert.That(e.ParamName, Is.EqualTo("NeckRadiusFraction"));
            Assert.That(e.Message, Does.Contain("[0.01, 1]"));
        }

        [Test]
        public void OtherParametersNameThemselvesAndTheirRange()
        {
            var s = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, BreakStrain = 1000f };
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.DefectPosition = 1.5f).Message, Does.Contain("DefectPosition").And.Contain("(0, 1)"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.NeckZoneDiameters = 0.1f).Message, Does.Contain("NeckZoneDiameters").And.Contain("[0.5, 1000]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.NeckGrowthStrain = 0f).Message, Does.Contain("NeckGrowthStrain").And.Contain("(0, 100]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.BreakRadiusFraction = 1f).Message, Does.Contain("BreakRadiusFraction").And.Contain("[0, 0.99]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.BreakStrain = float.NaN).Message, Does.Contain("BreakStrain").And.Contain("(0, 1000]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.BreakStrain = float.PositiveInfinity).ParamName, Is.EqualTo("BreakStrain"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.NeckMode = (NeckMode)7).ParamName, Is.EqualTo("NeckMode"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new RadiusModel(s, float.NaN, new[] { 1f })).ParamName, Is.EqualTo("restRadius"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new RadiusModel(s, 0.01f, new[] { 1f, 0f })).ParamName, Is.EqualTo("restLengths"));
        }

        [Test]
        public void DefaultsAreTheTableValues()
        {
            // The component's values (RopeParameters); the 0.1 core had ν 0.5, r_min 0.8 R and no strain criterion.
            var s = new RadiusSettings();
            Assert.That(s.PoissonRatio, Is.EqualTo(0.3f));
            Assert.That(s.NeckRadiusFraction, Is.EqualTo(0.75f));
            Assert.That(s.PoissonThinning, Is.True);
            Assert.That(s.Necking, Is.True);
            Assert.That(s.Fracture, Is.True);
            Assert.That(s.NeckMode, Is.EqualTo(NeckMode.Zone));
            Assert.That(s.DefectPosition, Is.EqualTo(0.5f));
            Assert.That(s.NeckZoneDiameters, Is.EqualTo(4f));
            Assert.That(s.NeckGrowthStrain, Is.EqualTo(0.2f));
            Assert.That(s.BreakRadiusFraction, Is.EqualTo(0.25f));
            Assert.That(s.BreakStrain, Is.EqualTo(0.6f));
        }

        [Test]
        public void NeckModeIsPaperOrZoneAndNeckingIsItsOwnSwitch()
        {
            var s = new RadiusSettings { NeckMode = NeckMode.Paper, Necking = false };
            Assert.That(s.NeckMode, Is.EqualTo(NeckMode.Paper), "the mode is kept while necking is off");
            Assert.That(s.Necking, Is.False);
            Assert.That((int)NeckMode.Paper, Is.EqualTo(1), "serialized value");
            Assert.That((int)NeckMode.Zone, Is.EqualTo(2), "serialized value (prefab m_NeckMode: 2)");
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.NeckMode = (NeckMode)0).ParamName, Is.EqualTo("NeckMode"));
        }

        [Test]
        public void EverythingOffDoesNoWork()
        {
            var s = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, PoissonThinning = false, Necking = false, Fracture = false };
            var model = new RadiusModel(s, 0.01f, new[] { 1f, 1f });
            Assert.That(model.IsActive, Is.False);
            // Returns before reading its inputs: even spans of the wrong length are not looked at.
            model.Update(new[] { 3f }, ReadOnlySpan<bool>.Empty);
            Assert.That(model.SegmentRadii[0], Is.EqualTo(0.01f));
            Assert.That(model.MinRadius, Is.EqualTo(0.01f));
        }

        [Test]
        public void UpdateAllocatesNothing()
        {
            var rest = new float[200];
            var current = new float[200];
            Array.Fill(rest, 0.01f);
            Array.Fill(current, 0.016f);
            var model = new RadiusModel(new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, BreakStrain = 1000f }, 0.004f, rest);
            var broken = new bool[200];
            var radii = new float[201];
            var segments = new int[201];
            var fractions = new float[201];
            for (int i = 0; i < 200; i++) segments[i] = i;
            segments[200] = 199;
            fractions[200] = 1f;
            int step = 0;
            long bytes = SteadyStateAllocation.Bytes(() =>
            {
                current[100] = 0.016f + 1e-5f * (step++ % 500);
                model.Update(current, broken);
                model.FillRadiiAt(segments, fractions, radii);
            }, 200);
            Assert.That(bytes, Is.EqualTo(0));
        }
    }
}
