using System;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Tests.MaterialLaw
{
    /// <summary>Builders of the material-law tests (issue 15).</summary>
    internal static class MaterialTestKit
    {
        public const float HostStep = 1f / 90f;
        public const double G = 9.81;

        /// <summary>Zero-gravity rope along +x between two rigid pins, undamped, exact solve unless told; pin 1 is the moving end.</summary>
        public static Rope Pulled(RopeSettings settings, out int endPin)
        {
            var rope = new Rope(settings, Float3.Zero, new Float3(settings.RestLength, 0f, 0f));
            rope.AddPin(0, Float3.Zero);
            endPin = rope.AddPin(rope.ParticleCount - 1, new Float3(settings.RestLength, 0f, 0f));
            return rope;
        }

        /// <summary>Settings of a rope of <paramref name="length"/> m, <paramref name="segments"/> segments, E·A (N), μ (kg/m, default 0.05), no damping, no gravity.</summary>
        public static RopeSettings Straight(float length, int segments, float axialStiffness, ConstraintSolverKind solver = ConstraintSolverKind.ExactChain, float linearDensity = 0.05f)
        {
            var s = new RopeSettings
            {
                RestLength = length, SegmentCount = segments, Radius = 0.008f, Damping = 0f, Gravity = new Float3(0f, 0f, 0f),
                Substeps = 8, Iterations = 1, Solver = solver,
            };
            s.AxialStiffness = axialStiffness;
            s.LinearDensity = linearDensity;
            return s;
        }

        /// <summary>Moves the end pin to total elongation <paramref name="elongation"/> (m) over <paramref name="seconds"/> s in host steps, calling <paramref name="after"/> after each.</summary>
        public static void Drive(Rope rope, int endPin, double from, double to, double seconds, Action after = null)
        {
            int steps = (int)Math.Ceiling(seconds / HostStep);
            float length = rope.Settings.RestLength;
            for (int k = 1; k <= steps; k++)
            {
                double e = from + (to - from) * k / steps;
                rope.SetPinTarget(endPin, new Float3((float)(length + e), 0f, 0f));
                rope.Step(HostStep);
                after?.Invoke();
            }
        }

        /// <summary>Total length of the rope's segments minus its rest length (m).</summary>
        public static double Elongation(Rope rope)
        {
            double sum = 0.0;
            for (int j = 0; j < rope.SegmentCount; j++) sum += rope.SegmentLengths[j] - rope.RestLengths[j];
            return sum;
        }

        /// <summary>
        /// The lanyard of issue 15's absorber test: 2 m of webbing (E·A 100 kN, 20 segments, 0.05 kg/m, undamped) pinned at the
        /// origin with 100 kg at its end, released taut after a free fall of 4 m (v = sqrt(2gh) down).
        /// </summary>
        public static Rope Lanyard(RopeSettings settings, out int load)
        {
            var rope = new Rope(settings, Float3.Zero, new Float3(0f, -settings.RestLength, 0f));
            rope.AddPin(0, Float3.Zero);
            load = rope.AddLoad(rope.ParticleCount - 1, 100f);
            rope.SetVelocity(rope.ParticleCount - 1, new Float3(0f, -(float)Math.Sqrt(2.0 * G * 4.0), 0f));
            return rope;
        }

        /// <summary>Settings of <see cref="Lanyard"/>, with the 4 kN / 1.75 m absorber when asked.</summary>
        public static RopeSettings LanyardSettings(bool absorber, int segments = 20, ConstraintSolverKind solver = ConstraintSolverKind.ExactChain, float deployment = 1.75f)
        {
            var s = new RopeSettings { RestLength = 2f, SegmentCount = segments, Radius = 0.008f, Damping = 0f, Substeps = 8, Iterations = 1, Solver = solver };
            s.AxialStiffness = 1e5f;
            s.LinearDensity = 0.05f;
            if (absorber) s.UseEnergyAbsorber(4000f, deployment);
            return s;
        }
    }
}
