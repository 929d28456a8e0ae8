using System;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Puts the drawn ends of a rope exactly on their attachments. The solver steps at the fixed rate, so positions
    /// interpolated for a rendered frame trail a hand or harness drawn at its live pose by up to one fixed step
    /// (18 cm at 8.9 m/s and 50 Hz). Each end's offset (live attachment − interpolated end, m) is added along the rope
    /// piece it holds: linearly fading to the other end of a piece held at both ends, whole to a piece held at one
    /// end only (a broken or free-ended rope moves with its holder). Pieces are split at broken segments.
    /// </summary>
    internal static class EndAlignment
    {
        /// <summary>
        /// Adds the end offsets (m) to the positions <paramref name="x"/>, <paramref name="y"/>, <paramref name="z"/> (m)
        /// of a chain whose segment j joins particles j and j + 1 and is broken where <paramref name="broken"/>[j].
        /// Allocation-free.
        /// </summary>
        public static void Apply(Span<float> x, Span<float> y, Span<float> z, ReadOnlySpan<bool> broken,
            bool startHeld, Float3 startOffset, bool endHeld, Float3 endOffset)
        {
            int n = x.Length;
            int first = 0;
            for (int j = 0; j < n; j++)
            {
                bool pieceEnds = j == n - 1 || broken[j];
                if (!pieceEnds) continue;
                int last = j;
                bool fromStart = startHeld && first == 0, fromEnd = endHeld && last == n - 1;
                if (fromStart || fromEnd)
                {
                    for (int i = first; i <= last; i++)
                    {
                        float toEnd = last > first ? (float)(i - first) / (last - first) : 0.5f;
                        float ws = fromStart ? (fromEnd ? 1f - toEnd : 1f) : 0f;
                        float we = fromEnd ? (fromStart ? toEnd : 1f) : 0f;
                        x[i] += ws * startOffset.X + we * endOffset.X;
                        y[i] += ws * startOffset.Y + we * endOffset.Y;
                        z[i] += ws * startOffset.Z + we * endOffset.Z;
                    }
                }
                first = j + 1;
            }
        }
    }
}
