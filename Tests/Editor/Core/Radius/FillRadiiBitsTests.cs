using System;
using HookeRope.Radius;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Radius
{
    /// <summary>
    /// RadiusModel.FillRadiiAt without a neck takes the Poisson interpolation in one loop (the segment's ends once per run
    /// of rings): every ring must be the bits of RadiusAt at the same station.
    /// </summary>
    public sealed class FillRadiiBitsTests
    {
        private const float R = 0.006f;
        private const int Segments = 12;

        [TestCase(0.3f)]
        [TestCase(0.5f)]
        [TestCase(-0.2f)]
        public void WithoutANeckEveryRingIsTheBitsOfRadiusAt(float poisson)
        {
            var settings = new RadiusSettings { PoissonRatio = poisson, Necking = false, Fracture = false };
            var rest = new float[Segments];
            var current = new float[Segments];
            var broken = new bool[Segments];
            for (int j = 0; j < Segments; j++)
            {
                rest[j] = 0.05f + 0.01f * j;
                current[j] = rest[j] * (0.9f + 0.07f * j); // slack, unstretched and stretched segments
            }
            broken[7] = true;
            var model = new RadiusModel(settings, R, rest);
            model.Update(current, broken);
            Assert.That(model.IsNecking, Is.False);

            // runs of rings per segment, a segment revisited, fractions outside [0, 1] (clamped) and either side of ½
            int[] segments = { 0, 0, 0, 1, 2, 2, 7, 7, 7, 7, 3, 3, 11, 11, 11, 2, 7 };
            float[] fractions = { 0f, 0.25f, 0.75f, -0.5f, 0.1f, 1.5f, 0f, 0.5f, 0.50000006f, 1f, 0.3f, 0.9f, 0.2f, 0.6f, 1f, 0.4f, 0.7f };
            var radii = new float[segments.Length];
            model.FillRadiiAt(segments, fractions, radii);

            for (int k = 0; k < segments.Length; k++)
            {
                float expected = model.RadiusAt(segments[k], fractions[k]);
                Assert.That(BitConverter.SingleToInt32Bits(radii[k]), Is.EqualTo(BitConverter.SingleToInt32Bits(expected)),
                    "ring " + k + " (segment " + segments[k] + ", t " + fractions[k] + ")");
            }
            // the profile is not trivial: the stretched end is thinner than the slack start (for ν > 0)
            if (poisson > 0f) Assert.That(radii[14], Is.LessThan(radii[0]));
            // the broken segment's halves keep their ends' radii
            Assert.That(radii[7], Is.EqualTo(model.RadiusAt(7, 0f)));
            Assert.That(radii[8], Is.EqualTo(model.RadiusAt(8, 0f)));
        }

        [Test]
        public void ASegmentOutsideTheRopeThrows()
        {
            var lengths = new float[Segments];
            Array.Fill(lengths, 0.1f);
            var model = new RadiusModel(new RadiusSettings { Necking = false }, R, lengths);
            var radii = new float[2];
            Assert.That(() => model.FillRadiiAt(new[] { 0, Segments }, new[] { 0f, 0f }, radii), Throws.InstanceOf<ArgumentOutOfRangeException>());
        }
    }
}
