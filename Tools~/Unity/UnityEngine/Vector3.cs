using System;
using System.Globalization;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.Vector3: a 3D vector of floats with Unity's operators and tolerances.</summary>
    public struct Vector3 : IEquatable<Vector3>
    {
        /// <summary>Tolerance of the == operator (Unity's Vector3.kEpsilon).</summary>
        public const float kEpsilon = 0.00001F;

        /// <summary>X component of the vector.</summary>
        public float x;

        /// <summary>Y component of the vector.</summary>
        public float y;

        /// <summary>Z component of the vector.</summary>
        public float z;

        /// <summary>Creates a new vector with given x, y, z components.</summary>
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }

        /// <summary>Creates a new vector with given x, y components and sets z to zero.</summary>
        public Vector3(float x, float y) { this.x = x; this.y = y; z = 0f; }

        /// <summary>Access the x, y, z components using [0], [1], [2] respectively.</summary>
        public float this[int index]
        {
            get => index == 0 ? x : index == 1 ? y : index == 2 ? z : throw new IndexOutOfRangeException("Invalid Vector3 index!");
            set
            {
                if (index == 0) x = value;
                else if (index == 1) y = value;
                else if (index == 2) z = value;
                else throw new IndexOutOfRangeException("Invalid Vector3 index!");
            }
        }

        /// <summary>Shorthand for writing Vector3(0, 0, 0).</summary>
        public static Vector3 zero => new Vector3(0f, 0f, 0f);

        /// <summary>Shorthand for writing Vector3(1, 1, 1).</summary>
        public static Vector3 one => new Vector3(1f, 1f, 1f);

        /// <summary>Shorthand for writing Vector3(0, 1, 0).</summary>
        public static Vector3 up => new Vector3(0f, 1f, 0f);

        /// <summary>Shorthand for writing Vector3(0, -1, 0).</summary>
        public static Vector3 down => new Vector3(0f, -1f, 0f);

        /// <summary>Shorthand for writing Vector3(-1, 0, 0).</summary>
        public static Vector3 left => new Vector3(-1f, 0f, 0f);

        /// <summary>Shorthand for writing Vector3(1, 0, 0).</summary>
        public static Vector3 right => new Vector3(1f, 0f, 0f);

        /// <summary>Shorthand for writing Vector3(0, 0, 1).</summary>
        public static Vector3 forward => new Vector3(0f, 0f, 1f);

        /// <summary>Shorthand for writing Vector3(0, 0, -1).</summary>
        public static Vector3 back => new Vector3(0f, 0f, -1f);

        /// <summary>Returns the length of this vector.</summary>
        public float magnitude => (float)Math.Sqrt(x * x + y * y + z * z);

        /// <summary>Returns the squared length of this vector.</summary>
        public float sqrMagnitude => x * x + y * y + z * z;

        /// <summary>Returns this vector with a magnitude of 1 (zero when it is too small to normalize).</summary>
        public Vector3 normalized => Normalize(this);

        /// <summary>Makes this vector have a magnitude of 1 (zero when it is too small to normalize).</summary>
        public void Normalize() => this = Normalize(this);

        /// <summary>Returns <paramref name="value"/> with a magnitude of 1, or zero when its magnitude is at most 1e-5.</summary>
        public static Vector3 Normalize(Vector3 value)
        {
            float length = value.magnitude;
            return length > kEpsilon ? value / length : zero;
        }

        /// <summary>Dot Product of two vectors.</summary>
        public static float Dot(Vector3 lhs, Vector3 rhs) => lhs.x * rhs.x + lhs.y * rhs.y + lhs.z * rhs.z;

        /// <summary>Cross Product of two vectors.</summary>
        public static Vector3 Cross(Vector3 lhs, Vector3 rhs) =>
            new Vector3(lhs.y * rhs.z - lhs.z * rhs.y, lhs.z * rhs.x - lhs.x * rhs.z, lhs.x * rhs.y - lhs.y * rhs.x);

        /// <summary>Returns the distance between a and b (same as (a - b).magnitude).</summary>
        public static float Distance(Vector3 a, Vector3 b) => (a - b).magnitude;

        /// <summary>Multiplies two vectors component-wise.</summary>
        public static Vector3 Scale(Vector3 a, Vector3 b) => new Vector3(a.x * b.x, a.y * b.y, a.z * b.z);

        /// <summary>Linearly interpolates between two points; t is clamped to [0, 1].</summary>
        public static Vector3 Lerp(Vector3 a, Vector3 b, float t)
        {
            t = t < 0f ? 0f : t > 1f ? 1f : t;
            return LerpUnclamped(a, b, t);
        }

        /// <summary>Linearly interpolates between two vectors without clamping t.</summary>
        public static Vector3 LerpUnclamped(Vector3 a, Vector3 b, float t) =>
            new Vector3(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t);

        /// <summary>Returns a vector made from the smallest components of two vectors.</summary>
        public static Vector3 Min(Vector3 lhs, Vector3 rhs) => new Vector3(Math.Min(lhs.x, rhs.x), Math.Min(lhs.y, rhs.y), Math.Min(lhs.z, rhs.z));

        /// <summary>Returns a vector made from the largest components of two vectors.</summary>
        public static Vector3 Max(Vector3 lhs, Vector3 rhs) => new Vector3(Math.Max(lhs.x, rhs.x), Math.Max(lhs.y, rhs.y), Math.Max(lhs.z, rhs.z));

        /// <summary>Adds two vectors.</summary>
        public static Vector3 operator +(Vector3 a, Vector3 b) => new Vector3(a.x + b.x, a.y + b.y, a.z + b.z);

        /// <summary>Subtracts one vector from another.</summary>
        public static Vector3 operator -(Vector3 a, Vector3 b) => new Vector3(a.x - b.x, a.y - b.y, a.z - b.z);

        /// <summary>Negates a vector.</summary>
        public static Vector3 operator -(Vector3 a) => new Vector3(-a.x, -a.y, -a.z);

        /// <summary>Multiplies a vector by a number.</summary>
        public static Vector3 operator *(Vector3 a, float d) => new Vector3(a.x * d, a.y * d, a.z * d);

        /// <summary>Multiplies a vector by a number.</summary>
        public static Vector3 operator *(float d, Vector3 a) => new Vector3(a.x * d, a.y * d, a.z * d);

        /// <summary>Divides a vector by a number.</summary>
        public static Vector3 operator /(Vector3 a, float d) => new Vector3(a.x / d, a.y / d, a.z / d);

        /// <summary>True when the vectors are approximately equal (difference shorter than 1e-5).</summary>
        public static bool operator ==(Vector3 lhs, Vector3 rhs)
        {
            float dx = lhs.x - rhs.x, dy = lhs.y - rhs.y, dz = lhs.z - rhs.z;
            return dx * dx + dy * dy + dz * dz < kEpsilon * kEpsilon;
        }

        /// <summary>True when the vectors differ (difference at least 1e-5 long).</summary>
        public static bool operator !=(Vector3 lhs, Vector3 rhs) => !(lhs == rhs);

        /// <summary>Exact component-wise equality.</summary>
        public bool Equals(Vector3 other) => x.Equals(other.x) && y.Equals(other.y) && z.Equals(other.z);

        /// <inheritdoc/>
        public override bool Equals(object other) => other is Vector3 v && Equals(v);

        /// <inheritdoc/>
        public override int GetHashCode() => x.GetHashCode() ^ (y.GetHashCode() << 2) ^ (z.GetHashCode() >> 2);

        /// <summary>Returns a formatted string for this vector, as Unity prints it (two decimals).</summary>
        public override string ToString() =>
            string.Format(CultureInfo.InvariantCulture, "({0:F2}, {1:F2}, {2:F2})", x, y, z);
    }
}
