using System;
using System.Numerics;
using HookeRope.Geometry;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// The rings' slopes dr/ds on lanes (TubeMeshBuilder.InteriorSlopesOnLanes) against the scalar Slope, bit for bit, on
    /// inputs the drawn tube rarely meets (the cone limit keeps a drawn tube's slopes near 2): steps far steeper than the
    /// ±10 clamp both ways, NaN and infinite radii, distances at and around the 1e-12 m floor, zero and NaN distances.
    /// </summary>
    public sealed class RingSlopeLanesTests
    {
        private static readonly float[] Radii = { 0f, 1e-6f, 0.005f, 0.01f, 1f, 1e3f, float.NaN, float.PositiveInfinity, float.NegativeInfinity };
        private static readonly float[] Distances = { 0f, 1e-13f, 1e-12f, 1.0000001e-12f, 1e-9f, 1e-3f, 1f, float.NaN, float.PositiveInfinity };

        [Test]
        public void LaneSlopesAreTheScalarSlopesAndClampToTenBothWays()
        {
            int lanes = Vector<float>.Count;
            int n = 40 * lanes + 2;
            var r = new float[n];
            var distance = new float[n];
            int below = 0, above = 0, compared = 0;
            // every radius pair and distance among the cases, then random ones, placed so each lane sees each case
            var random = new Random(7);
            for (int round = 0; round < 60; round++)
            {
                for (int i = 0; i < n; i++)
                {
                    int pick = round * n + i;
                    r[i] = round < 30 ? Radii[pick % Radii.Length] : (float)(random.NextDouble() * 0.02);
                    distance[i] = round < 30 ? Distances[(pick / Radii.Length) % Distances.Length] : (float)(random.NextDouble() * 1e-3);
                }
                var slope = new float[n];
                int written = TubeMeshBuilder.InteriorSlopesOnLanes(r, distance, slope);
                Assert.That(written, Is.GreaterThan(lanes), "rings the lanes wrote");
                for (int i = 1; i < written; i++)
                {
                    float expected = TubeMeshBuilder.Slope(r[i + 1], r[i - 1], distance[i]);
                    Assert.That(BitConverter.SingleToInt32Bits(slope[i]), Is.EqualTo(BitConverter.SingleToInt32Bits(expected)),
                        "ring " + i + ": r " + r[i - 1] + " … " + r[i + 1] + ", distance " + distance[i]);
                    if (expected == -10f) below++;
                    if (expected == 10f) above++;
                    compared++;
                }
            }
            // the clamp took part both ways (NaN counts as −10), and the slopes are inside it everywhere
            Assert.That(below, Is.GreaterThan(0), "slopes clamped to −10");
            Assert.That(above, Is.GreaterThan(0), "slopes clamped to +10");
            Assert.That(compared, Is.GreaterThan(1000));
        }

        [TestCase(0.01f, 0f, 1e-3f, -10f)]
        [TestCase(0f, 0.01f, 1e-3f, 10f)]
        [TestCase(0.01f, 0.011f, 1e-3f, 1f)]
        [TestCase(0.011f, 0.01f, 1e-3f, -1f)]
        [TestCase(0.01f, 0.02f, 1e-12f, 0f)]
        [TestCase(float.NaN, 0.01f, 1e-3f, -10f)]
        [TestCase(float.PositiveInfinity, 0f, 1e-3f, -10f)]
        [TestCase(0f, float.PositiveInfinity, 1e-3f, 10f)]
        public void SlopeIsTheQuotientClampedToTen(float behind, float ahead, float distance, float expected)
        {
            Assert.That(TubeMeshBuilder.Slope(ahead, behind, distance), Is.EqualTo(expected).Within(1e-5f));
        }
    }
}
