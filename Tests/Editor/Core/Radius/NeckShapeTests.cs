using System;
using System.Linq;
using HookeRope.Geometry;
using HookeRope.Radius;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Radius
{
    /// <summary>Issue 17 item 1: the Zone neck joins the rope smoothly, starts at r_min and tells r_min settings apart.</summary>
    public sealed class NeckShapeTests
    {
        private const float R = 0.01f;
        private const int Segments = 20;
        private const float SegmentLength = 0.05f;

        private static float[] Uniform(float value) => Enumerable.Repeat(value, Segments).ToArray();

        private static RadiusModel Stretched(float fraction, float stretch)
        {
            var settings = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = fraction, Fracture = false };
            var model = new RadiusModel(settings, R, Uniform(SegmentLength));
            model.Update(Uniform(SegmentLength * stretch), ReadOnlySpan<bool>.Empty);
            return model;
        }

        /// <summary>Radius (m) at rest arc length <paramref name="s"/> (m) of the uniform test rope.</summary>
        private static double RadiusAtArc(RadiusModel model, double s)
        {
            int j = Math.Min(Segments - 1, (int)Math.Floor(s / SegmentLength));
            return model.RadiusAt(j, (float)((s - j * SegmentLength) / SegmentLength));
        }

        [TestCase(0.8f)]
        [TestCase(0.75f)]
        [TestCase(0.7f)]
        public void ProfileHasNoShoulderAtTheNeckEdges(float fraction)
        {
            const float stretch = 2.3f; // every fraction at full depth (onset of 0.7 R at 2.04×)
            var model = Stretched(fraction, stretch);
            Assert.That(model.IsNecking, Is.True);
            double half = 0.5 * model.NeckZoneRestLength;
            double largestJump = 0.0, largestInside = 0.0;
            foreach (double edge in new[] { model.DefectRestArc - half, model.DefectRestArc + half })
            {
                const double h = 2e-4; // m of rest arc; slopes per metre of the current (stretched) length
                double inside = edge < model.DefectRestArc ? edge + h : edge - h;
                double outside = edge < model.DefectRestArc ? edge - h : edge + h;
                double slopeIn = (RadiusAtArc(model, edge) - RadiusAtArc(model, inside)) / (h * stretch);
                double slopeOut = (RadiusAtArc(model, outside) - RadiusAtArc(model, edge)) / (h * stretch);
                largestJump = Math.Max(largestJump, Math.Abs(Math.Atan(slopeIn) - Math.Atan(slopeOut)) * 180.0 / Math.PI);
            }
            for (int i = 1; i < 200; i++)
            {
                double s = model.DefectRestArc - half + 2.0 * half * i / 200.0;
                double slope = (RadiusAtArc(model, s + 1e-5) - RadiusAtArc(model, s - 1e-5)) / (2e-5 * stretch);
                largestInside = Math.Max(largestInside, Math.Abs(Math.Atan(slope)) * 180.0 / Math.PI);
            }
            TestContext.WriteLine("r_min " + fraction + " R: slope jump at the edges " + largestJump + "°, steepest flank " + largestInside + "°");
            Assert.That(largestJump, Is.LessThan(1.0));
            Assert.That(largestInside, Is.GreaterThan(5.0), "a real neck, not a ripple");
        }

        [TestCase(0.8f)]
        [TestCase(0.75f)]
        [TestCase(0.7f)]
        public void WaistStartsAtRMinAndOnlyNarrowsAfterwards(float fraction)
        {
            var settings = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = fraction, Fracture = false };
            var model = new RadiusModel(settings, R, Uniform(SegmentLength));
            var current = new float[Segments];
            float previous = float.MaxValue, atOnset = float.NaN;
            int rising = 0;
            for (int step = 1; step <= 800; step++)
            {
                Array.Fill(current, SegmentLength * (1f + 0.002f * step));
                model.Update(current, ReadOnlySpan<bool>.Empty);
                if (!model.IsNecking) continue;
                if (float.IsNaN(atOnset)) atOnset = model.NeckRadius;
                else if (model.NeckRadius > previous) rising++;
                previous = model.NeckRadius;
            }
            TestContext.WriteLine("r_min " + fraction + " R: waist at onset " + atOnset / R + " R");
            Assert.That(atOnset, Is.EqualTo(fraction * R).Within(0.01 * R));
            Assert.That(rising, Is.EqualTo(0));
        }

        [Test]
        public void RMinSettingsDifferVisiblyAtTheSameStretch()
        {
            const float stretch = 1.8f;
            double w80 = Stretched(0.8f, stretch).NeckRadius, w75 = Stretched(0.75f, stretch).NeckRadius, w70 = Stretched(0.7f, stretch).NeckRadius;
            TestContext.WriteLine("waist at 1.8×: r_min 0.8 → " + w80 / R + " R, 0.75 → " + w75 / R + " R, 0.7 → " + w70 / R + " R");
            Assert.That(w75 - w80, Is.GreaterThan(0.2 * R));
            Assert.That(w70 - w75, Is.GreaterThan(0.05 * R));
        }

        [Test]
        public void OutsideTheNeckTheRadiusFollowsTheRopesOwnStrain()
        {
            var model = Stretched(0.8f, 2f);
            double poisson = R / Math.Sqrt(2.0);
            Assert.That(model.RadiusAt(0, 0.5f), Is.EqualTo(poisson).Within(1e-6 * R));
            Assert.That(model.RadiusAt(Segments - 1, 0.5f), Is.EqualTo(poisson).Within(1e-6 * R));
        }

        [Test]
        public void ANeckOfZeroLengthIsRejectedNamingTheRange()
        {
            var s = new RadiusSettings();
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => s.NeckZoneDiameters = 0f);
            Assert.That(e.ParamName, Is.EqualTo("NeckZoneDiameters"));
            Assert.That(e.Message, Does.Contain("[0.5, 1000]"));
            Assert.That(s.NeckZoneDiameters, Is.EqualTo(4f));
        }

        [TestCase(8)]
        [TestCase(16)]
        [TestCase(32)]
        public void AdaptedRingsTurnTheReferenceProfileByAtMostTheRadialStep(int radial)
        {
            var rest = Uniform(SegmentLength);
            float zone = 8f * R, centre = 0.525f;
            var layout = RingLayout.Adapted(rest, 4, centre, zone, R, radial);
            double largest = 0.0, previous = 0.0;
            int inZone = 0;
            for (int k = 0; k + 1 < layout.RingCount; k++)
            {
                double s0 = layout.RingSegments[k] * SegmentLength + layout.RingFractions[k] * SegmentLength;
                double s1 = layout.RingSegments[k + 1] * SegmentLength + layout.RingFractions[k + 1] * SegmentLength;
                double r0 = R * NeckProfile.Ratio((float)((s0 - centre) / zone), RingLayout.ReferenceWaistRatio * RingLayout.ReferenceWaistRatio);
                double r1 = R * NeckProfile.Ratio((float)((s1 - centre) / zone), RingLayout.ReferenceWaistRatio * RingLayout.ReferenceWaistRatio);
                double angle = Math.Atan((r1 - r0) / (s1 - s0));
                if (k > 0) largest = Math.Max(largest, Math.Abs(angle - previous));
                previous = angle;
                if (Math.Abs(s0 - centre) < 0.5 * zone) inZone++;
            }
            TestContext.WriteLine(radial + " radial: " + inZone + " rings in the neck, largest turn " + largest + " rad (π/radial " + Math.PI / radial + ")");
            Assert.That(largest, Is.LessThan(1.5 * Math.PI / radial));
            Assert.That(inZone, Is.GreaterThanOrEqualTo(RingLayout.BaseRingsInZone));
        }
    }
}
