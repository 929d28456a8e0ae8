using System;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Tests.Solver
{
    /// <summary>Builders shared by the solver tests.</summary>
    internal static class RopeTestKit
    {
        public const float HostStep = 1f / 90f;
        public const double G = 9.81;

        /// <summary>A vertical rope hanging from a rigid pin at the origin, particles laid at rest length downwards, optional load at the bottom.</summary>
        public static Rope Hanging(RopeSettings settings, float load, out int loadIndex)
        {
            var rope = new Rope(settings, Float3.Zero, new Float3(0f, -settings.RestLength, 0f));
            rope.AddPin(0, Float3.Zero);
            loadIndex = load > 0f ? rope.AddLoad(rope.ParticleCount - 1, load) : -1;
            return rope;
        }

        public static RopeSettings Settings(float length, int segments, float axialStiffness, float ropeMass)
        {
            var s = Legacy(length, segments);
            s.AxialStiffness = axialStiffness;
            s.LinearDensity = ropeMass / length;
            return s;
        }

        /// <summary>
        /// Settings with the core's pre-issue-12 defaults stated explicitly (R 5 mm, E 1 GPa, ρ 1140 kg/m³, β 0 s,
        /// L 1 m, 16 segments, 8 substeps, 1 iteration, g = −9.81 m/s² on Y, exact chain, tension only), so that no
        /// solver test number moves when <see cref="RopeSettings"/> takes the parameter table's defaults.
        /// </summary>
        public static RopeSettings Legacy(
            float length = 1f, int segments = 16, float radius = 0.005f, float youngsModulus = 1e9f, float density = 1140f,
            float damping = 0f, int substeps = 8, int iterations = 1, ConstraintSolverKind solver = ConstraintSolverKind.ExactChain)
        {
            return new RopeSettings
            {
                RestLength = length,
                SegmentCount = segments,
                Radius = radius,
                YoungsModulus = youngsModulus,
                Density = density,
                Damping = damping,
                Gravity = new Float3(0f, -9.81f, 0f),
                Substeps = substeps,
                Iterations = iterations,
                Solver = solver,
                Tension = TensionModel.TensionOnly,
            };
        }

        /// <summary>A straight rope of <paramref name="settings"/> pinned at the origin and released at rest length 30° from the downward vertical.</summary>
        public static Rope ReleasedAt30Degrees(RopeSettings settings)
        {
            float length = settings.RestLength;
            var rope = new Rope(settings, Float3.Zero, new Float3(length * 0.5f, -length * (float)Math.Sqrt(0.75), 0f));
            rope.AddPin(0, Float3.Zero);
            return rope;
        }

        /// <summary>
        /// The stability grid's sphere for a 1 m rope of <see cref="ReleasedAt30Degrees"/> to swing onto: R 0.1 m, centred
        /// 0.6 m below the pin, friction coefficient <paramref name="friction"/>.
        /// </summary>
        public static void AddGridSphere(Rope rope, float friction) => rope.AddCollider(ColliderShape.Sphere(new Float3(0f, -0.6f, 0f), 0.1f, friction));

        /// <summary>
        /// Kinetic + gravitational + the least (or, <paramref name="upper"/>, the most) elastic energy any state within
        /// float32 round-off of the rope's stores (<see cref="Rope.ElasticEnergyBounds"/>), J.
        /// </summary>
        public static double TotalEnergy(Rope rope, bool upper)
        {
            rope.ElasticEnergyBounds(out double lower, out double higher);
            return rope.KineticEnergy() + rope.GravitationalEnergy() + (upper ? higher : lower);
        }

        /// <summary>Segment angles (rad) from the downward vertical after 1 s (45 host steps of 1/45 s) of <see cref="ReleasedAt30Degrees"/>.</summary>
        public static double[] AnglesAfterOneSecond(RopeSettings settings)
        {
            var rope = ReleasedAt30Degrees(settings);
            for (int k = 0; k < 45; k++) rope.Step(1f / 45f);
            var angles = new double[rope.SegmentCount];
            for (int j = 0; j < angles.Length; j++)
            {
                Float3 d = rope.GetPosition(j + 1) - rope.GetPosition(j);
                angles[j] = Math.Atan2(d.X, -d.Y);
            }
            return angles;
        }

        public static float Bottom(Rope rope) => rope.GetPosition(rope.ParticleCount - 1).Y;

        public static bool AllFinite(Rope rope)
        {
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                if (!float.IsFinite(rope.PositionX[i]) || !float.IsFinite(rope.PositionY[i]) || !float.IsFinite(rope.PositionZ[i])) return false;
                if (!rope.GetVelocity(i).IsFinite) return false;
            }
            for (int j = 0; j < rope.SegmentCount; j++) if (!float.IsFinite(rope.Tensions[j])) return false;
            return true;
        }
    }
}
