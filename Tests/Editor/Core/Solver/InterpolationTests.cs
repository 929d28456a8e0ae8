using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>The step-start snapshot behind <see cref="Rope.Interpolate"/>, and the broken-segment read-outs.</summary>
    public sealed class InterpolationTests
    {
        private static Rope SwingingRope()
        {
            var settings = RopeTestKit.Legacy(length: 1f, segments: 8);
            var start = new Float3(100f, 50f, -20f);
            var rope = new Rope(settings, start, start + new Float3(1f, 0f, 0f));
            rope.AddPin(0, start);
            return rope;
        }

        [Test]
        public void AlphaZeroAndOneGiveTheStartAndTheEndOfTheLastStep()
        {
            var rope = SwingingRope();
            int n = rope.ParticleCount;
            for (int k = 0; k < 5; k++) rope.Step(RopeTestKit.HostStep);
            float[] sx = rope.PositionX.ToArray(), sy = rope.PositionY.ToArray(), sz = rope.PositionZ.ToArray();
            rope.Step(RopeTestKit.HostStep);
            float[] x = new float[n], y = new float[n], z = new float[n];

            rope.Interpolate(0f, x, y, z);
            Assert.That(x, Is.EqualTo(sx));
            Assert.That(y, Is.EqualTo(sy));
            Assert.That(z, Is.EqualTo(sz));

            rope.Interpolate(1f, x, y, z);
            Assert.That(x, Is.EqualTo(rope.PositionX.ToArray()));
            Assert.That(y, Is.EqualTo(rope.PositionY.ToArray()));
            Assert.That(z, Is.EqualTo(rope.PositionZ.ToArray()));

            rope.Interpolate(7f, x, y, z);
            Assert.That(y, Is.EqualTo(rope.PositionY.ToArray()), "alpha is clamped to 1");

            int last = n - 1;
            Float3 mid = rope.GetInterpolatedPosition(last, 0.5f);
            Float3 expected = rope.Origin + new Float3(sx[last] + (rope.PositionX[last] - sx[last]) * 0.5f,
                sy[last] + (rope.PositionY[last] - sy[last]) * 0.5f, sz[last] + (rope.PositionZ[last] - sz[last]) * 0.5f);
            Assert.That(mid.X, Is.EqualTo(expected.X));
            Assert.That(mid.Y, Is.EqualTo(expected.Y));
            Assert.That(mid.Z, Is.EqualTo(expected.Z));
            Assert.That(rope.GetInterpolatedPosition(last, -3f).Y, Is.EqualTo(rope.Origin.Y + sy[last]), "alpha is clamped to 0");
        }

        [Test]
        public void SetPositionMovesBothEndsOfTheInterpolation()
        {
            var rope = SwingingRope();
            for (int k = 0; k < 3; k++) rope.Step(RopeTestKit.HostStep);
            var target = new Float3(101f, 48f, -19f);
            int last = rope.ParticleCount - 1;
            rope.SetPosition(last, target);
            Assert.That(rope.GetInterpolatedPosition(last, 0f), Is.EqualTo(rope.GetPosition(last)));
            Assert.That(rope.GetInterpolatedPosition(last, 1f), Is.EqualTo(rope.GetPosition(last)));
            Assert.That((rope.GetInterpolatedPosition(last, 0.3f) - target).Length, Is.LessThan(1e-4f));
        }

        [Test]
        public void BeforeTheFirstStepTheInterpolationIsTheBuiltRope()
        {
            var rope = SwingingRope();
            for (int i = 0; i < rope.ParticleCount; i++)
                Assert.That(rope.GetInterpolatedPosition(i, 0f), Is.EqualTo(rope.GetPosition(i)));
            Assert.Throws<ArgumentException>(() => rope.Interpolate(0.5f, new float[2], new float[9], new float[9]));
            Assert.Throws<ArgumentOutOfRangeException>(() => rope.GetInterpolatedPosition(rope.ParticleCount, 0.5f));
        }

        [Test]
        public void BrokenSegmentsReflectBreakSegment()
        {
            var rope = SwingingRope();
            Assert.That(rope.BrokenSegmentCount, Is.EqualTo(0));
            Assert.That(rope.BrokenSegments.Length, Is.EqualTo(rope.SegmentCount));
            rope.BreakSegment(3);
            rope.BreakSegment(3);
            rope.BreakSegment(6);
            Assert.That(rope.BrokenSegmentCount, Is.EqualTo(2), "breaking a broken segment again counts once");
            for (int j = 0; j < rope.SegmentCount; j++)
                Assert.That(rope.BrokenSegments[j], Is.EqualTo(j == 3 || j == 6), "segment " + j);
        }

        [Test]
        public void InterpolationAllocatesNothing()
        {
            var rope = SwingingRope();
            rope.Step(RopeTestKit.HostStep);
            int n = rope.ParticleCount;
            float[] x = new float[n], y = new float[n], z = new float[n];
            rope.Interpolate(0.5f, x, y, z);
            long fewest = long.MaxValue;
            for (int round = 0; round < 3; round++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                rope.Interpolate(0.25f, x, y, z);
                rope.GetInterpolatedPosition(n - 1, 0.75f);
                fewest = Math.Min(fewest, GC.GetAllocatedBytesForCurrentThread() - before);
            }
            Assert.That(fewest, Is.EqualTo(0L));
        }
    }
}
