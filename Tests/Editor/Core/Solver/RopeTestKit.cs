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
            var s = new RopeSettings { RestLength = length, SegmentCount = segments };
            s.AxialStiffness = axialStiffness;
            s.LinearDensity = ropeMass / length;
            return s;
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
