using System;
using System.Globalization;

namespace HookeRope
{
    /// <summary>
    /// Valid ranges of the <see cref="ElasticRope"/> inspector values (SI units), with the check used by the
    /// property setters (throws) and the clamp used by OnValidate (returns the message to log).
    /// </summary>
    public static class RopeParameterLimits
    {
        /// <summary>Rest length range in metres.</summary>
        public const float MinRestLength = 0.01f, MaxRestLength = 1000f;
        /// <summary>Rest radius range in metres.</summary>
        public const float MinRadius = 1e-4f, MaxRadius = 1f;
        /// <summary>Segment count range.</summary>
        public const int MinSegments = 1, MaxSegments = 1000;
        /// <summary>Young's modulus range in pascals.</summary>
        public const float MinYoungsModulus = 1e3f, MaxYoungsModulus = 1e12f;
        /// <summary>Axial stiffness E·A range in newtons.</summary>
        public const float MinAxialStiffness = 1f, MaxAxialStiffness = 1e10f;
        /// <summary>Material density range in kg/m³.</summary>
        public const float MinDensity = 1f, MaxDensity = 20000f;
        /// <summary>Poisson ratio range (dimensionless); 0.5 keeps the volume.</summary>
        public const float MinPoisson = -1f, MaxPoisson = 0.5f;
        /// <summary>Neck onset radius r_min as a fraction of the rest radius R.</summary>
        public const float MinNeckFraction = 0.01f, MaxNeckFraction = 1f;
        /// <summary>Material defect position as a fraction of the rest length from the start.</summary>
        public const float MinDefectPosition = 0f, MaxDefectPosition = 1f;
        /// <summary>Break radius as a fraction of the rest radius R (0 = off).</summary>
        public const float MinBreakRadiusFraction = 0f, MaxBreakRadiusFraction = 0.99f;
        /// <summary>Break strain range (l/L − 1, dimensionless).</summary>
        public const float MinBreakStrain = 1e-3f, MaxBreakStrain = 10f;
        /// <summary>XPBD damping coefficient β range in seconds.</summary>
        public const float MinDamping = 0f, MaxDamping = 1f;
        /// <summary>Substep range per physics step.</summary>
        public const int MinSubsteps = 1, MaxSubsteps = 1000;
        /// <summary>Iteration range per substep.</summary>
        public const int MinIterations = 1, MaxIterations = 1000;
        /// <summary>Coulomb friction coefficient range (dimensionless).</summary>
        public const float MinFriction = 0f, MaxFriction = 2f;
        /// <summary>Attachment compliance range in m/N (0 = rigid).</summary>
        public const float MinCompliance = 0f, MaxCompliance = 1f;

        /// <summary>Returns <paramref name="value"/> or throws ArgumentOutOfRangeException naming the parameter, its range and unit.</summary>
        public static float Check(float value, float min, float max, string parameter, string unit)
        {
            if (!(value >= min && value <= max))
                throw new ArgumentOutOfRangeException(parameter, value, Describe(parameter, min, max, unit));
            return value;
        }

        /// <summary>Returns <paramref name="value"/> or throws ArgumentOutOfRangeException naming the parameter and its range.</summary>
        public static int Check(int value, int min, int max, string parameter)
        {
            if (value < min || value > max)
                throw new ArgumentOutOfRangeException(parameter, value, Describe(parameter, min, max, ""));
            return value;
        }

        /// <summary>
        /// Clamps <paramref name="value"/> into [min, max] (NaN becomes <paramref name="fallback"/>). Returns the message
        /// to log when it had to change the value, else null.
        /// </summary>
        public static string Clamp(ref float value, float min, float max, float fallback, string parameter, string unit)
        {
            float before = value;
            if (float.IsNaN(value)) value = fallback;
            else if (value < min) value = min;
            else if (value > max) value = max;
            if (before.Equals(value)) return null;
            return string.Format(CultureInfo.InvariantCulture, "{0} = {1} {2} is outside {3}; clamped to {4} {2}.",
                parameter, before, unit, Range(min, max, unit), value).Replace("  ", " ");
        }

        /// <summary>Integer variant of <see cref="Clamp(ref float, float, float, float, string, string)"/>.</summary>
        public static string Clamp(ref int value, int min, int max, string parameter)
        {
            int before = value;
            value = value < min ? min : value > max ? max : value;
            if (before == value) return null;
            return string.Format(CultureInfo.InvariantCulture, "{0} = {1} is outside [{2}, {3}]; clamped to {4}.",
                parameter, before, min, max, value);
        }

        static string Describe(string parameter, float min, float max, string unit) =>
            parameter + " must be in " + Range(min, max, unit);

        static string Range(float min, float max, string unit) =>
            string.Format(CultureInfo.InvariantCulture, "[{0}, {1}]{2}", min, max, unit.Length > 0 ? " " + unit : "");
    }
}
