using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    public sealed class CollisionTests
    {
        private const float RopeRadius = 0.01f;

        private static Rope LooseRope(float length, int segments, Float3 start, Float3 end)
        {
            var settings = new RopeSettings { RestLength = length, SegmentCount = segments, Radius = RopeRadius };
            settings.YoungsModulus = 1e9f;
            return new Rope(settings, start, end);
        }

        /// <summary>Deepest particle penetration into collider 0, in metres (≤ 0 = none), and the deepest segment-midpoint one.</summary>
        private static double Deepest(Rope rope, out double midpoint)
        {
            double worst = double.NegativeInfinity;
            midpoint = double.NegativeInfinity;
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                double d = rope.ParticleRadius[i] - rope.ColliderDistance(0, rope.GetPosition(i));
                worst = Math.Max(worst, d);
                if (i + 1 < rope.ParticleCount)
                {
                    Float3 mid = Float3.Lerp(rope.GetPosition(i), rope.GetPosition(i + 1), 0.5f);
                    midpoint = Math.Max(midpoint, rope.ParticleRadius[i] - rope.ColliderDistance(0, mid));
                }
            }
            return worst;
        }

        private static double Settle(Rope rope, int steps)
        {
            double worst = double.NegativeInfinity;
            for (int i = 0; i < steps; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                if (i >= steps / 2) worst = Math.Max(worst, Deepest(rope, out _));
            }
            Assert.That(RopeTestKit.AllFinite(rope), Is.True);
            return worst;
        }

        [Test]
        public void RopeDrapedOverASphereDoesNotPenetrate()
        {
            const float SphereRadius = 0.5f;
            var rope = LooseRope(2f, 64, new Float3(-1f, SphereRadius + RopeRadius + 0.001f, 0f), new Float3(1f, SphereRadius + RopeRadius + 0.001f, 0f));
            rope.AddCollider(ColliderShape.Sphere(Float3.Zero, SphereRadius, 0.5f));
            double worst = Settle(rope, 180);
            Deepest(rope, out double midpoint);
            TestContext.WriteLine($"sphere: deepest particle penetration {worst:E3} m ({worst / RopeRadius * 100:F3} % of r), segment midpoints {midpoint:E3} m");
            Assert.That(worst, Is.LessThan(0.01 * RopeRadius));
            // it really drapes: the ends hang below the sphere's equator
            Assert.That(rope.GetPosition(0).Y, Is.LessThan(0f));
            Assert.That(rope.GetPosition(rope.ParticleCount - 1).Y, Is.LessThan(0f));
        }

        [Test]
        public void RopeOverABoxEdgeDoesNotPenetrateAndFrictionHoldsIt()
        {
            // box top at y = 0, edge at x = 0.5; 1 m of rope on top, 0.5 m over the edge
            var box = ColliderShape.Box(new Float3(0f, -0.5f, 0f), Quat.Identity, new Float3(0.5f, 0.5f, 0.5f), 1f);
            var rope = LooseRope(1.5f, 60, new Float3(-0.5f, RopeRadius + 0.001f, 0f), new Float3(1f, RopeRadius + 0.001f, 0f));
            rope.AddCollider(box);
            double worst = Settle(rope, 180);
            Deepest(rope, out double midpoint);
            TestContext.WriteLine($"box edge: deepest particle penetration {worst:E3} m ({worst / RopeRadius * 100:F3} % of r), segment midpoints {midpoint:E3} m");
            Assert.That(worst, Is.LessThan(0.01 * RopeRadius));
            Assert.That(rope.GetPosition(rope.ParticleCount - 1).Y, Is.LessThan(-0.4f), "the free end hangs over the edge");
            Assert.That(rope.GetPosition(0).X, Is.EqualTo(-0.5f).Within(0.02f), "friction holds the part on top");
        }

        [Test]
        public void RotatedBoxUsesItsRotation()
        {
            // a box rotated 45° about Z presents a corner upwards at height h·√2
            var box = ColliderShape.Box(Float3.Zero, Quat.FromAxisAngle(new Float3(0f, 0f, 1f), MathF.PI / 4f), new Float3(0.5f, 0.5f, 0.5f), 0.8f);
            var rope = LooseRope(1f, 20, new Float3(-0.5f, 1f, 0f), new Float3(0.5f, 1f, 0f));
            rope.AddCollider(box);
            Assert.That(rope.ColliderDistance(0, new Float3(0f, 1f, 0f)), Is.EqualTo(1.0 - 0.5 * Math.Sqrt(2.0)).Within(1e-5));
            double worst = Settle(rope, 120);
            Assert.That(worst, Is.LessThan(0.01 * RopeRadius));
            Assert.That(rope.GetPosition(10).Y, Is.EqualTo(0.5 * Math.Sqrt(2.0) + RopeRadius).Within(0.002), "the middle rests on the corner");
        }

        [Test]
        public void RopeRestsOnAPlaneAtItsRadius()
        {
            var rope = LooseRope(1f, 10, new Float3(0f, 0.5f, 0f), new Float3(1f, 0.5f, 0f));
            rope.AddCollider(ColliderShape.Plane(Float3.Zero, new Float3(0f, 1f, 0f), 0.3f));
            Settle(rope, 90);
            for (int i = 0; i < rope.ParticleCount; i++)
                Assert.That(rope.GetPosition(i).Y, Is.EqualTo(RopeRadius).Within(1e-5));
        }

        [Test]
        public void RopeOverACapsuleHangsOnItsRoundSurface()
        {
            // horizontal capsule along Z (rotation maps Y to Z), radius 0.2
            var capsule = ColliderShape.Capsule(Float3.Zero, Quat.FromAxisAngle(new Float3(1f, 0f, 0f), MathF.PI / 2f), 0.2f, 1f, 0.5f);
            var rope = LooseRope(1f, 40, new Float3(-0.5f, 0.25f, 0f), new Float3(0.5f, 0.25f, 0f));
            rope.AddCollider(capsule);
            double worst = Settle(rope, 120);
            Assert.That(worst, Is.LessThan(0.01 * RopeRadius));
            Assert.That(rope.GetPosition(20).Y, Is.EqualTo(0.2f + RopeRadius).Within(0.001f));
        }

        [Test]
        public void MovingSpherePushesTheRopeAlong()
        {
            // a hanging rope; a sphere sweeps through its lower half in +X and carries it along
            var settings = new RopeSettings { RestLength = 1f, SegmentCount = 20, Radius = RopeRadius };
            var rope = RopeTestKit.Hanging(settings, 0f, out _);
            int sphere = rope.AddCollider(ColliderShape.Sphere(new Float3(-0.3f, -0.8f, 0f), 0.1f));
            for (int i = 0; i < 45; i++)
            {
                rope.SetColliderPose(sphere, new Float3(-0.3f + 0.6f * (i + 1) / 45f, -0.8f, 0f), Quat.Identity);
                rope.Step(RopeTestKit.HostStep);
                Assert.That(Deepest(rope, out _), Is.LessThan(0.01 * RopeRadius));
            }
            Assert.That(rope.GetPosition(16).X, Is.GreaterThan(0.05f), "the rope was pushed to +X");
        }
    }
}
