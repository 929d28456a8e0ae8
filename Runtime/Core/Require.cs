using System;
using System.Globalization;

namespace HookeRope
{
    /// <summary>
    /// Range checks for validated settings and arguments: each returns the value when it lies in the range and
    /// otherwise throws <see cref="ArgumentOutOfRangeException"/> whose message names the parameter and the range,
    /// e.g. "Spread must be finite and in [0, 1.4] rad.". The message is built only on the throwing path.
    /// </summary>
    internal static class Require
    {
        /// <summary>Value in [min, max]; message "name must be in [min, max] unit.".</summary>
        internal static int InRange(int value, int min, int max, string name, string unit = "")
        {
            if (value < min || value > max)
                throw new ArgumentOutOfRangeException(name, value, name + " must be in [" + Format(min) + ", " + Format(max) + "]" + Suffix(unit) + ".");
            return value;
        }

        /// <summary>Finite value in [min, max].</summary>
        internal static float InClosedRange(float value, float min, float max, string name, string unit = "") =>
            Check(value, min, true, max, true, name, unit);

        /// <summary>Finite value in (min, max].</summary>
        internal static float InOpenClosedRange(float value, float min, float max, string name, string unit = "") =>
            Check(value, min, false, max, true, name, unit);

        /// <summary>Finite value in [min, max).</summary>
        internal static float InClosedOpenRange(float value, float min, float max, string name, string unit = "") =>
            Check(value, min, true, max, false, name, unit);

        private static float Check(float value, float min, bool minInclusive, float max, bool maxInclusive, string name, string unit)
        {
            bool ok = float.IsFinite(value)
                && (minInclusive ? value >= min : value > min)
                && (maxInclusive ? value <= max : value < max);
            if (!ok)
            {
                string range = (minInclusive ? "[" : "(") + Format(min) + ", " + Format(max) + (maxInclusive ? "]" : ")");
                throw new ArgumentOutOfRangeException(name, value, name + " must be finite and in " + range + Suffix(unit) + ".");
            }
            return value;
        }

        private static string Format(int value) => value.ToString(CultureInfo.InvariantCulture);

        private static string Format(float value) => value.ToString(CultureInfo.InvariantCulture);

        private static string Suffix(string unit) => string.IsNullOrEmpty(unit) ? "" : " " + unit;
    }
}
