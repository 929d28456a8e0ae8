using System;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// <see cref="ViewDetail"/> (issue 18): beyond the detail distance D the ring tolerance grows as d / D up to 16, so the
    /// along-rope error seen from the viewer, an angle, is never more than at D; the distance is to the box around the
    /// particles, never more than to the nearest one; bad input is named with its range.
    /// </summary>
    public sealed class ViewDetailTests
    {
        private const float R = 0.01f;

        [TestCase(1f, 0f, 50f, 1f, TestName = "off at a detail distance of 0")]
        [TestCase(1f, 2f, 1.5f, 1f, TestName = "inside the detail distance: the ring tolerance")]
        [TestCase(1f, 2f, 2f, 1f, TestName = "at the detail distance: the ring tolerance")]
        [TestCase(1f, 2f, 6f, 3f, TestName = "three times as far: three times the tolerance")]
        [TestCase(2f, 2f, 6f, 6f, TestName = "the ring tolerance is scaled, not replaced")]
        [TestCase(1f, 2f, 100f, 16f, TestName = "capped at the ring tolerance's upper bound")]
        [TestCase(1f, 2f, float.PositiveInfinity, 16f, TestName = "an infinite distance: the cap")]
        [TestCase(1f, 2f, float.NaN, 1f, TestName = "a distance that is not a number: full detail")]
        public void TheToleranceGrowsWithTheDistanceBeyondTheDetailDistance(float tolerance, float detail, float distance, float expected)
        {
            Assert.That(ViewDetail.RingTolerance(tolerance, detail, distance), Is.EqualTo(expected).Within(1e-6f));
        }

        [TestCase(16, 0f, 100f, 16, 16, TestName = "sides: off at a detail distance of 0")]
        [TestCase(16, 2f, 8.7f, 16, 16, TestName = "sides: all of them short of 4.4 D")]
        [TestCase(16, 2f, 8.8f, 16, 8, TestName = "sides: half from 4.4 D on")]
        [TestCase(16, 2f, 8.2f, 8, 8, TestName = "sides: half kept down to 4 D")]
        [TestCase(16, 2f, 7.9f, 8, 16, TestName = "sides: all again within 4 D")]
        [TestCase(12, 2f, 100f, 12, 6, TestName = "sides: 12 -> 6")]
        [TestCase(5, 2f, 100f, 5, 3, TestName = "sides: half rounded up, 5 -> 3")]
        [TestCase(4, 2f, 100f, 4, 3, TestName = "sides: never fewer than 3")]
        [TestCase(3, 2f, 100f, 3, 3, TestName = "sides: 3 stays 3")]
        [TestCase(16, 2f, float.NaN, 8, 16, TestName = "sides: a distance that is not a number, all of them")]
        public void FarRopesDrawHalfTheirSides(int sides, float detail, float distance, int before, int expected)
        {
            Assert.That(ViewDetail.RadialSegments(sides, detail, distance, before), Is.EqualTo(expected));
        }

        [Test]
        public void WithHalfTheSidesTheToleranceIsScaledByTheDeeperPolygon()
        {
            // at 8 D with 8 of 16 sides: the 8-gon is (1 − cos π/8) / (1 − cos π/16) = 3.96 times as deep
            double deeper = (1 - Math.Cos(Math.PI / 8)) / (1 - Math.Cos(Math.PI / 16));
            Assert.That(ViewDetail.RingTolerance(1f, 2f, 16f, 16, 8), Is.EqualTo(8 / deeper).Within(1e-5));
            Assert.That(ViewDetail.RingTolerance(1f, 2f, 16f, 16, 16), Is.EqualTo(ViewDetail.RingTolerance(1f, 2f, 16f)), "the same sides: the plain rule");
            Assert.That(ViewDetail.RingTolerance(1f, 2f, 3f, 16, 8), Is.EqualTo(1f), "never below 1");
            Assert.That(() => ViewDetail.RingTolerance(1f, 2f, 16f, 16, 2), Throws.TypeOf<ArgumentOutOfRangeException>().With.Message.Contain("RadialSegments"));
        }

        [Test]
        public void ChooseGivesTheSidesAndTheirToleranceOrKeepsTheSides()
        {
            ViewDetail.Choose(16, 1f, 2f, 100f, 16, false, out int sides, out float tolerance);
            Assert.That(sides, Is.EqualTo(8));
            Assert.That(tolerance, Is.EqualTo(ViewDetail.RingTolerance(1f, 2f, 100f, 16, 8)));
            ViewDetail.Choose(16, 1f, 2f, 100f, 16, true, out sides, out tolerance);
            Assert.That(sides, Is.EqualTo(16), "kept (a broken rope)");
            Assert.That(tolerance, Is.EqualTo(ViewDetail.RingTolerance(1f, 2f, 100f)));
            ViewDetail.Choose(16, 2f, 0f, 100f, 8, false, out sides, out tolerance);
            Assert.That(sides, Is.EqualTo(16), "off");
            Assert.That(tolerance, Is.EqualTo(2f));
            ViewDetail.Choose(16, 2f, 2f, float.NaN, 8, false, out sides, out tolerance);
            Assert.That(sides, Is.EqualTo(16), "no viewer (NaN)");
            Assert.That(tolerance, Is.EqualTo(2f));
        }

        [Test]
        public void BadInputIsNamedWithItsRange()
        {
            Assert.That(() => ViewDetail.RingTolerance(0.5f, 2f, 3f), Throws.TypeOf<ArgumentOutOfRangeException>()
                .With.Message.Contain("RingTolerance").And.Message.Contain("[1, 16]"));
            Assert.That(() => ViewDetail.RingTolerance(1f, -1f, 3f), Throws.TypeOf<ArgumentOutOfRangeException>()
                .With.Message.Contain("DetailDistance"));
            Assert.That(() => ViewDetail.RingTolerance(1f, float.NaN, 3f), Throws.TypeOf<ArgumentOutOfRangeException>()
                .With.Message.Contain("DetailDistance"));
            var x = new float[2];
            Assert.That(() => ViewDetail.DistanceToBox(x, x, x, 3, default), Throws.TypeOf<ArgumentOutOfRangeException>()
                .With.Message.Contain("count"));
        }

        [Test]
        public void TheDistanceIsToTheBoxAroundThePositions()
        {
            // a box from (0, 0, 0) to (2, 1, 1)
            float[] x = { 0f, 2f, 1f }, y = { 0f, 1f, 0.5f }, z = { 1f, 0f, 0.2f };
            Assert.That(ViewDetail.DistanceToBox(x, y, z, 3, new Float3(1f, 0.5f, 0.5f)), Is.EqualTo(0f), "inside");
            Assert.That(ViewDetail.DistanceToBox(x, y, z, 3, new Float3(4f, 0.5f, 0.5f)), Is.EqualTo(2f).Within(1e-6f), "off one face");
            Assert.That(ViewDetail.DistanceToBox(x, y, z, 3, new Float3(3f, 3f, 3f)), Is.EqualTo(3f).Within(1e-6f), "off a corner: sqrt(1 + 4 + 4)");
            Assert.That(ViewDetail.DistanceToBox(x, y, z, 2, new Float3(-1f, 0f, 0f)), Is.EqualTo(1f).Within(1e-6f), "the first count positions only");
            Assert.That(ViewDetail.DistanceToBox(x, y, z, 0, default), Is.EqualTo(float.PositiveInfinity), "no positions");
            z[2] = float.NaN;
            Assert.That(ViewDetail.DistanceToBox(x, y, z, 3, default), Is.NaN, "a position that is not finite");
            Assert.That(ViewDetail.RingTolerance(1f, 2f, ViewDetail.DistanceToBox(x, y, z, 3, default)), Is.EqualTo(1f), "which draws at full detail");
        }

        [Test]
        public void TheDistanceIsNeverMoreThanToTheNearestPosition()
        {
            var random = new Random(18);
            var x = new float[65];
            var y = new float[65];
            var z = new float[65];
            for (int trial = 0; trial < 200; trial++)
            {
                for (int i = 0; i < x.Length; i++)
                {
                    x[i] = (float)(random.NextDouble() * 4 - 2);
                    y[i] = (float)(random.NextDouble() * 4 - 2);
                    z[i] = (float)(random.NextDouble() * 4 - 2);
                }
                var point = new Float3((float)(random.NextDouble() * 40 - 20), (float)(random.NextDouble() * 40 - 20), (float)(random.NextDouble() * 40 - 20));
                double nearest = double.PositiveInfinity;
                for (int i = 0; i < x.Length; i++)
                {
                    double dx = x[i] - point.X, dy = y[i] - point.Y, dz = z[i] - point.Z;
                    nearest = Math.Min(nearest, Math.Sqrt(dx * dx + dy * dy + dz * dz));
                }
                Assert.That(ViewDetail.DistanceToBox(x, y, z, x.Length, point), Is.LessThanOrEqualTo(nearest * (1 + 1e-6)));
            }
        }

        /// <summary>
        /// On four bent shapes at 16 sides, seen from D … 64 D with the side count and tolerance <see cref="ViewDetail"/>
        /// gives (8 sides from 4.4 D): the measured surface error over the view distance (the angle it spans) is at most the
        /// full-detail bound over D, and the vertex count falls with the distance.
        /// </summary>
        [TestCase("lanyard")]
        [TestCase("helix")]
        [TestCase("u-turn")]
        [TestCase("wave")]
        public void TheErrorSeenFromTheViewerIsNeverMoreThanAtTheDetailDistance(string name)
        {
            const int radial = 16;
            const float detail = 2f;
            RopeShape shape = AdaptiveRingsTests.Shape(name);
            int n = shape.Segments;
            double polygon = R * (1.0 - Math.Cos(Math.PI / radial));
            double nearBound = polygon + RingNeed.Tolerance(radial) * R;
            int drawn = int.MaxValue, full = 0, sides = radial;
            float before = 0f;
            // 8.8 m enters half the sides; 8 m, nearer again, keeps them (the band's worst case: 8 sides at 4 D)
            foreach (float distance in new[] { 2f, 4f, 8f, 8.8f, 8f, 16f, 32f, 128f })
            {
                sides = ViewDetail.RadialSegments(radial, detail, distance, sides);
                float tolerance = ViewDetail.RingTolerance(1f, detail, distance, radial, sides);
                var builder = TubeMeshBuilder.Adaptive(new TubeMeshSettings { RadialSegments = sides, RingTolerance = tolerance }, n, R, null, AdaptiveRings.MaxRingsPerSegment);
                var update = AdaptiveRingsTests.BuildAdaptive(builder, shape, R, new bool[n], out var vertices, out _);
                double deviation = TubeDeviation.Largest(shape, R, builder.Layout, sides, vertices, out _, out _);
                int count = update.VertexCount;
                if (distance == detail) full = count;
                TestContext.WriteLine($"{name} at {distance} m: {sides} sides, tolerance {tolerance:F3}, {builder.Layout.RingCount} rings, {count} vertices, " +
                                      $"deviation {deviation / R:F4} R, seen {deviation / distance * 1e6:F1} µrad (at D: at most {nearBound / detail * 1e6:F1})");
                Assert.That(deviation / distance, Is.LessThanOrEqualTo(nearBound / detail * 1.0001 + 1e-9), "the angle seen is at most the one at D");
                if (distance >= before) Assert.That(count, Is.LessThanOrEqualTo(drawn), "no more vertices farther away");
                if (distance == 8f && before > distance) Assert.That(sides, Is.EqualTo(8), "in the band: still 8 sides");
                drawn = count;
                before = distance;
            }
            Assert.That(sides, Is.EqualTo(8), "half the sides far away");
            Assert.That(drawn, Is.LessThan(full * 0.6), "far away fewer than 60 % of the vertices at D");
        }
    }
}
