using System;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Where the rings of a tube sit along the rope: segment j holds <c>RingsIn(j)</c> rings at fractions
    /// t = i/RingsIn(j), i = 0 … RingsIn(j) − 1, and one last ring sits at the last particle (t = 1 of the
    /// last segment). Ring k at particle j is <c>FirstRing(j)</c>. Immutable; allocated once.
    /// </summary>
    internal sealed class RingLayout
    {
        /// <summary>Largest number of rings in one segment.</summary>
        public const int MaxRingsPerSegment = 1024;

        private readonly int[] firstRing;
        private readonly int[] ringSegment;
        private readonly float[] ringFraction;

        /// <summary>Uniform layout: <paramref name="ringsPerSegment"/> (1 … 1024) rings in each of <paramref name="segmentCount"/> (≥ 1) segments.</summary>
        public RingLayout(int segmentCount, int ringsPerSegment)
            : this(Uniform(segmentCount, ringsPerSegment))
        {
        }

        /// <summary>Layout with a ring count (1 … 1024) per segment.</summary>
        public RingLayout(ReadOnlySpan<int> ringsPerSegment)
        {
            int n = ringsPerSegment.Length;
            if (n < 1) throw new ArgumentException("ringsPerSegment must hold at least one segment (1 … any).", nameof(ringsPerSegment));
            firstRing = new int[n + 1];
            int total = 0;
            for (int j = 0; j < n; j++)
            {
                int m = ringsPerSegment[j];
                if (m < 1 || m > MaxRingsPerSegment)
                    throw new ArgumentOutOfRangeException(nameof(ringsPerSegment), m, "every ring count must be in [1, 1024].");
                firstRing[j] = total;
                total += m;
            }
            firstRing[n] = total;
            ringSegment = new int[total + 1];
            ringFraction = new float[total + 1];
            for (int j = 0; j < n; j++)
            {
                int m = ringsPerSegment[j];
                for (int i = 0; i < m; i++)
                {
                    ringSegment[firstRing[j] + i] = j;
                    ringFraction[firstRing[j] + i] = (float)i / m;
                }
            }
            ringSegment[total] = n - 1;
            ringFraction[total] = 1f;
        }

        /// <summary>Number of segments.</summary>
        public int SegmentCount => firstRing.Length - 1;

        /// <summary>Number of rings of the intact rope (Σ RingsIn + 1).</summary>
        public int RingCount => ringSegment.Length;

        /// <summary>Index of the ring at particle <paramref name="particle"/> (0 … SegmentCount).</summary>
        public int FirstRing(int particle) => firstRing[particle];

        /// <summary>Rings in segment <paramref name="segment"/>.</summary>
        public int RingsIn(int segment) => firstRing[segment + 1] - firstRing[segment];

        /// <summary>Segment of each ring.</summary>
        public ReadOnlySpan<int> RingSegments => ringSegment;

        /// <summary>Fraction t ∈ [0, 1] of each ring inside its segment.</summary>
        public ReadOnlySpan<float> RingFractions => ringFraction;

        /// <summary>
        /// A layout with <paramref name="ringsPerSegment"/> rings per segment, and more in the segments that overlap
        /// the rest-arc interval [<paramref name="zoneCenter"/> ± <paramref name="zoneLength"/>/2] (m), so that the
        /// zone holds about <paramref name="ringsInZone"/> rings (capped at 1024 per segment). For the neck zone.
        /// </summary>
        public static RingLayout Refined(ReadOnlySpan<float> restLengths, int ringsPerSegment, float zoneCenter, float zoneLength, int ringsInZone)
        {
            int n = restLengths.Length;
            int[] counts = Uniform(n, ringsPerSegment);
            if (zoneLength > 0f && ringsInZone > 0)
            {
                float start = zoneCenter - 0.5f * zoneLength;
                float end = zoneCenter + 0.5f * zoneLength;
                float arc = 0f;
                for (int j = 0; j < n; j++)
                {
                    float next = arc + restLengths[j];
                    if (next > start && arc < end)
                    {
                        double wanted = Math.Ceiling(ringsInZone * (double)restLengths[j] / zoneLength);
                        int m = wanted > MaxRingsPerSegment ? MaxRingsPerSegment : (int)wanted;
                        if (m > counts[j]) counts[j] = m;
                    }
                    arc = next;
                }
            }
            return new RingLayout(counts);
        }

        private static int[] Uniform(int segmentCount, int ringsPerSegment)
        {
            if (segmentCount < 1)
                throw new ArgumentOutOfRangeException(nameof(segmentCount), segmentCount, "segmentCount must be in [1, +inf).");
            Require.InRange(ringsPerSegment, 1, MaxRingsPerSegment, nameof(ringsPerSegment));
            int[] counts = new int[segmentCount];
            Array.Fill(counts, ringsPerSegment);
            return counts;
        }
    }
}
