using System;
using HookeRope.Solver;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>Particle positions (SoA) of test shapes.</summary>
    internal sealed class RopeShape
    {
        public readonly float[] X, Y, Z, Rest;

        public RopeShape(int segments, float restLength)
        {
            X = new float[segments + 1];
            Y = new float[segments + 1];
            Z = new float[segments + 1];
            Rest = new float[segments];
            Array.Fill(Rest, restLength);
        }

        public int Segments => Rest.Length;

        /// <summary>A copy of <paramref name="rope"/>'s particle positions and rest lengths.</summary>
        public static RopeShape FromRope(Rope rope)
        {
            var shape = new RopeShape(rope.SegmentCount, 0f);
            rope.PositionX.CopyTo(shape.X);
            rope.PositionY.CopyTo(shape.Y);
            rope.PositionZ.CopyTo(shape.Z);
            rope.RestLengths.CopyTo(shape.Rest);
            return shape;
        }

        public static RopeShape Straight(int segments, float restLength, float stretch, float dx, float dy, float dz, float ox = 0f, float oy = 0f, float oz = 0f)
        {
            var s = new RopeShape(segments, restLength);
            float norm = MathF.Sqrt(dx * dx + dy * dy + dz * dz);
            for (int i = 0; i <= segments; i++)
            {
                float d = i * restLength * stretch / norm;
                s.X[i] = ox + dx * d; s.Y[i] = oy + dy * d; s.Z[i] = oz + dz * d;
            }
            return s;
        }

        public static RopeShape Helix(int segments, float restLength, float radius, float pitchPerTurn)
        {
            var s = new RopeShape(segments, restLength);
            for (int i = 0; i <= segments; i++)
            {
                float angle = 0.5f * i;
                s.X[i] = radius * MathF.Cos(angle); s.Y[i] = radius * MathF.Sin(angle); s.Z[i] = pitchPerTurn * angle / (2f * MathF.PI);
            }
            return s;
        }

        /// <summary>Zig-zag: every particle folds back 180° onto the previous segment.</summary>
        public static RopeShape Folded(int segments, float restLength)
        {
            var s = new RopeShape(segments, restLength);
            for (int i = 0; i <= segments; i++) s.X[i] = (i % 2) * restLength;
            return s;
        }

        /// <summary>All particles at one point.</summary>
        public static RopeShape Collapsed(int segments, float restLength)
        {
            var s = new RopeShape(segments, restLength);
            Array.Fill(s.X, 0.3f); Array.Fill(s.Y, -0.2f); Array.Fill(s.Z, 1f);
            return s;
        }

        /// <summary>Pairs of coincident particles along a bent path.</summary>
        public static RopeShape PairsCoincident(int segments, float restLength)
        {
            var s = new RopeShape(segments, restLength);
            for (int i = 0; i <= segments; i++)
            {
                int k = i / 2;
                s.X[i] = restLength * k; s.Y[i] = 0.3f * restLength * (k % 3); s.Z[i] = 0f;
            }
            return s;
        }

        /// <summary>A U-turn: straight, a half circle of the given radius, straight back.</summary>
        public static RopeShape UTurn(int segments, float restLength, float bendRadius)
        {
            var s = new RopeShape(segments, restLength);
            int third = segments / 3;
            for (int i = 0; i <= segments; i++)
            {
                if (i <= third) { s.X[i] = -(third - i) * restLength; s.Y[i] = 0f; }
                else if (i <= 2 * third)
                {
                    float angle = MathF.PI * (i - third) / third;
                    s.X[i] = bendRadius * MathF.Sin(angle); s.Y[i] = bendRadius * (1f - MathF.Cos(angle));
                }
                else { s.X[i] = -(i - 2 * third) * restLength; s.Y[i] = 2f * bendRadius; }
            }
            return s;
        }
    }
}
