using System;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Distance-based detail of the tube mesh: beyond a detail distance D the adaptive rings' along-rope tolerance
    /// (<see cref="TubeMeshSettings.RingTolerance"/>) grows in proportion to the view distance d, so the tolerance seen
    /// from the viewer — a length over the distance, an angle — stays what it is at D. A rope at 2 D draws its bent
    /// segments with 1/sqrt(2) of their rings, at 16 D and beyond (the tolerance's upper bound) with a quarter; the
    /// polygon around the tube (its sides) is not changed. Pure functions in the caller's units (m).
    /// </summary>
    public static class ViewDetail
    {
        /// <summary>
        /// The ring tolerance for a rope seen from <paramref name="viewDistance"/> (m): <paramref name="ringTolerance"/>
        /// (range <see cref="RopeParameters.RingTolerance"/>) up to <paramref name="detailDistance"/> (m, range
        /// <see cref="RopeParameters.DetailDistance"/>; 0 turns the scaling off), beyond it ringTolerance · d / D, at most
        /// <see cref="RopeParameters.RingTolerance"/>.Max. A distance that is not a number gives ringTolerance.
        /// </summary>
        public static float RingTolerance(float ringTolerance, float detailDistance, float viewDistance)
        {
            RopeParameters.Check(ringTolerance, RopeParameters.RingTolerance.Row);
            RopeParameters.Check(detailDistance, RopeParameters.DetailDistance.Row);
            // NaN compares false: full detail
            if (!(detailDistance > 0f) || !(viewDistance > detailDistance)) return ringTolerance;
            double scaled = (double)ringTolerance * viewDistance / detailDistance;
            return scaled >= RopeParameters.RingTolerance.Max ? RopeParameters.RingTolerance.Max : (float)scaled;
        }

        /// <summary>
        /// Distance (m) from <paramref name="point"/> to the axis-aligned box around the first <paramref name="count"/>
        /// positions (<paramref name="x"/>, <paramref name="y"/>, <paramref name="z"/>, the same space as the point); 0 inside
        /// it. Never more than the distance to the nearest position, so a rope is never drawn coarser than its nearest
        /// point asks for. +∞ for no positions; NaN when a coordinate is not finite.
        /// </summary>
        public static float DistanceToBox(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, int count, Float3 point)
        {
            if ((uint)count > (uint)x.Length || count > y.Length || count > z.Length)
                throw new ArgumentOutOfRangeException(nameof(count), count, "count must lie in [0, the positions' length]");
            if (count == 0) return float.PositiveInfinity;
            float minX = x[0], maxX = x[0], minY = y[0], maxY = y[0], minZ = z[0], maxZ = z[0];
            bool finite = float.IsFinite(x[0]) && float.IsFinite(y[0]) && float.IsFinite(z[0]);
            for (int i = 1; i < count; i++)
            {
                float px = x[i], py = y[i], pz = z[i];
                finite &= float.IsFinite(px) && float.IsFinite(py) && float.IsFinite(pz);
                if (px < minX) minX = px; else if (px > maxX) maxX = px;
                if (py < minY) minY = py; else if (py > maxY) maxY = py;
                if (pz < minZ) minZ = pz; else if (pz > maxZ) maxZ = pz;
            }
            if (!finite) return float.NaN;
            double dx = Outside(point.X, minX, maxX), dy = Outside(point.Y, minY, maxY), dz = Outside(point.Z, minZ, maxZ);
            return (float)Math.Sqrt(dx * dx + dy * dy + dz * dz);
        }

        /// <summary>How far <paramref name="value"/> lies outside [min, max] (0 inside).</summary>
        private static double Outside(float value, float min, float max) =>
            value < min ? (double)min - value : value > max ? (double)value - max : 0.0;
    }
}
