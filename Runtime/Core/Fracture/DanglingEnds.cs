using System;
using HookeRope.Geometry;

namespace HookeRope.Fracture
{
    /// <summary>
    /// The two dangling halves of each broken segment, as the tube mesh draws them (issue 17 item 2): the solver parts a
    /// segment at its middle (<see cref="HookeRope.Solver.Rope.BreakSegment"/>), each side keeps half of its rest length,
    /// relaxed (its stored energy went into the recoil), and the mesh continues each piece straight along its end tangent
    /// by that length to the cut, where the cap and the burr sit. Per segment: the drawn length of each half (caller units)
    /// and the radius of each cut end (caller units), written by the owner before a build. Allocated once per topology.
    /// </summary>
    internal sealed class DanglingEnds
    {
        /// <summary>Fraction of a segment where a break parts it.</summary>
        public const float Cut = 0.5f;

        /// <summary>Layout rings closer to the cut than this fraction of the segment are left out (the cut ring replaces them).</summary>
        private const float MinGap = 1e-3f;

        private readonly float[] halfLength;
        private readonly float[] lowerRadius;
        private readonly float[] upperRadius;

        /// <summary>Ends for a rope of <paramref name="segmentCount"/> segments (≥ 1).</summary>
        public DanglingEnds(int segmentCount)
        {
            if (segmentCount < 1) throw new ArgumentOutOfRangeException(nameof(segmentCount), segmentCount, "segmentCount must be in [1, +inf).");
            halfLength = new float[segmentCount];
            lowerRadius = new float[segmentCount];
            upperRadius = new float[segmentCount];
        }

        /// <summary>Number of segments.</summary>
        public int SegmentCount => halfLength.Length;

        /// <summary>Sets the drawn length of each half of broken segment j and the radii of its two cut ends (caller units, finite, ≥ 0).</summary>
        public void Set(int segment, float halfDrawnLength, float lowerCutRadius, float upperCutRadius)
        {
            halfLength[segment] = halfDrawnLength;
            lowerRadius[segment] = lowerCutRadius;
            upperRadius[segment] = upperCutRadius;
        }

        /// <summary>Drawn length of each half of segment j (caller units).</summary>
        public float HalfLength(int segment) => halfLength[segment];

        /// <summary>Radius of the cut end of segment j on the side of particle j (upper false) or j + 1 (true), caller units.</summary>
        public float CutRadius(int segment, bool upper) => upper ? upperRadius[segment] : lowerRadius[segment];

        /// <summary>
        /// Rings a dangling half of <paramref name="segment"/> adds to its piece: the layout's rings inside the half (the
        /// lower half t ∈ (0, ½), the upper t ∈ (½, 1)), and the ring on the cut.
        /// </summary>
        public static int RingCount(RingLayout layout, int segment, bool upper)
        {
            int count = 1;
            ReadOnlySpan<float> fractions = layout.RingFractions;
            int first = layout.FirstRing(segment), end = layout.FirstRing(segment + 1);
            for (int k = first + 1; k < end; k++)
                if (InHalf(fractions[k], upper)) count++;
            return count;
        }

        /// <summary>
        /// Writes the stations of a dangling half into <paramref name="rings"/> (at least <see cref="RingCount"/> entries),
        /// ordered from the piece's end particle out to the cut: layout ring indices, then −1 for the cut. Returns the count.
        /// </summary>
        public static int Stations(RingLayout layout, int segment, bool upper, Span<int> rings)
        {
            ReadOnlySpan<float> fractions = layout.RingFractions;
            int first = layout.FirstRing(segment), end = layout.FirstRing(segment + 1);
            int count = 0;
            if (upper)
            {
                for (int k = end - 1; k > first; k--)
                    if (InHalf(fractions[k], true)) rings[count++] = k;
            }
            else
            {
                for (int k = first + 1; k < end; k++)
                    if (InHalf(fractions[k], false)) rings[count++] = k;
            }
            rings[count++] = -1;
            return count;
        }

        /// <summary>Distance of fraction t from the half's end particle as a share of the half (0 at the particle, 1 at the cut).</summary>
        public static float ShareOfHalf(float t, bool upper) => upper ? (1f - t) / (1f - Cut) : t / Cut;

        /// <summary>Largest <see cref="RingCount"/> over the segments of a layout.</summary>
        public static int MaxRingCount(RingLayout layout)
        {
            int most = 1;
            for (int j = 0; j < layout.SegmentCount; j++)
            {
                int m = layout.RingsIn(j) + 1;
                if (m > most) most = m;
            }
            return most;
        }

        private static bool InHalf(float t, bool upper) => upper ? t > Cut + MinGap : t > 0f && t < Cut - MinGap;
    }
}
