using System;
using HookeRope.Radius;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Radius
{
    public sealed class BreakDecisionTests
    {
        private const float R = 0.005f;

        [Test]
        public void ElongationPastTheThresholdBreaksAtTheDefectSegment()
        {
            var settings = new RadiusSettings { NeckMode = NeckMode.Off, DefectPosition = 0.33f, BreakElongation = 0.5f, BreakRadiusFraction = 0f };
            var rest = new[] { 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f };
            var model = new RadiusModel(settings, R, rest);
            var current = new float[10];
            Array.Fill(current, 0.149f);
            model.Update(current, ReadOnlySpan<bool>.Empty);
            Assert.That(model.ShouldBreak, Is.False);
            current[3] = 0.1501f;
            model.Update(current, ReadOnlySpan<bool>.Empty);
            Assert.That(model.ShouldBreak, Is.True);
            Assert.That(model.BreakReason, Is.EqualTo(BreakReason.Elongation));
            Assert.That(model.DefectSegment, Is.EqualTo(3));
        }

        [Test]
        public void NeckRadiusBelowTheBreakRadiusBreaks()
        {
            var settings = new RadiusSettings { NeckMode = NeckMode.Zone, BreakRadiusFraction = 0.25f };
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
            var settings = new RadiusSettings { BreakEnabled = false, BreakElongation = 0.1f };
            var model = new RadiusModel(settings, R, new[] { 1f, 1f });
            model.Update(new[] { 5f, 5f }, ReadOnlySpan<bool>.Empty);
            Assert.That(model.ShouldBreak, Is.False);
        }
    }
}
