using System;

namespace HookeRope.Radius
{
    /// <summary>
    /// Poisson thinning (Chen et al. 2022, eq. 16): r/R = sqrt(1 + 2ν(L/l − 1)), from the volume change
    /// (1 − 2ν)·ε of a segment with rest length L stretched to l. ν = 0.5 keeps the volume.
    /// </summary>
    public static class PoissonRadius
    {
        /// <summary>Largest rest/current length ratio L/l used (l is clamped to at least L/4), unitless.</summary>
        public const double MaxCompressionRatio = 4.0;

        /// <summary>Smallest value of the square-root argument (so r ≥ 0.01·R), unitless.</summary>
        public const double MinSquareRatio = 1e-4;

        /// <summary>
        /// Radius ratio r/R (unitless) of a segment with rest length <paramref name="restLength"/> (m) and
        /// current length <paramref name="currentLength"/> (m) for Poisson ratio <paramref name="poissonRatio"/>.
        /// Clamps: L/l ≤ <see cref="MaxCompressionRatio"/> (a zero or negative length counts as L/4) and the
        /// square-root argument ≥ <see cref="MinSquareRatio"/>, so compression with a negative ν never gives NaN.
        /// When <paramref name="slackKeepsRestRadius"/> is true a segment shorter than its rest length counts as
        /// unstretched (a slack rope buckles, it is not compressed).
        /// </summary>
        public static double Ratio(double restLength, double currentLength, double poissonRatio, bool slackKeepsRestRadius)
        {
            if (!(restLength > 0.0)) return 1.0;
            double inverseStretch;
            if (!(currentLength > 0.0)) inverseStretch = MaxCompressionRatio;
            else inverseStretch = Math.Min(restLength / currentLength, MaxCompressionRatio);
            if (slackKeepsRestRadius && inverseStretch > 1.0) inverseStretch = 1.0;
            double square = 1.0 + 2.0 * poissonRatio * (inverseStretch - 1.0);
            if (!(square > MinSquareRatio)) square = MinSquareRatio;
            return Math.Sqrt(square);
        }

        /// <summary>
        /// Strain l/L − 1 (unitless) at which the Poisson radius ratio reaches <paramref name="radiusFraction"/>,
        /// or +∞ when it never does (ν ≤ 0, or the fraction is at or below the asymptote sqrt(1 − 2ν)).
        /// </summary>
        public static double StrainAtRatio(double radiusFraction, double poissonRatio)
        {
            if (radiusFraction >= 1.0) return 0.0;
            if (!(poissonRatio > 0.0)) return double.PositiveInfinity;
            double inverseStretch = 1.0 + (radiusFraction * radiusFraction - 1.0) / (2.0 * poissonRatio);
            if (!(inverseStretch > 0.0)) return double.PositiveInfinity;
            return 1.0 / inverseStretch - 1.0;
        }
    }
}
