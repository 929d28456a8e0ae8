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
            var settings = RopeTestKit.Legacy(length: length, segments: segments, radius: RopeRadius);
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
            var settings = RopeTestKit.Legacy(length: 1f, segments: 20, radius: RopeRadius);
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

        /// <summary>
        /// A cord pulled over a frictionless bar (capsule along Z, radius 0.1 m) by two pins, no gravity: the rope takes
        /// the tangent–arc–tangent path around R = R_bar + r, and its tension must be E·A·(path/L − 1) all along it and at
        /// both anchors. Returns (mean tension, largest relative tension deviation, anchor forces) after settling.
        /// </summary>
        private static void PullOverBar(int substeps, int iterations, out double expected, out double path, out Rope rope, out int left, out int right)
        {
            const float BarRadius = 0.1f, CordRadius = 0.005f, Length = 1.2f;
            var settings = RopeTestKit.Legacy(length: Length, segments: 80, radius: CordRadius, substeps: substeps, iterations: iterations);
            settings.AxialStiffness = 200f;
            settings.LinearDensity = 0.05f;
            settings.Gravity = Float3.Zero;
            Float3 a0 = new Float3(-0.5f, 0.2f, 0f), b0 = new Float3(0.5f, 0.2f, 0f);
            rope = new Rope(settings, a0, b0);
            left = rope.AddPin(0, a0);
            right = rope.AddPin(rope.ParticleCount - 1, b0);
            rope.AddCollider(ColliderShape.Capsule(Float3.Zero, Quat.FromAxisAngle(new Float3(1f, 0f, 0f), MathF.PI / 2f), BarRadius, 0.5f));
            const float Drop = 0.6f;
            for (int k = 1; k <= 180; k++)
            {
                float f = Math.Min(k / 90f, 1f); // ends pulled down 0.6 m in 1 s, then held for 1 s
                rope.SetPinTarget(left, new Float3(-0.5f, 0.2f - Drop * f, 0f));
                rope.SetPinTarget(right, new Float3(0.5f, 0.2f - Drop * f, 0f));
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
            var settings = RopeTestKit.Legacy(length: 1f, segments: 16, radius: RopeRadius, damping: 0.01f);
            var rope = new Rope(settings, new Float3(-0.5f, RopeRadius, 0f), new Float3(0.5f, RopeRadius, 0f));
            rope.AddCollider(ColliderShape.Plane(Float3.Zero, new Float3(0f, 1f, 0f)));
            rope.AddCollider(ColliderShape.Sphere(new Float3(0f, 0f, 10f), 1f));
            for (int k = 0; k < 90; k++) rope.Step(RopeTestKit.HostStep);
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
