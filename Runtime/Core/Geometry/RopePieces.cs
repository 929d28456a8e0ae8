using System;

namespace HookeRope.Geometry
{
    /// <summary>The unbroken pieces of a rope and the mirrored Catmull–Rom control points of a segment in one, as the tube mesh sees them.</summary>
    internal static class RopePieces
    {
        /// <summary>
        /// Finds the next intact piece at or after <paramref name="segment"/> of a rope of <paramref name="n"/> segments:
        /// segments [a, b) with no break among them (an empty span means nothing is broken). Advances
        /// <paramref name="segment"/> to b; false when there is none.
        /// </summary>
        public static bool Next(ReadOnlySpan<bool> brokenSegments, int n, ref int segment, out int a, out int b)
        {
            // the same walk as flag by flag (skip broken segments, then take unbroken ones), with the span searches
            if (segment < n)
            {
                if (brokenSegments.Length == 0) { a = segment; segment = n; }
                else
                {
                    int intact = brokenSegments.Slice(segment, n - segment).IndexOf(false);
                    segment = intact < 0 ? n : segment + intact;
                    a = segment;
                    int broken = segment < n ? brokenSegments.Slice(segment, n - segment).IndexOf(true) : -1;
                    segment = broken < 0 ? n : segment + broken;
                }
            }
            else a = segment;
            b = segment;
            return a < n;
        }

        /// <summary>Largest tangent of the centre curve at a particle, in lengths of the shorter segment beside it.</summary>
        public const float TangentLimit = 3f;

        /// <summary>
        /// The four control points p0 … p3 of segment <paramref name="j"/> of piece [a, b], relative to
        /// (<paramref name="ox"/>, <paramref name="oy"/>, <paramref name="oz"/>): the segment's particles and their
        /// neighbours, mirrored (p0 = 2p1 − p2, p3 = 2p2 − p1) at the piece's ends. The uniform Catmull–Rom curve through
        /// them is the cubic Hermite with the tangents m1 = (p2 − p0)/2 and m2 = (p3 − p1)/2; a tangent longer than
        /// <see cref="TangentLimit"/> times the shorter of the two segments at its particle is shortened to that length by
        /// moving p0 (or p3) to the virtual point p2 − 2m1 (p1 + 2m2), so a segment squeezed between longer ones does not
        /// overshoot and loop back (the one-dimensional monotonicity bound of a Hermite cubic). Where the limit is idle
        /// (every rope whose neighbouring segments differ by less than about 5×) the points are the particles, bit for bit.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        public static void ControlPoints(int j, int a, int b, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            float ox, float oy, float oz,
            out float p0x, out float p0y, out float p0z, out float p1x, out float p1y, out float p1z,
            out float p2x, out float p2y, out float p2z, out float p3x, out float p3y, out float p3z)
        {
            p1x = x[j] - ox; p1y = y[j] - oy; p1z = z[j] - oz;
            p2x = x[j + 1] - ox; p2y = y[j + 1] - oy; p2z = z[j + 1] - oz;
            float ex = p2x - p1x, ey = p2y - p1y, ez = p2z - p1z;
            float chord2 = ex * ex + ey * ey + ez * ez;
            if (j - 1 >= a)
            {
                p0x = x[j - 1] - ox; p0y = y[j - 1] - oy; p0z = z[j - 1] - oz;
                Limit(ref p0x, ref p0y, ref p0z, p1x, p1y, p1z, p2x, p2y, p2z, chord2);
            }
            else { p0x = p1x * 2f - p2x; p0y = p1y * 2f - p2y; p0z = p1z * 2f - p2z; }
            if (j + 2 <= b)
            {
                p3x = x[j + 2] - ox; p3y = y[j + 2] - oy; p3z = z[j + 2] - oz;
                Limit(ref p3x, ref p3y, ref p3z, p2x, p2y, p2z, p1x, p1y, p1z, chord2);
            }
            else { p3x = p2x * 2f - p1x; p3y = p2y * 2f - p1y; p3z = p2z * 2f - p1z; }
        }

        /// <summary>
        /// The outer control point q of a segment end p (the segment's other end o, chord² = |o − p|²): when the tangent at
        /// p, (o − q)/2, is longer than <see cref="TangentLimit"/> × min(|p − q|, |o − p|), q moves to o − 2m with m that
        /// tangent shortened to the limit. Untouched otherwise (and for non-finite input).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static void Limit(ref float qx, ref float qy, ref float qz, float px, float py, float pz, float ox, float oy, float oz, float chord2)
        {
            float dx = px - qx, dy = py - qy, dz = pz - qz;
            float outer2 = dx * dx + dy * dy + dz * dz;
            float mx = 0.5f * (ox - qx), my = 0.5f * (oy - qy), mz = 0.5f * (oz - qz);
            float tangent2 = mx * mx + my * my + mz * mz;
            float shorter2 = outer2 < chord2 ? outer2 : chord2;
            float limit2 = TangentLimit * TangentLimit * shorter2;
            if (!(tangent2 > limit2)) return;
            float scale = MathF.Sqrt(limit2 / tangent2);
            qx = ox - 2f * (mx * scale); qy = oy - 2f * (my * scale); qz = oz - 2f * (mz * scale);
        }

        /// <summary>Bitwise equality of two spans of floats (−0 differs from +0, a NaN equals only the same NaN): an input counts as unchanged only when it is the same bits.</summary>
        public static bool SameBits(ReadOnlySpan<float> now, ReadOnlySpan<float> before) =>
            System.Runtime.InteropServices.MemoryMarshal.AsBytes(now).SequenceEqual(System.Runtime.InteropServices.MemoryMarshal.AsBytes(before));
    }
}
