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
            bool hasBroken = brokenSegments.Length > 0;
            while (segment < n && hasBroken && brokenSegments[segment]) segment++;
            a = segment;
            while (segment < n && !(hasBroken && brokenSegments[segment])) segment++;
            b = segment;
            return a < n;
        }

        /// <summary>
        /// The four control points p0 … p3 of segment <paramref name="j"/> of piece [a, b], relative to
        /// (<paramref name="ox"/>, <paramref name="oy"/>, <paramref name="oz"/>): the segment's particles and their
        /// neighbours, mirrored (p0 = 2p1 − p2, p3 = 2p2 − p1) at the piece's ends.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        public static void ControlPoints(int j, int a, int b, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            float ox, float oy, float oz,
            out float p0x, out float p0y, out float p0z, out float p1x, out float p1y, out float p1z,
            out float p2x, out float p2y, out float p2z, out float p3x, out float p3y, out float p3z)
        {
            p1x = x[j] - ox; p1y = y[j] - oy; p1z = z[j] - oz;
            p2x = x[j + 1] - ox; p2y = y[j + 1] - oy; p2z = z[j + 1] - oz;
            if (j - 1 >= a) { p0x = x[j - 1] - ox; p0y = y[j - 1] - oy; p0z = z[j - 1] - oz; }
            else { p0x = p1x * 2f - p2x; p0y = p1y * 2f - p2y; p0z = p1z * 2f - p2z; }
            if (j + 2 <= b) { p3x = x[j + 2] - ox; p3y = y[j + 2] - oy; p3z = z[j + 2] - oz; }
            else { p3x = p2x * 2f - p1x; p3y = p2y * 2f - p1y; p3z = p2z * 2f - p1z; }
        }

        /// <summary>Bitwise equality of two spans of floats (−0 differs from +0, a NaN equals only the same NaN): an input counts as unchanged only when it is the same bits.</summary>
        public static bool SameBits(ReadOnlySpan<float> now, ReadOnlySpan<float> before) =>
            System.Runtime.InteropServices.MemoryMarshal.AsBytes(now).SequenceEqual(System.Runtime.InteropServices.MemoryMarshal.AsBytes(before));
    }
}
