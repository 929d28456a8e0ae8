using System;
using System.Globalization;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Bounds: an axis-aligned bounding box stored as centre and extents, with Unity
    /// 2022.3's Bounds.cs semantics (size = 2 × extents, SetMinMax, Encapsulate, Expand, Intersects). Contains is
    /// native in Unity (AABB::IsInside); here it is inclusive on both faces.
    /// </summary>
    public struct Bounds : IEquatable<Bounds>, IFormattable
    {
        Vector3 m_Center;
        Vector3 m_Extents;

        /// <summary>Creates a new Bounds with the given center and total size (extents are half the size).</summary>
        public Bounds(Vector3 center, Vector3 size)
        {
            m_Center = center;
            m_Extents = size * 0.5F;
        }

        /// <summary>The center of the bounding box.</summary>
        public Vector3 center { get => m_Center; set => m_Center = value; }

        /// <summary>The total size of the box. This is always twice as large as the extents.</summary>
        public Vector3 size { get => m_Extents * 2.0F; set => m_Extents = value * 0.5F; }

        /// <summary>The extents of the Bounding Box. This is always half of the size of the Bounds.</summary>
        public Vector3 extents { get => m_Extents; set => m_Extents = value; }

        /// <summary>The minimal point of the box. This is always equal to center-extents.</summary>
        public Vector3 min { get => center - extents; set => SetMinMax(value, max); }

        /// <summary>The maximal point of the box. This is always equal to center+extents.</summary>
        public Vector3 max { get => center + extents; set => SetMinMax(min, value); }

        /// <summary>Sets the bounds to the min and max value of the box.</summary>
        public void SetMinMax(Vector3 min, Vector3 max)
        {
            extents = (max - min) * 0.5F;
            center = min + extents;
        }

        /// <summary>Grows the Bounds to include the point.</summary>
        public void Encapsulate(Vector3 point) => SetMinMax(Vector3.Min(min, point), Vector3.Max(max, point));

        /// <summary>Grow the bounds to encapsulate the bounds.</summary>
        public void Encapsulate(Bounds bounds)
        {
            Encapsulate(bounds.center - bounds.extents);
            Encapsulate(bounds.center + bounds.extents);
        }

        /// <summary>Expand the bounds by increasing its size by amount along each side.</summary>
        public void Expand(float amount)
        {
            amount *= 0.5f;
            extents += new Vector3(amount, amount, amount);
        }

        /// <summary>Expand the bounds by increasing its size by amount along each side.</summary>
        public void Expand(Vector3 amount) => extents += amount * 0.5f;

        /// <summary>Does another bounding box intersect with this bounding box?</summary>
        public bool Intersects(Bounds bounds) =>
            min.x <= bounds.max.x && max.x >= bounds.min.x &&
            min.y <= bounds.max.y && max.y >= bounds.min.y &&
            min.z <= bounds.max.z && max.z >= bounds.min.z;

        /// <summary>Is point contained in the bounding box? (Inclusive of the faces.)</summary>
        public bool Contains(Vector3 point)
        {
            Vector3 lo = min, hi = max;
            return point.x >= lo.x && point.x <= hi.x && point.y >= lo.y && point.y <= hi.y && point.z >= lo.z && point.z <= hi.z;
        }

        /// <summary>True when centres and extents compare equal with Vector3's tolerance.</summary>
        public static bool operator ==(Bounds lhs, Bounds rhs) => lhs.center == rhs.center && lhs.extents == rhs.extents;

        /// <summary>Negation of ==.</summary>
        public static bool operator !=(Bounds lhs, Bounds rhs) => !(lhs == rhs);

        /// <summary>Exact equality of centre and extents.</summary>
        public bool Equals(Bounds other) => center.Equals(other.center) && extents.Equals(other.extents);

        /// <summary>Exact equality with another Bounds.</summary>
        public override bool Equals(object other) => other is Bounds bounds && Equals(bounds);

        /// <summary>Hash of centre and extents.</summary>
        public override int GetHashCode() => center.GetHashCode() ^ (extents.GetHashCode() << 2);

        /// <summary>Returns "Center: (x, y, z), Extents: (x, y, z)" with two decimals.</summary>
        public override string ToString() => ToString(null, null);

        /// <summary>Returns "Center: …, Extents: …" with the given number format.</summary>
        public string ToString(string format) => ToString(format, null);

        /// <summary>Returns "Center: …, Extents: …" with the given number format and provider (invariant culture by default).</summary>
        public string ToString(string format, IFormatProvider formatProvider)
        {
            if (string.IsNullOrEmpty(format)) format = "F2";
            if (formatProvider == null) formatProvider = CultureInfo.InvariantCulture.NumberFormat;
            return "Center: " + Format(m_Center, format, formatProvider) + ", Extents: " + Format(m_Extents, format, formatProvider);
        }

        static string Format(Vector3 v, string format, IFormatProvider provider) =>
            "(" + v.x.ToString(format, provider) + ", " + v.y.ToString(format, provider) + ", " + v.z.ToString(format, provider) + ")";
    }
}
