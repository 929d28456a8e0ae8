using System;
using System.Globalization;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.Quaternion: rotations, composed and applied as Unity does.</summary>
    public struct Quaternion : IEquatable<Quaternion>
    {
        /// <summary>Tolerance of the == operator on the dot product (Unity's Quaternion.kEpsilon).</summary>
        public const float kEpsilon = 0.000001F;

        /// <summary>X component of the Quaternion. Don't modify this directly unless you know quaternions inside out.</summary>
        public float x;

        /// <summary>Y component of the Quaternion. Don't modify this directly unless you know quaternions inside out.</summary>
        public float y;

        /// <summary>Z component of the Quaternion. Don't modify this directly unless you know quaternions inside out.</summary>
        public float z;

        /// <summary>W component of the Quaternion. Do not directly modify quaternions.</summary>
        public float w;

        /// <summary>Constructs new Quaternion with given x,y,z,w components.</summary>
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }

        /// <summary>The identity rotation (Read Only).</summary>
        public static Quaternion identity => new Quaternion(0f, 0f, 0f, 1f);

        /// <summary>
        /// Returns a rotation that rotates z degrees around the z axis, x degrees around the x axis, and y degrees
        /// around the y axis; applied in that order (q = qy · qx · qz).
        /// </summary>
        public static Quaternion Euler(float x, float y, float z) =>
            AngleAxis(y, Vector3.up) * AngleAxis(x, Vector3.right) * AngleAxis(z, Vector3.forward);

        /// <summary>Returns a rotation that rotates euler.z, euler.x and euler.y degrees, in that order.</summary>
        public static Quaternion Euler(Vector3 euler) => Euler(euler.x, euler.y, euler.z);

        /// <summary>Creates a rotation which rotates angle degrees around axis.</summary>
        public static Quaternion AngleAxis(float angle, Vector3 axis)
        {
            var n = axis.normalized;
            if (n.sqrMagnitude == 0f) return identity;
            double half = angle * Math.PI / 360.0;
            float s = (float)Math.Sin(half);
            return new Quaternion(n.x * s, n.y * s, n.z * s, (float)Math.Cos(half));
        }

        /// <summary>Creates a rotation which rotates from fromDirection to toDirection.</summary>
        public static Quaternion FromToRotation(Vector3 fromDirection, Vector3 toDirection)
        {
            var a = fromDirection.normalized;
            var b = toDirection.normalized;
            float d = Vector3.Dot(a, b);
            if (d < -0.999999f)
            {
                var axis = Vector3.Cross(Vector3.right, a);
                if (axis.sqrMagnitude < 1e-6f) axis = Vector3.Cross(Vector3.up, a);
                return AngleAxis(180f, axis);
            }
            var c = Vector3.Cross(a, b);
            return Normalize(new Quaternion(c.x, c.y, c.z, 1f + d));
        }

        /// <summary>Returns the Inverse of rotation.</summary>
        public static Quaternion Inverse(Quaternion rotation)
        {
            float n = Dot(rotation, rotation);
            if (n <= 0f) return identity;
            float k = 1f / n;
            return new Quaternion(-rotation.x * k, -rotation.y * k, -rotation.z * k, rotation.w * k);
        }

        /// <summary>Converts this quaternion to one with the same orientation but with a magnitude of 1.</summary>
        public static Quaternion Normalize(Quaternion q)
        {
            float mag = (float)Math.Sqrt(Dot(q, q));
            return mag < Mathf_Epsilon ? identity : new Quaternion(q.x / mag, q.y / mag, q.z / mag, q.w / mag);
        }

        /// <summary>Returns this quaternion with a magnitude of 1.</summary>
        public Quaternion normalized => Normalize(this);

        /// <summary>The dot product between two rotations.</summary>
        public static float Dot(Quaternion a, Quaternion b) => a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;

        /// <summary>Returns the angle in degrees between two rotations a and b.</summary>
        public static float Angle(Quaternion a, Quaternion b)
        {
            float dot = Math.Min(Math.Abs(Dot(a, b)), 1f);
            return dot > 1f - kEpsilon ? 0f : (float)(Math.Acos(dot) * 2.0 * 180.0 / Math.PI);
        }

        /// <summary>Spherically interpolates between a and b by t (clamped to [0, 1]).</summary>
        public static Quaternion Slerp(Quaternion a, Quaternion b, float t)
        {
            t = t < 0f ? 0f : t > 1f ? 1f : t;
            float cos = Dot(a, b);
            if (cos < 0f) { b = new Quaternion(-b.x, -b.y, -b.z, -b.w); cos = -cos; }
            float wa, wb;
            if (cos > 0.9995f) { wa = 1f - t; wb = t; }
            else
            {
                double theta = Math.Acos(cos), sin = Math.Sin(theta);
                wa = (float)(Math.Sin((1 - t) * theta) / sin);
                wb = (float)(Math.Sin(t * theta) / sin);
            }
            return Normalize(new Quaternion(a.x * wa + b.x * wb, a.y * wa + b.y * wb, a.z * wa + b.z * wb, a.w * wa + b.w * wb));
        }

        /// <summary>Combines rotations lhs and rhs (rhs applied first).</summary>
        public static Quaternion operator *(Quaternion lhs, Quaternion rhs) =>
            new Quaternion(
                lhs.w * rhs.x + lhs.x * rhs.w + lhs.y * rhs.z - lhs.z * rhs.y,
                lhs.w * rhs.y + lhs.y * rhs.w + lhs.z * rhs.x - lhs.x * rhs.z,
                lhs.w * rhs.z + lhs.z * rhs.w + lhs.x * rhs.y - lhs.y * rhs.x,
                lhs.w * rhs.w - lhs.x * rhs.x - lhs.y * rhs.y - lhs.z * rhs.z);

        /// <summary>Rotates the point point with rotation.</summary>
        public static Vector3 operator *(Quaternion rotation, Vector3 point)
        {
            // v' = v + 2w (q × v) + 2 q × (q × v), q = (x, y, z)
            float qx = rotation.x, qy = rotation.y, qz = rotation.z, qw = rotation.w;
            float tx = 2f * (qy * point.z - qz * point.y);
            float ty = 2f * (qz * point.x - qx * point.z);
            float tz = 2f * (qx * point.y - qy * point.x);
            return new Vector3(
                point.x + qw * tx + (qy * tz - qz * ty),
                point.y + qw * ty + (qz * tx - qx * tz),
                point.z + qw * tz + (qx * ty - qy * tx));
        }

        /// <summary>True when the rotations are the same to within Unity's tolerance (dot product above 1 − 1e-6).</summary>
        public static bool operator ==(Quaternion lhs, Quaternion rhs) => Dot(lhs, rhs) > 1f - kEpsilon;

        /// <summary>True when the rotations differ.</summary>
        public static bool operator !=(Quaternion lhs, Quaternion rhs) => !(lhs == rhs);

        /// <summary>Exact component-wise equality.</summary>
        public bool Equals(Quaternion other) => x.Equals(other.x) && y.Equals(other.y) && z.Equals(other.z) && w.Equals(other.w);

        /// <inheritdoc/>
        public override bool Equals(object other) => other is Quaternion q && Equals(q);

        /// <inheritdoc/>
        public override int GetHashCode() => x.GetHashCode() ^ (y.GetHashCode() << 2) ^ (z.GetHashCode() >> 2) ^ (w.GetHashCode() >> 1);

        /// <summary>Returns a formatted string for this quaternion, as Unity prints it (five decimals).</summary>
        public override string ToString() =>
            string.Format(CultureInfo.InvariantCulture, "({0:F5}, {1:F5}, {2:F5}, {3:F5})", x, y, z, w);

        const float Mathf_Epsilon = 1.17549435E-38f;
    }
}
