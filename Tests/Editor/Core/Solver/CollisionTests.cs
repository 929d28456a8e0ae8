using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    public sealed class CollisionTests
    {
        private const float RopeRadius = CollisionScenes.RopeRadius;

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
            var rope = CollisionScenes.SphereDrape();
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
            var rope = CollisionScenes.BoxEdge();
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
            var rope = CollisionScenes.RotatedBox();
            Assert.That(rope.ColliderDistance(0, new Float3(0f, 1f, 0f)), Is.EqualTo(1.0 - 0.5 * Math.Sqrt(2.0)).Within(1e-5));
            double worst = Settle(rope, 120);
            Assert.That(worst, Is.LessThan(0.01 * RopeRadius));
            Assert.That(rope.GetPosition(10).Y, Is.EqualTo(0.5 * Math.Sqrt(2.0) + RopeRadius).Within(0.002), "the middle rests on the corner");
        }

        [Test]
        public void RopeRestsOnAPlaneAtItsRadius()
        {
            var rope = CollisionScenes.PlaneRest();
            Settle(rope, 90);
            for (int i = 0; i < rope.ParticleCount; i++)
                Assert.That(rope.GetPosition(i).Y, Is.EqualTo(RopeRadius).Within(1e-5));
        }

        [Test]
        public void RopeOverACapsuleHangsOnItsRoundSurface()
        {
            var rope = CollisionScenes.CapsuleHang();
            double worst = Settle(rope, 120);
            Assert.That(worst, Is.LessThan(0.01 * RopeRadius));
            Assert.That(rope.GetPosition(20).Y, Is.EqualTo(0.2f + RopeRadius).Within(0.001f));
        }

        [Test]
        public void MovingSpherePushesTheRopeAlong()
        {
            // a hanging rope; a sphere sweeps through its lower half in +X and carries it along
            var rope = CollisionScenes.MovingSphere();
            for (int i = 0; i < CollisionScenes.MovingSphereSteps; i++)
            {
                CollisionScenes.MoveSphere(rope, i);
                rope.Step(RopeTestKit.HostStep);
                Assert.That(Deepest(rope, out _), Is.LessThan(0.01 * RopeRadius));
            }
            Assert.That(rope.GetPosition(16).X, Is.GreaterThan(0.05f), "the rope was pushed to +X");
        }

        /// <summary>
        /// A cord pulled over a frictionless bar (capsule along Z, radius 0.1 m) by two pins, no gravity: the rope takes
        /// the tangent–arc–tangent path around R = R_bar + r, and its tension must be E·A·(path/L − 1) all along it and at
        /// both anchors. Returns (mean tension, largest relative tension deviation, anchor forces) after settling.
        /// </summary>
        private static void PullOverBar(int substeps, int iterations, out double expected, out double path, out Rope rope, out int left, out int right)
        {
            const float BarRadius = CollisionScenes.BarRadius, CordRadius = CollisionScenes.CordRadius, Length = CollisionScenes.CordLength;
            rope = CollisionScenes.BarPull(substeps, iterations);
            left = 0;
            right = 1;
            for (int k = 0; k < CollisionScenes.BarPullSteps; k++)
            {
                CollisionScenes.PullDown(rope, k);
                rope.Step(RopeTestKit.HostStep);
            }
            // tangent + arc + tangent from A = (−0.5, −0.4) to B = (0.5, −0.4) around the bar's centre
            double radius = BarRadius + CordRadius;
            double d = Math.Sqrt(0.5 * 0.5 + 0.4 * 0.4);
            double tangent = Math.Sqrt(d * d - radius * radius);
            double toAnchor = Math.Atan2(0.4, 0.5);                 // anchors below the horizontal through the centre
            double touch = Math.Acos(radius / d);                   // angle between the anchor ray and the tangent point
            double arc = Math.PI - 2.0 * (touch - toAnchor);        // wrapped angle θ
            path = 2.0 * tangent + radius * arc;
            expected = 200.0 * (path / Length - 1.0);
        }

        [TestCase(16, 1)]
        [TestCase(8, 2)]
        public void TensionOverAFrictionlessBarIsEATimesTheWrappedStrain(int substeps, int iterations)
        {
            PullOverBar(substeps, iterations, out double expected, out double path, out Rope rope, out int left, out int right);
            double length = 0.0, low = double.PositiveInfinity, high = 0.0, mean = 0.0;
            for (int j = 0; j < rope.SegmentCount; j++)
            {
                length += rope.SegmentLengths[j];
                low = Math.Min(low, rope.Tensions[j]);
                high = Math.Max(high, rope.Tensions[j]);
                mean += rope.Tensions[j] / rope.SegmentCount;
            }
            double mid = rope.Tensions[rope.SegmentCount / 2];
            double anchorLeft = rope.GetPinForce(left).Length, anchorRight = rope.GetPinForce(right).Length;
            double deepest = Deepest(rope, out _);
            TestContext.WriteLine($"{substeps}x{iterations}: path {path:F5} m, rope {length:F5} m; E·A·strain {expected:F3} N; tension mean {mean:F3}, mid {mid:F3}, range {low:F3}–{high:F3} N; anchors {anchorLeft:F3} / {anchorRight:F3} N; deepest {deepest:E2} m");
            Assert.That(RopeTestKit.AllFinite(rope), Is.True);
            Assert.That(length, Is.EqualTo(path).Within(0.5).Percent, "the cord follows tangent + arc + tangent");
            Assert.That(mid, Is.EqualTo(expected).Within(2).Percent, "tension over the bar");
            Assert.That(low, Is.EqualTo(expected).Within(2).Percent, "lowest segment tension");
            Assert.That(high, Is.EqualTo(expected).Within(2).Percent, "highest segment tension");
            Assert.That(anchorLeft, Is.EqualTo(expected).Within(2).Percent, "left anchor force");
            Assert.That(anchorRight, Is.EqualTo(expected).Within(2).Percent, "right anchor force");
            Assert.That(deepest, Is.LessThan(0.01 * 0.005), "no particle deeper than 1 % of the cord radius");
        }

        /// <summary>A free rope resting on a floor plane (y = 0) for 1 s, with a sphere far away as a second collider.</summary>
        private static Rope RopeOnTheFloor(out float restingY)
        {
            var rope = CollisionScenes.FloorWithFarSphere();
            for (int k = 0; k < CollisionScenes.FloorSteps; k++) rope.Step(RopeTestKit.HostStep);
            restingY = CentreY(rope);
            return rope;
        }

        private static float CentreY(Rope rope)
        {
            double sum = 0.0, mass = 0.0;
            for (int i = 0; i < rope.ParticleCount; i++) { sum += rope.GetParticleMass(i) * rope.GetPosition(i).Y; mass += rope.GetParticleMass(i); }
            return (float)(sum / mass);
        }

        [Test]
        public void RemovingTheFloorLetsTheRopeFallFreelyAndShiftsLaterColliders()
        {
            var rope = RopeOnTheFloor(out float restingY);
            Assert.That(restingY, Is.EqualTo(RopeRadius).Within(1e-4), "it rests on the floor");
            rope.RemoveCollider(0);
            Assert.That(rope.ColliderCount, Is.EqualTo(1));
            // the sphere moved down to index 0: 9 m from the origin to its surface
            Assert.That(rope.ColliderDistance(0, Float3.Zero), Is.EqualTo(9f).Within(1e-4));
            Assert.Throws<ArgumentOutOfRangeException>(() => rope.RemoveCollider(1));
            for (int k = 0; k < 45; k++) rope.Step(RopeTestKit.HostStep);
            // from rest, the centre of mass falls ½·g·t² (t = 0.5 s; the exact drop of the discrete integrator is
            // ½·g·Δt·h·n(n+1) over n substeps of h, within 0.1 % of it at 720 substeps)
            double t = 45 * RopeTestKit.HostStep;
            Assert.That(restingY - CentreY(rope), Is.EqualTo(0.5 * RopeTestKit.G * t * t).Within(0.5).Percent);
        }

        [Test]
        public void ClearingTheCollidersAllocatesNothingAndStopsTheCollisionWork()
        {
            var rope = RopeOnTheFloor(out float restingY);
            long before = GC.GetAllocatedBytesForCurrentThread();
            rope.ClearColliders();
            long clearing = GC.GetAllocatedBytesForCurrentThread() - before;
            // three windows of 15 steps: a per-step allocation shows in every one, a one-off runtime
            // allocation (tiered JIT) in at most one
            long stepping = long.MaxValue;
            for (int window = 0; window < 3; window++)
            {
                before = GC.GetAllocatedBytesForCurrentThread();
                for (int k = 0; k < 15; k++) rope.Step(RopeTestKit.HostStep);
                stepping = Math.Min(stepping, GC.GetAllocatedBytesForCurrentThread() - before);
            }
            Assert.That(clearing, Is.EqualTo(0), "ClearColliders");
            Assert.That(stepping, Is.EqualTo(0), "steps after clearing");
            Assert.That(rope.ColliderCount, Is.EqualTo(0));
            double t = 45 * RopeTestKit.HostStep;
            Assert.That(restingY - CentreY(rope), Is.EqualTo(0.5 * RopeTestKit.G * t * t).Within(0.5).Percent);
            // colliders can be added again afterwards
            Assert.That(rope.AddCollider(ColliderShape.Plane(new Float3(0f, -10f, 0f), new Float3(0f, 1f, 0f))), Is.EqualTo(0));
        }
    }
}
