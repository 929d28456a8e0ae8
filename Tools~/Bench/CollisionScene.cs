using System;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Bench
{
    /// <summary>
    /// The collision broad-phase workloads of issue 18 item 3: a 256-segment rope at the benchmark settings
    /// (<see cref="LegacySettings"/>: exact chain, 8 substeps × 1 iteration), pinned at its top and swinging, with no
    /// collider, one far plane, one far sphere or ten far colliders of every kind; and a free rope draped over a bar
    /// (a capsule), on which only the few particles at the top touch. Each is warmed up by <see cref="WarmUpSteps"/> steps (the draped rope by <see cref="DrapeSteps"/>).
    /// </summary>
    internal static class CollisionScene
    {
        /// <summary>Segments of every case.</summary>
        public const int Segments = 256;

        /// <summary>Host step, s.</summary>
        public const float Step = 1f / 90f;

        /// <summary>Steps taken before measuring (the draped rope: <see cref="DrapeSteps"/>).</summary>
        public const int WarmUpSteps = 30;

        /// <summary>Steps the draped rope takes to fall onto the bar and hang (3 s).</summary>
        public const int DrapeSteps = 270;

        /// <summary>The cases, in the order the table prints them.</summary>
        public static readonly string[] Cases = { "none", "far-plane", "far-sphere", "ten-far", "bar", "bar-bare" };

        /// <summary>What each case is, for the table.</summary>
        public static string Describe(string name)
        {
            switch (name)
            {
                case "none": return "hanging, no collider";
                case "far-plane": return "hanging, one plane 90 m below";
                case "far-sphere": return "hanging, one sphere 10 m aside";
                case "ten-far": return "hanging, 10 far colliders (3 planes, 3 spheres, 2 capsules, 2 boxes)";
                case "bar": return "draped over a bar (capsule r 5 cm)";
                case "bar-bare": return "the same rope with the bar removed after warm-up";
                default: throw new ArgumentException("unknown case " + name, nameof(name));
            }
        }

        /// <summary>Builds case <paramref name="name"/> (colliders through the brute-force pass when <paramref name="brute"/>) and warms it up.</summary>
        public static Rope Build(string name, bool brute)
        {
            Rope rope;
            if (name == "bar" || name == "bar-bare")
            {
                // 10 m laid across a horizontal bar along Z at the origin; both halves fall and hang
                var settings = LegacySettings.Create(10f, Segments, ConstraintSolverKind.ExactChain);
                rope = new Rope(settings, new Float3(-5f, 0.06f, 0f), new Float3(5f, 0.06f, 0f));
                rope.AddCollider(ColliderShape.Capsule(Float3.Zero, Quat.FromAxisAngle(new Float3(1f, 0f, 0f), MathF.PI / 2f), 0.05f, 0.5f, 0.5f));
            }
            else
            {
                // 10 m from an anchor at the origin, released 20° from the vertical: it swings through the warm-up and the measurement
                var settings = LegacySettings.Create(10f, Segments, ConstraintSolverKind.ExactChain);
                var end = new Float3(10f * MathF.Sin(0.35f), -10f * MathF.Cos(0.35f), 0f);
                rope = new Rope(settings, Float3.Zero, end);
                rope.AddPin(0, Float3.Zero);
                AddFarColliders(rope, name);
            }
            rope.Collisions.BruteForce = brute;
            int warmUp = name.StartsWith("bar", StringComparison.Ordinal) ? DrapeSteps : WarmUpSteps;
            for (int i = 0; i < warmUp; i++) rope.Step(Step);
            if (name == "bar-bare") rope.ClearColliders();
            return rope;
        }

        private static void AddFarColliders(Rope rope, string name)
        {
            switch (name)
            {
                case "none":
                    return;
                case "far-plane":
                    rope.AddCollider(ColliderShape.Plane(new Float3(0f, -100f, 0f), new Float3(0f, 1f, 0f)));
                    return;
                case "far-sphere":
                    rope.AddCollider(ColliderShape.Sphere(new Float3(0f, -5f, 10f), 1f, 0.5f));
                    return;
                case "ten-far":
                    rope.AddCollider(ColliderShape.Plane(new Float3(0f, -100f, 0f), new Float3(0f, 1f, 0f), 0.5f));
                    rope.AddCollider(ColliderShape.Plane(new Float3(30f, 0f, 0f), new Float3(-1f, 0f, 0f)));
                    rope.AddCollider(ColliderShape.Plane(new Float3(0f, 0f, -30f), new Float3(0.2f, 0f, 1f)));
                    rope.AddCollider(ColliderShape.Sphere(new Float3(0f, -5f, 10f), 1f, 0.5f));
                    rope.AddCollider(ColliderShape.Sphere(new Float3(-8f, -8f, 0f), 2f));
                    rope.AddCollider(ColliderShape.Sphere(new Float3(0f, 3f, 0f), 1f));
                    rope.AddCollider(ColliderShape.Capsule(new Float3(0f, -15f, 0f), Quat.FromAxisAngle(new Float3(1f, 0f, 0f), MathF.PI / 2f), 0.2f, 3f));
                    rope.AddCollider(ColliderShape.Capsule(new Float3(12f, -5f, 0f), Quat.Identity, 0.3f, 2f, 0.4f));
                    rope.AddCollider(ColliderShape.Box(new Float3(-6f, -2f, 4f), Quat.FromAxisAngle(new Float3(0f, 1f, 0f), 0.5f), new Float3(1f, 0.5f, 2f)));
                    rope.AddCollider(ColliderShape.Box(new Float3(5f, -12f, -5f), Quat.Identity, new Float3(2f, 0.5f, 2f), 0.6f));
                    return;
                default:
                    throw new ArgumentException("unknown case " + name, nameof(name));
            }
        }
    }
}
