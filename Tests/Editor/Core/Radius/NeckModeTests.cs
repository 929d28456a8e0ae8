using System;
using HookeRope.Geometry;
using HookeRope.Radius;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Radius
{
    public sealed class NeckModeTests
    {
        private const float R = 0.006f;
        private const int Segments = 20;
        private const float SegmentLength = 0.1f;

        private static float[] Uniform(float value)
        {
            var a = new float[Segments];
            Array.Fill(a, value);
            return a;
        }

        [Test]
        public void PaperProfileEndsAtRMinHasAAtTheDefectAndIsSymmetricAndMonotonic()
        {
            var settings = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, NeckMode = NeckMode.Paper, Fracture = false };
            var model = new RadiusModel(settings, R, Uniform(SegmentLength));
            const float stretch = 1.7f; // onset at 1/0.8² = 1.5625
            model.Update(Uniform(SegmentLength * stretch), ReadOnlySpan<bool>.Empty);
            Assert.That(model.IsNecking, Is.True);

            var layout = new RingLayout(Segments, 4);
            var radii = new float[layout.RingCount];
            model.FillRadiiAt(layout.RingSegments, layout.RingFractions, radii);
            int last = radii.Length - 1;
            float rMin = 0.8f * R;
            double length = Segments * SegmentLength * stretch;
            double a = NeckHyperbola.WaistRadius(length, rMin);

            Assert.That(radii[0], Is.EqualTo(rMin).Within(1e-5 * rMin));
            Assert.That(radii[last], Is.EqualTo(rMin).Within(1e-5 * rMin));
            Assert.That(radii[last / 2], Is.EqualTo(a).Within(1e-4 * a));
            Assert.That(model.NeckRadius, Is.EqualTo(a).Within(1e-4 * a));
            Assert.That(model.DefectSegment, Is.EqualTo(Segments / 2));
            for (int k = 0; k <= last; k++)
                Assert.That(radii[k], Is.EqualTo(radii[last - k]).Within(1e-5 * rMin), "ring " + k);
            for (int k = 1; k <= last / 2; k++)
                Assert.That(radii[k], Is.LessThan(radii[k - 1]), "ring " + k);
        }

        [Test]
        public void PaperModeJumpsAtOnsetOverALongRope()
        {
            var settings = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, NeckMode = NeckMode.Paper, Fracture = false };
            var model = new RadiusModel(settings, R, Uniform(SegmentLength));
            model.Update(Uniform(SegmentLength * 1.5624f), ReadOnlySpan<bool>.Empty);
            float before = model.NeckRadius;
            model.Update(Uniform(SegmentLength * 1.5627f), ReadOnlySpan<bool>.Empty);
            float after = model.NeckRadius;
            Assert.That(before, Is.EqualTo(0.8f * R).Within(1e-4 * R));
            Assert.That(after, Is.LessThan(0.01f * R)); // ≈ 2·r_min²/l = 7.4 µm on a 3.1 m rope
            Assert.That(before - after, Is.GreaterThan(0.75f * R));
        }

        [Test]
        public void ZoneModeRadiusChangesAtMostOnePercentOfRPerStepThroughOnset()
        {
            var settings = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, NeckMode = NeckMode.Zone, Fracture = false };
            var rest = Uniform(SegmentLength);
            var model = new RadiusModel(settings, R, rest);
            var layout = RingLayout.Refined(rest, 4, model.DefectRestArc, model.NeckZoneRestLength, 16);
            var radii = new float[layout.RingCount];
            var previous = new float[layout.RingCount];
            var current = new float[Segments];
            Array.Fill(previous, R);
            double largestChange = 0.0;
            float deepest = R;
            for (int step = 1; step <= 500; step++)
            {
                float stretch = 1f + 0.002f * step; // through onset (1.5625) and full depth (1.7625)
                Array.Fill(current, SegmentLength * stretch);
                model.Update(current, ReadOnlySpan<bool>.Empty);
                model.FillRadiiAt(layout.RingSegments, layout.RingFractions, radii);
                for (int k = 0; k < radii.Length; k++)
                {
                    largestChange = Math.Max(largestChange, Math.Abs(radii[k] - previous[k]));
                    previous[k] = radii[k];
                    deepest = Math.Min(deepest, radii[k]);
                }
            }
            Assert.That(largestChange, Is.LessThanOrEqualTo(0.01 * R));
            Assert.That(model.NeckDepth, Is.EqualTo(1f));
            // Full depth: the zone hyperbola (zone = 8 R of rest length, stretched 2×) scaled by the Poisson radius.
            double zone = 8.0 * R * 2.0;
            double rMin = 0.8 * R;
            double poisson = R / Math.Sqrt(2.0);
            double expected = poisson * NeckHyperbola.WaistRadius(zone, rMin) / rMin;
            Assert.That(model.NeckRadius, Is.EqualTo(expected).Within(1e-4 * expected));
            Assert.That(deepest, Is.EqualTo(model.NeckRadius).Within(0.02 * R));
            Assert.That(model.MinRadius, Is.EqualTo(model.NeckRadius).Within(1e-6));
        }

        [Test]
        public void ZoneNeckSitsAtTheDefectPositionAndLeavesTheRestOfTheRopeAlone()
        {
            var settings = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, NeckMode = NeckMode.Zone, DefectPosition = 0.25f, Fracture = false };
            var model = new RadiusModel(settings, R, Uniform(SegmentLength));
            model.Update(Uniform(SegmentLength * 1.9f), ReadOnlySpan<bool>.Empty);
            Assert.That(model.DefectSegment, Is.EqualTo(5));
            // The waist is centred in the segment holding the defect (0.25 → segment 5, waist at its middle).
            Assert.That(model.DefectFraction, Is.EqualTo(0.5f).Within(1e-5));
            Assert.That(model.DefectRestArc, Is.EqualTo(0.55f).Within(1e-6));
            float poisson = (float)(R / Math.Sqrt(1.9));
            Assert.That(model.RadiusAt(5, 0.5f), Is.EqualTo(model.NeckRadius).Within(1e-9));
            Assert.That(model.NeckRadius, Is.LessThan(0.3f * poisson));
            Assert.That(model.RadiusAt(5, 0f), Is.EqualTo(poisson).Within(1e-6 * R)); // 5 cm away, zone half-length 2.4 cm
            Assert.That(model.RadiusAt(6, 0f), Is.EqualTo(poisson).Within(1e-6 * R));
            Assert.That(model.RadiusAt(15, 0.5f), Is.EqualTo(poisson).Within(1e-6 * R));
        }

        [Test]
        public void NeckOffKeepsThePoissonRadiusAtTheDefect()
        {
            var settings = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, Necking = false, Fracture = false };
            var model = new RadiusModel(settings, R, Uniform(SegmentLength));
            model.Update(Uniform(SegmentLength * 2f), ReadOnlySpan<bool>.Empty);
            Assert.That(model.IsNecking, Is.False);
            Assert.That(model.NeckRadius, Is.EqualTo(R / MathF.Sqrt(2f)).Within(1e-6 * R));
        }
    }
}
