using System;

namespace HookeRope.Radius
{
    /// <summary>
    /// Shape of the Zone-mode neck: r/r_rope = sqrt(1 − (1 − ρ²)·(1 − x²)²) with x = 2|u| the distance from the
    /// waist in half-zones (u = (s − s_waist)/z, s the rest arc length, z the zone's rest length) and ρ the waist
    /// ratio. Near the waist r² ≈ ρ²r_rope² + 2(1 − ρ²)r_rope²x², the hyperbola of Chen et al. eq. 18
    /// (x²/a² − y²/b² = 1); at the zone's edges (x = 1) radius and slope meet the rope's (C¹: the slope goes to 0 like
    /// (1 − x)), so there is no shoulder. ρ = 1 is the straight rope.
    /// </summary>
    internal static class NeckProfile
    {
        /// <summary>
        /// Radius ratio r/r_rope (unitless, in [ρ, 1]) at <paramref name="zoneFraction"/> u = (s − s_waist)/z
        /// (unitless; |u| ≥ ½ is outside the neck and gives 1) for the squared waist ratio
        /// <paramref name="waistSquared"/> ρ² ∈ [0, 1].
        /// </summary>
        public static float Ratio(float zoneFraction, float waistSquared)
        {
            float x = 2f * zoneFraction;
            float g = 1f - x * x;
            if (!(g > 0f) || waistSquared >= 1f) return 1f;
            float square = 1f - (1f - waistSquared) * g * g;
            return square > 0f ? MathF.Sqrt(square) : 0f;
        }

        /// <summary>
        /// Slope d(r/r_rope)/dx (unitless, per half-zone) of <see cref="Ratio"/> at x = 2u ∈ [−1, 1] for waist ratio
        /// <paramref name="waistRatio"/> ρ ∈ (0, 1]: 2(1 − ρ²)x(1 − x²) / sqrt(1 − (1 − ρ²)(1 − x²)²); 0 at x = 0 and at
        /// the edges x = ±1.
        /// </summary>
        public static double Slope(double x, double waistRatio)
        {
            double g = 1.0 - x * x;
            if (!(g > 0.0)) return 0.0;
            double c = 1.0 - waistRatio * waistRatio;
            return 2.0 * c * x * g / Math.Sqrt(1.0 - c * g * g);
        }
    }
}
