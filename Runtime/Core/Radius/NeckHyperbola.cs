using System;

namespace HookeRope.Radius
{
    /// <summary>
    /// The neck profile of Chen et al. 2022, eq. 18: x²/a² − y²/b² = 1 with a² + b² = r_min² and the ends
    /// (y = ±l/2) at x = r_min, so r(y) = a·sqrt(1 + y²/b²). The printed solution
    /// a = (sqrt(l² + 16 r_min²) − l)/4 cancels catastrophically when l ≫ r_min; the cancellation-free forms
    /// a = 4 r_min²/(sqrt(l² + 16 r_min²) + l) and b² = 2 r_min² l/(sqrt(l² + 16 r_min²) + l) are used.
    /// </summary>
    public static class NeckHyperbola
    {
        /// <summary>Neck (waist) radius a in metres for neck length <paramref name="length"/> (m) and end radius <paramref name="endRadius"/> (m); cancellation-free.</summary>
        public static double WaistRadius(double length, double endRadius)
        {
            double rr = endRadius * endRadius;
            double root = Math.Sqrt(length * length + 16.0 * rr);
            double denominator = root + length;
            return denominator > 0.0 ? 4.0 * rr / denominator : endRadius;
        }

        /// <summary>Squared semi-axis b² in m² for neck length <paramref name="length"/> (m) and end radius <paramref name="endRadius"/> (m); cancellation-free.</summary>
        public static double AxisSquared(double length, double endRadius)
        {
            double rr = endRadius * endRadius;
            double root = Math.Sqrt(length * length + 16.0 * rr);
            double denominator = root + length;
            return denominator > 0.0 ? 2.0 * rr * length / denominator : 0.0;
        }

        /// <summary>Waist radius a in metres in the printed form (sqrt(l² + 16 r_min²) − l)/4 (loses digits when l ≫ r_min; for tests and documentation).</summary>
        public static double WaistRadiusPrinted(double length, double endRadius) =>
            (Math.Sqrt(length * length + 16.0 * endRadius * endRadius) - length) / 4.0;

        /// <summary>Squared semi-axis b² in m² in the printed form (sqrt(l² + 16 r_min²) − l)·l/8.</summary>
        public static double AxisSquaredPrinted(double length, double endRadius) =>
            (Math.Sqrt(length * length + 16.0 * endRadius * endRadius) - length) * length / 8.0;

        /// <summary>Float32 waist radius a in metres (cancellation-free; what the per-step code uses).</summary>
        public static float WaistRadius(float length, float endRadius)
        {
            float rr = endRadius * endRadius;
            float denominator = MathF.Sqrt(length * length + 16f * rr) + length;
            return denominator > 0f ? 4f * rr / denominator : endRadius;
        }

        /// <summary>Float32 squared semi-axis b² in m² (cancellation-free).</summary>
        public static float AxisSquared(float length, float endRadius)
        {
            float rr = endRadius * endRadius;
            float denominator = MathF.Sqrt(length * length + 16f * rr) + length;
            return denominator > 0f ? 2f * rr * length / denominator : 0f;
        }

        /// <summary>
        /// Radius r(y) = a·sqrt(1 + y²/b²) in metres at signed distance <paramref name="y"/> (m) from the waist,
        /// for waist radius <paramref name="waist"/> (m) and squared semi-axis <paramref name="axisSquared"/> (m²).
        /// </summary>
        public static double Radius(double y, double waist, double axisSquared) =>
            axisSquared > 0.0 ? waist * Math.Sqrt(1.0 + y * y / axisSquared) : waist;
    }
}
