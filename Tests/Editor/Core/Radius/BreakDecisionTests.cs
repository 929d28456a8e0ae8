using System;
using HookeRope.Radius;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Radius
{
    public sealed class BreakDecisionTests
    {
        private const float R = 0.005f;

        [Test]
        public void StrainPastTheBreakStrainBreaksAtTheDefectSegment()
        {
            var settings = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, Necking = false, DefectPosition = 0.33f, BreakStrain = 0.5f, BreakRadiusFraction = 0f };
            var rest = new[] { 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f };
            var model = new RadiusModel(settings, R, rest);
            var current = new float[10];
            Array.Fill(current, 0.149f);
            model.Update(current, ReadOnlySpan<bool>.Empty);
            Assert.That(model.ShouldBreak, Is.False);
            current[3] = 0.1501f;
            model.Update(current, ReadOnlySpan<bool>.Empty);
            Assert.That(model.ShouldBreak, Is.True);
            Assert.That(model.BreakReason, Is.EqualTo(BreakReason.Strain));
            Assert.That(model.DefectSegment, Is.EqualTo(3));
        }

        [Test]
        public void NeckRadiusBelowTheBreakRadiusBreaks()
        {
            var settings = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, NeckMode = NeckMode.Zone, BreakRadiusFraction = 0.25f, BreakStrain = 1000f };
            var rest = new float[8];
            Array.Fill(rest, 0.05f);
            var model = new RadiusModel(settings, R, rest);
            var current = new float[8];
            float brokeAt = float.NaN;
            for (int step = 0; step <= 600 && float.IsNaN(brokeAt); step++)
            {
                float stretch = 1f + 0.002f * step;
                Array.Fill(current, 0.05f * stretch);
                model.Update(current, ReadOnlySpan<bool>.Empty);
                if (model.ShouldBreak) brokeAt = stretch;
            }
            Assert.That(model.BreakReason, Is.EqualTo(BreakReason.NeckRadius));
            Assert.That(model.NeckRadius, Is.LessThan(0.25f * R));
            Assert.That(model.NeckRadius, Is.GreaterThan(0.23f * R)); // crossed within one small step
            Assert.That(brokeAt, Is.GreaterThan(1.5625f)); // after the neck onset
            Assert.That(model.DefectSegment, Is.EqualTo(4));

            model.MarkBroken();
            float frozen = model.NeckRadius;
            Array.Fill(current, 0.05f);
            model.Update(current, ReadOnlySpan<bool>.Empty);
            Assert.That(model.ShouldBreak, Is.False);
            Assert.That(model.IsBroken, Is.True);
            Assert.That(model.NeckRadius / R, Is.EqualTo(frozen / R * MathF.Sqrt(brokeAt)).Within(1e-4)); // neck kept, Poisson part relaxed
        }

        [Test]
        public void BreakDisabledNeverAsks()
        {
            var settings = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, Fracture = false, BreakStrain = 0.1f };
            var model = new RadiusModel(settings, R, new[] { 1f, 1f });
            model.Update(new[] { 5f, 5f }, ReadOnlySpan<bool>.Empty);
            Assert.That(model.ShouldBreak, Is.False);
        }
    
        [Test]
        public void NeckRadiusCriterionNeedsNecking()
        {
            // The same stretch that breaks a necking rope by its neck radius leaves a rope without necking intact:
            // its radius at the defect is only the Poisson radius, and the strain criterion is off (BreakStrain 1000).
            var rest = new float[8];
            Array.Fill(rest, 0.05f);
            var current = new float[8];
            Array.Fill(current, 0.05f * 2.2f);
            var necking = new RadiusModel(new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, BreakStrain = 1000f, BreakRadiusFraction = 0.9f }, R, rest);
            necking.Update(current, ReadOnlySpan<bool>.Empty);
            Assert.That(necking.BreakReason, Is.EqualTo(BreakReason.NeckRadius));

            var plain = new RadiusModel(new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, Necking = false, BreakStrain = 1000f, BreakRadiusFraction = 0.9f }, R, rest);
            plain.Update(current, ReadOnlySpan<bool>.Empty);
            Assert.That(plain.NeckRadius, Is.LessThan(0.9f * R), "below the break radius, yet no neck");
            Assert.That(plain.ShouldBreak, Is.False);
            Assert.That(plain.BreakReason, Is.EqualTo(BreakReason.None));
        }
    }
}
