using System;
using System.Globalization;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Color: RGBA colour, components 0 to 1. Arithmetic, equality (squared distance below
    /// 1e-10, as Unity compares through Vector4), Lerp and the named colours follow Unity 2022.3's Color.cs.
    /// </summary>
    public struct Color : IEquatable<Color>, IFormattable
    {
        /// <summary>Red component of the color.</summary>
        public float r;
        /// <summary>Green component of the color.</summary>
        public float g;
        /// <summary>Blue component of the color.</summary>
        public float b;
        /// <summary>Alpha component of the color (0 is transparent, 1 is opaque).</summary>
        public float a;

        /// <summary>Unity's Vector4.kEpsilon, the tolerance of == on colours.</summary>
        const float kEpsilon = 0.00001F;

        /// <summary>Constructs a new Color with given r,g,b,a components.</summary>
        public Color(float r, float g, float b, float a) { this.r = r; this.g = g; this.b = b; this.a = a; }

        /// <summary>Constructs a new Color with given r,g,b components and sets a to 1.</summary>
        public Color(float r, float g, float b) { this.r = r; this.g = g; this.b = b; a = 1f; }

        /// <summary>Solid red. RGBA is (1, 0, 0, 1).</summary>
        public static Color red => new Color(1f, 0f, 0f, 1f);

        /// <summary>Solid green. RGBA is (0, 1, 0, 1).</summary>
        public static Color green => new Color(0f, 1f, 0f, 1f);

        /// <summary>Solid blue. RGBA is (0, 0, 1, 1).</summary>
        public static Color blue => new Color(0f, 0f, 1f, 1f);

        /// <summary>Solid white. RGBA is (1, 1, 1, 1).</summary>
        public static Color white => new Color(1f, 1f, 1f, 1f);

        /// <summary>Solid black. RGBA is (0, 0, 0, 1).</summary>
        public static Color black => new Color(0f, 0f, 0f, 1f);

        /// <summary>Yellow. RGBA is (1, 0.92, 0.016, 1).</summary>
        public static Color yellow => new Color(1f, 235f / 255f, 4f / 255f, 1f);

        /// <summary>Cyan. RGBA is (0, 1, 1, 1).</summary>
        public static Color cyan => new Color(0f, 1f, 1f, 1f);

        /// <summary>Magenta. RGBA is (1, 0, 1, 1).</summary>
        public static Color magenta => new Color(1f, 0f, 1f, 1f);

        /// <summary>Gray. RGBA is (0.5, 0.5, 0.5, 1).</summary>
        public static Color gray => new Color(0.5f, 0.5f, 0.5f, 1f);

        /// <summary>English spelling for gray. RGBA is the same (0.5, 0.5, 0.5, 1).</summary>
        public static Color grey => new Color(0.5f, 0.5f, 0.5f, 1f);

        /// <summary>Completely transparent. RGBA is (0, 0, 0, 0).</summary>
        public static Color clear => new Color(0f, 0f, 0f, 0f);

        /// <summary>The grayscale value of the color (Read Only).</summary>
        public float grayscale => 0.299F * r + 0.587F * g + 0.114F * b;

        /// <summary>Access the r, g, b, a components using [0], [1], [2], [3] respectively.</summary>
        public float this[int index]
        {
            get
            {
                switch (index)
                {
                    case 0: return r;
                    case 1: return g;
                    case 2: return b;
                    case 3: return a;
                    default: throw new IndexOutOfRangeException("Invalid Color index(" + index + ")!");
                }
            }
            set
            {
                switch (index)
                {
                    case 0: r = value; break;
                    case 1: g = value; break;
                    case 2: b = value; break;
                    case 3: a = value; break;
                    default: throw new IndexOutOfRangeException("Invalid Color index(" + index + ")!");
                }
            }
        }

        /// <summary>Linearly interpolates between colors a and b by t (t clamped to [0, 1]).</summary>
        public static Color Lerp(Color a, Color b, float t)
        {
            t = t < 0f ? 0f : t > 1f ? 1f : t;
            return LerpUnclamped(a, b, t);
        }

        /// <summary>Linearly interpolates between colors a and b by t, without clamping t.</summary>
        public static Color LerpUnclamped(Color a, Color b, float t) =>
            new Color(a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t, a.a + (b.a - a.a) * t);

        /// <summary>Adds two colors together. Each component is added separately.</summary>
        public static Color operator +(Color a, Color b) => new Color(a.r + b.r, a.g + b.g, a.b + b.b, a.a + b.a);

        /// <summary>Subtracts color b from color a. Each component is subtracted separately.</summary>
        public static Color operator -(Color a, Color b) => new Color(a.r - b.r, a.g - b.g, a.b - b.b, a.a - b.a);

        /// <summary>Multiplies two colors together. Each component is multiplied separately.</summary>
        public static Color operator *(Color a, Color b) => new Color(a.r * b.r, a.g * b.g, a.b * b.b, a.a * b.a);

        /// <summary>Multiplies color a by the float b. Each color component is scaled separately.</summary>
        public static Color operator *(Color a, float b) => new Color(a.r * b, a.g * b, a.b * b, a.a * b);

        /// <summary>Multiplies color a by the float b. Each color component is scaled separately.</summary>
        public static Color operator *(float b, Color a) => new Color(a.r * b, a.g * b, a.b * b, a.a * b);

        /// <summary>Divides color a by the float b. Each color component is scaled separately.</summary>
        public static Color operator /(Color a, float b) => new Color(a.r / b, a.g / b, a.b / b, a.a / b);

        /// <summary>True when the colours are within Unity's Vector4 tolerance (false with NaN components).</summary>
        public static bool operator ==(Color lhs, Color rhs)
        {
            float dr = lhs.r - rhs.r, dg = lhs.g - rhs.g, db = lhs.b - rhs.b, da = lhs.a - rhs.a;
            return dr * dr + dg * dg + db * db + da * da < kEpsilon * kEpsilon;
        }

        /// <summary>Negation of ==.</summary>
        public static bool operator !=(Color lhs, Color rhs) => !(lhs == rhs);

        /// <summary>Exact component-wise equality.</summary>
        public bool Equals(Color other) => r.Equals(other.r) && g.Equals(other.g) && b.Equals(other.b) && a.Equals(other.a);

        /// <summary>Exact component-wise equality with another Color.</summary>
        public override bool Equals(object other) => other is Color color && Equals(color);

        /// <summary>Hash of the four components (as Unity's Vector4 hash).</summary>
        public override int GetHashCode() => r.GetHashCode() ^ (g.GetHashCode() << 2) ^ (b.GetHashCode() >> 2) ^ (a.GetHashCode() >> 1);

        /// <summary>Returns "RGBA(r, g, b, a)" with three decimals.</summary>
        public override string ToString() => ToString(null, null);

        /// <summary>Returns "RGBA(r, g, b, a)" with the given number format.</summary>
        public string ToString(string format) => ToString(format, null);

        /// <summary>Returns "RGBA(r, g, b, a)" with the given number format and provider (invariant culture by default).</summary>
        public string ToString(string format, IFormatProvider formatProvider)
        {
            if (string.IsNullOrEmpty(format)) format = "F3";
            if (formatProvider == null) formatProvider = CultureInfo.InvariantCulture.NumberFormat;
            return "RGBA(" + r.ToString(format, formatProvider) + ", " + g.ToString(format, formatProvider) + ", " +
                   b.ToString(format, formatProvider) + ", " + a.ToString(format, formatProvider) + ")";
        }
    }
}
