using System;

namespace HookeRope.Mathematics
{
    /// <summary>
    /// Engine-free unit quaternion (x, y, z, w) used for collider and pin rotations. Component
    /// order and meaning match <c>UnityEngine.Quaternion</c>, so the Unity layer copies it field by field.
    /// </summary>
    public readonly struct Quat : IEquatable<Quat>
    {
        /// <summary>X component of the vector part (dimensionless).</summary>
        public readonly float X;
        /// <summary>Y component of the vector part (dimensionless).</summary>
        public readonly float Y;
        /// <summary>Z component of the vector part (dimensionless).</summary>
        public readonly float Z;
        /// <summary>Scalar part (dimensionless).</summary>
        public readonly float W;

        /// <summary>Creates a quaternion from its components (not normalised).</summary>
        public Quat(float x, float y, float z, float w) { X = x; Y = y; Z = z; W = w; }

        /// <summary>The identity rotation (0, 0, 0, 1).</summary>
        public static Quat Identity => new Quat(0f, 0f, 0f, 1f);

        /// <summary>True when no component is NaN or infinite.</summary>
        public bool IsFinite => float.IsFinite(X) && float.IsFinite(Y) && float.IsFinite(Z) && float.IsFinite(W);

        /// <summary>Squared norm (dimensionless).</summary>
        public float LengthSquared => X * X + Y * Y + Z * Z + W * W;

        /// <summary>Rotation of <paramref name="angle"/> radians about <paramref name="axis"/> (any length; identity when the axis is zero).</summary>
        public static Quat FromAxisAngle(Float3 axis, float angle)
        {
            Float3 unit = axis.NormalizedOr(Float3.Zero);
            float half = 0.5f * angle;
            float s = MathF.Sin(half);
            return unit == Float3.Zero ? Identity : new Quat(unit.X * s, unit.Y * s, unit.Z * s, MathF.Cos(half));
        }

        /// <summary>Shortest rotation taking direction <paramref name="from"/> to direction <paramref name="to"/> (any lengths).</summary>
        public static Quat FromToRotation(Float3 from, Float3 to)
        {
            Float3 a = from.NormalizedOr(new Float3(0f, 1f, 0f));
            Float3 b = to.NormalizedOr(new Float3(0f, 1f, 0f));
            float d = Float3.Dot(a, b);
            if (d < -0.999999f)
            {
                Float3 axis = Float3.Cross(new Float3(1f, 0f, 0f), a);
                if (axis.LengthSquared < 1e-6f) axis = Float3.Cross(new Float3(0f, 0f, 1f), a);
                return FromAxisAngle(axis, MathF.PI);
            }
            Float3 c = Float3.Cross(a, b);
            return new Quat(c.X, c.Y, c.Z, 1f + d).Normalized();
        }

        /// <summary>This quaternion scaled to unit norm, or the identity when its norm is zero or not finite.</summary>
        public Quat Normalized()
        {
            float n = LengthSquared;
            if (!(n > 1e-30f) || !float.IsFinite(n)) return Identity;
            float inv = 1f / MathF.Sqrt(n);
            return new Quat(X * inv, Y * inv, Z * inv, W * inv);
        }

        /// <summary>Inverse of a unit quaternion (its conjugate).</summary>
        public Quat Conjugate => new Quat(-X, -Y, -Z, W);

        /// <summary>Rotates vector <paramref name="v"/> by this unit quaternion.</summary>
        public Float3 Rotate(Float3 v)
        {
            // v' = v + 2 w (q × v) + 2 q × (q × v), q the vector part.
            float tx = 2f * (Y * v.Z - Z * v.Y);
            float ty = 2f * (Z * v.X - X * v.Z);
            float tz = 2f * (X * v.Y - Y * v.X);
            return new Float3(
                v.X + W * tx + (Y * tz - Z * ty),
                v.Y + W * ty + (Z * tx - X * tz),
                v.Z + W * tz + (X * ty - Y * tx));
        }

        /// <summary>Normalised linear interpolation between two rotations along the shorter arc, t in [0, 1].</summary>
        public static Quat Nlerp(Quat a, Quat b, float t)
        {
            float dot = a.X * b.X + a.Y * b.Y + a.Z * b.Z + a.W * b.W;
            float sign = dot < 0f ? -1f : 1f;
            float u = 1f - t;
            float v = t * sign;
            return new Quat(a.X * u + b.X * v, a.Y * u + b.Y * v, a.Z * u + b.Z * v, a.W * u + b.W * v).Normalized();
        }

        /// <summary>Composition: rotating by the result equals rotating by <paramref name="b"/> then by <paramref name="a"/>.</summary>
        public static Quat operator *(Quat a, Quat b) => new Quat(
            a.W * b.X + a.X * b.W + a.Y * b.Z - a.Z * b.Y,
            a.W * b.Y - a.X * b.Z + a.Y * b.W + a.Z * b.X,
            a.W * b.Z + a.X * b.Y - a.Y * b.X + a.Z * b.W,
            a.W * b.W - a.X * b.X - a.Y * b.Y - a.Z * b.Z);

        /// <summary>Exact component equality.</summary>
        public static bool operator ==(Quat a, Quat b) => a.Equals(b);
        /// <summary>Exact component inequality.</summary>
        public static bool operator !=(Quat a, Quat b) => !a.Equals(b);

        /// <inheritdoc/>
        public bool Equals(Quat other) => X.Equals(other.X) && Y.Equals(other.Y) && Z.Equals(other.Z) && W.Equals(other.W);
        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is Quat other && Equals(other);
        /// <inheritdoc/>
        public override int GetHashCode() => HashCode.Combine(X, Y, Z, W);
        /// <inheritdoc/>
        public override string ToString() => $"({X:G6}, {Y:G6}, {Z:G6}, {W:G6})";
    }
}
