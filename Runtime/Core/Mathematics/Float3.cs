using System;

namespace HookeRope.Mathematics
{
    /// <summary>
    /// Engine-free 3-component float vector (metres, metres per second or newtons, as the caller says).
    /// The Unity layer converts to and from <c>UnityEngine.Vector3</c> field by field.
    /// </summary>
    public readonly struct Float3 : IEquatable<Float3>
    {
        /// <summary>X component.</summary>
        public readonly float X;
        /// <summary>Y component (up in Unity's convention).</summary>
        public readonly float Y;
        /// <summary>Z component.</summary>
        public readonly float Z;

        /// <summary>Creates a vector from its components.</summary>
        public Float3(float x, float y, float z) { X = x; Y = y; Z = z; }

        /// <summary>(0, 0, 0).</summary>
        public static Float3 Zero => default;

        /// <summary>Euclidean length.</summary>
        public float Length => MathF.Sqrt(X * X + Y * Y + Z * Z);

        /// <summary>Squared Euclidean length.</summary>
        public float LengthSquared => X * X + Y * Y + Z * Z;

        /// <summary>True when no component is NaN or infinite.</summary>
        public bool IsFinite => float.IsFinite(X) && float.IsFinite(Y) && float.IsFinite(Z);

        /// <summary>Dot product.</summary>
        public static float Dot(Float3 a, Float3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

        /// <summary>Cross product (right-handed formula; Unity's left-handed axes give the same components).</summary>
        public static Float3 Cross(Float3 a, Float3 b) =>
            new Float3(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

        /// <summary>This vector scaled to unit length, or <paramref name="fallback"/> when its length is below 1e-20.</summary>
        public Float3 NormalizedOr(Float3 fallback)
        {
            float lengthSquared = LengthSquared;
            return lengthSquared > 1e-20f ? this * (1f / MathF.Sqrt(lengthSquared)) : fallback;
        }

        /// <summary>Linear interpolation a + (b − a)·t.</summary>
        public static Float3 Lerp(Float3 a, Float3 b, float t) => a + (b - a) * t;

        /// <summary>Component-wise sum.</summary>
        public static Float3 operator +(Float3 a, Float3 b) => new Float3(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        /// <summary>Component-wise difference.</summary>
        public static Float3 operator -(Float3 a, Float3 b) => new Float3(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        /// <summary>Negation.</summary>
        public static Float3 operator -(Float3 a) => new Float3(-a.X, -a.Y, -a.Z);
        /// <summary>Scaling.</summary>
        public static Float3 operator *(Float3 a, float s) => new Float3(a.X * s, a.Y * s, a.Z * s);
        /// <summary>Scaling.</summary>
        public static Float3 operator *(float s, Float3 a) => new Float3(a.X * s, a.Y * s, a.Z * s);
        /// <summary>Division by a scalar.</summary>
        public static Float3 operator /(Float3 a, float s) => new Float3(a.X / s, a.Y / s, a.Z / s);
        /// <summary>Exact component equality.</summary>
        public static bool operator ==(Float3 a, Float3 b) => a.Equals(b);
        /// <summary>Exact component inequality.</summary>
        public static bool operator !=(Float3 a, Float3 b) => !a.Equals(b);

        /// <inheritdoc/>
        public bool Equals(Float3 other) => X.Equals(other.X) && Y.Equals(other.Y) && Z.Equals(other.Z);
        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is Float3 other && Equals(other);
        /// <inheritdoc/>
        public override int GetHashCode() => HashCode.Combine(X, Y, Z);
        /// <inheritdoc/>
        public override string ToString() => $"({X:G6}, {Y:G6}, {Z:G6})";
    }
}
