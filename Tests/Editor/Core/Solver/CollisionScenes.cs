using System;
using System.Collections.Generic;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// The collision tests' scenes, built in one place: <see cref="CollisionTests"/> checks their physics and
    /// <see cref="BroadPhaseTests"/> steps each with the broad phase and with the brute-force pass, bit for bit.
    /// </summary>
    internal static class CollisionScenes
    {
        public const float RopeRadius = 0.01f;

        /// <summary>A scene: its rope, what happens before each step k (collider and pin motion), and how many steps it runs.</summary>
        public sealed class Scene
        {
            public string Name;
            public Func<Rope> Build;
            public Action<Rope, int> BeforeStep = (rope, k) => { };
            public int Steps;

            public override string ToString() => Name;
        }

        /// <summary>Every scene of <see cref="CollisionTests"/>, as it runs there.</summary>
        public static IEnumerable<Scene> All()
        {
            yield return new Scene { Name = "sphere drape", Build = SphereDrape, Steps = 180 };
            yield return new Scene { Name = "box edge", Build = BoxEdge, Steps = 180 };
            yield return new Scene { Name = "rotated box", Build = RotatedBox, Steps = 120 };
            yield return new Scene { Name = "plane rest", Build = PlaneRest, Steps = 90 };
            yield return new Scene { Name = "capsule", Build = CapsuleHang, Steps = 120 };
            yield return new Scene { Name = "moving sphere", Build = MovingSphere, BeforeStep = MoveSphere, Steps = MovingSphereSteps };
            yield return new Scene { Name = "bar pull 16x1", Build = () => BarPull(16, 1), BeforeStep = PullDown, Steps = BarPullSteps };
            yield return new Scene { Name = "bar pull 8x2", Build = () => BarPull(8, 2), BeforeStep = PullDown, Steps = BarPullSteps };
            yield return new Scene { Name = "floor removed", Build = FloorWithFarSphere, BeforeStep = (rope, k) => { if (k == FloorSteps) rope.RemoveCollider(0); }, Steps = FloorSteps + 45 };
        }

        public static Rope LooseRope(float length, int segments, Float3 start, Float3 end)
        {
            var settings = RopeTestKit.Legacy(length: length, segments: segments, radius: RopeRadius);
            settings.YoungsModulus = 1e9f;
            return new Rope(settings, start, end);
        }

        public const float SphereRadius = 0.5f;

        /// <summary>A rope laid over the top of a sphere (radius 0.5 m, μ 0.5) at the origin.</summary>
        public static Rope SphereDrape()
        {
            var rope = LooseRope(2f, 64, new Float3(-1f, SphereRadius + RopeRadius + 0.001f, 0f), new Float3(1f, SphereRadius + RopeRadius + 0.001f, 0f));
            rope.AddCollider(ColliderShape.Sphere(Float3.Zero, SphereRadius, 0.5f));
            return rope;
        }

        /// <summary>Box top at y = 0, edge at x = 0.5 (μ 1); 1 m of rope on top, 0.5 m over the edge.</summary>
        public static Rope BoxEdge()
        {
            var rope = LooseRope(1.5f, 60, new Float3(-0.5f, RopeRadius + 0.001f, 0f), new Float3(1f, RopeRadius + 0.001f, 0f));
            rope.AddCollider(ColliderShape.Box(new Float3(0f, -0.5f, 0f), Quat.Identity, new Float3(0.5f, 0.5f, 0.5f), 1f));
            return rope;
        }

        /// <summary>A box rotated 45° about Z presents a corner upwards at height h·√2; the rope is laid 1 m up.</summary>
        public static Rope RotatedBox()
        {
            var rope = LooseRope(1f, 20, new Float3(-0.5f, 1f, 0f), new Float3(0.5f, 1f, 0f));
            rope.AddCollider(ColliderShape.Box(Float3.Zero, Quat.FromAxisAngle(new Float3(0f, 0f, 1f), MathF.PI / 4f), new Float3(0.5f, 0.5f, 0.5f), 0.8f));
            return rope;
        }

        /// <summary>A rope dropped 0.5 m onto a floor plane (μ 0.3).</summary>
        public static Rope PlaneRest()
        {
            var rope = LooseRope(1f, 10, new Float3(0f, 0.5f, 0f), new Float3(1f, 0.5f, 0f));
            rope.AddCollider(ColliderShape.Plane(Float3.Zero, new Float3(0f, 1f, 0f), 0.3f));
            return rope;
        }

        /// <summary>A horizontal capsule along Z (rotation maps Y to Z), radius 0.2 m, μ 0.5, and a rope laid just above it.</summary>
        public static Rope CapsuleHang()
        {
            var capsule = ColliderShape.Capsule(Float3.Zero, Quat.FromAxisAngle(new Float3(1f, 0f, 0f), MathF.PI / 2f), 0.2f, 1f, 0.5f);
            var rope = LooseRope(1f, 40, new Float3(-0.5f, 0.25f, 0f), new Float3(0.5f, 0.25f, 0f));
            rope.AddCollider(capsule);
            return rope;
        }

        public const int MovingSphereSteps = 45;

        /// <summary>A hanging rope and a sphere (collider 0) that <see cref="MoveSphere"/> sweeps through its lower half in +X.</summary>
        public static Rope MovingSphere()
        {
            var settings = RopeTestKit.Legacy(length: 1f, segments: 20, radius: RopeRadius);
            var rope = RopeTestKit.Hanging(settings, 0f, out _);
            rope.AddCollider(ColliderShape.Sphere(new Float3(-0.3f, -0.8f, 0f), 0.1f));
            return rope;
        }

        public static void MoveSphere(Rope rope, int k) => rope.SetColliderPose(0, new Float3(-0.3f + 0.6f * (k + 1) / MovingSphereSteps, -0.8f, 0f), Quat.Identity);

        public const int BarPullSteps = 180;
        public const float BarRadius = 0.1f, CordRadius = 0.005f, CordLength = 1.2f, Drop = 0.6f;

        /// <summary>
        /// A cord (E·A 200 N, no gravity) between pins 0 (start) and 1 (end) above a frictionless bar (capsule along Z,
        /// radius 0.1 m); <see cref="PullDown"/> pulls both ends down 0.6 m in 1 s and holds them for 1 s.
        /// </summary>
        public static Rope BarPull(int substeps, int iterations)
        {
            var settings = RopeTestKit.Legacy(length: CordLength, segments: 80, radius: CordRadius, substeps: substeps, iterations: iterations);
            settings.AxialStiffness = 200f;
            settings.LinearDensity = 0.05f;
            settings.Gravity = Float3.Zero;
            Float3 a0 = new Float3(-0.5f, 0.2f, 0f), b0 = new Float3(0.5f, 0.2f, 0f);
            var rope = new Rope(settings, a0, b0);
            rope.AddPin(0, a0);
            rope.AddPin(rope.ParticleCount - 1, b0);
            rope.AddCollider(ColliderShape.Capsule(Float3.Zero, Quat.FromAxisAngle(new Float3(1f, 0f, 0f), MathF.PI / 2f), BarRadius, 0.5f));
            return rope;
        }

        public static void PullDown(Rope rope, int k)
        {
            float f = Math.Min((k + 1) / 90f, 1f);
            rope.SetPinTarget(0, new Float3(-0.5f, 0.2f - Drop * f, 0f));
            rope.SetPinTarget(1, new Float3(0.5f, 0.2f - Drop * f, 0f));
        }

        public const int FloorSteps = 90;

        /// <summary>A free rope (β 0.01 s) resting on a floor plane (y = 0, collider 0) with a sphere 10 m away as collider 1.</summary>
        public static Rope FloorWithFarSphere()
        {
            var settings = RopeTestKit.Legacy(length: 1f, segments: 16, radius: RopeRadius, damping: 0.01f);
            var rope = new Rope(settings, new Float3(-0.5f, RopeRadius, 0f), new Float3(0.5f, RopeRadius, 0f));
            rope.AddCollider(ColliderShape.Plane(Float3.Zero, new Float3(0f, 1f, 0f)));
            rope.AddCollider(ColliderShape.Sphere(new Float3(0f, 0f, 10f), 1f));
            return rope;
        }

        /// <summary>Steps <paramref name="rope"/> through steps from … to − 1 of <paramref name="scene"/>.</summary>
        public static void Run(Scene scene, Rope rope, int from, int to)
        {
            for (int k = from; k < to; k++)
            {
                scene.BeforeStep(rope, k);
                rope.Step(RopeTestKit.HostStep);
            }
        }
    }
}
