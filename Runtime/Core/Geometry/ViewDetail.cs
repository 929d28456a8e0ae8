using System;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Distance-based detail of the tube mesh: beyond a detail distance D the adaptive rings' along-rope tolerance
    /// (<see cref="TubeMeshSettings.RingTolerance"/>) grows in proportion to the view distance d, so the tolerance seen
    /// from the viewer — a length over the distance, an angle — stays what it is at D. A rope at 2 D draws its bent
    /// segments with 1/sqrt(2) of their rings, and at 16 D/t (the tolerance's upper bound of 16) with a quarter. From
    /// <see cref="FewerSidesDistance"/>·D on it may also draw half its sides (<see cref="RadialSegments"/>): the halved
    /// polygon is at most 4 times as deep, seen from at least 4 times as far, and the tolerance — a multiple of the drawn
    /// polygon's depth — is divided by that ratio, so it reaches 16 only about 4 times farther. Pure functions in the
    /// caller's units (m).
    /// </summary>
    public static class ViewDetail
    {
        /// <summary>Distance, in detail distances, from which a rope draws <see cref="FewerSides"/> (4.4 D).</summary>
        public const float FewerSidesDistance = 4.4f;

        /// <summary>
        /// Distance, in detail distances, below which a rope drawn with fewer sides takes its full count again (4 D: the
        /// halved polygon's depth, at most 4 times the full one's, then spans no larger an angle than the full one at D).
        /// </summary>
        public const float AllSidesDistance = 4f;

        /// <summary>Half of <paramref name="radialSegments"/>, rounded up, at least <see cref="RopeParameters.RadialSegments"/>.Min (3).</summary>
        public static int FewerSides(int radialSegments)
        {
            RopeParameters.Check(radialSegments, RopeParameters.RadialSegments.Row);
            return Math.Max(RopeParameters.RadialSegments.Min, (radialSegments + 1) / 2);
        }

        /// <summary>
        /// The side count for a rope seen from <paramref name="viewDistance"/> (m): <paramref name="radialSegments"/>, or
        /// <see cref="FewerSides"/> of it from <see cref="FewerSidesDistance"/>·D on, kept down to <see cref="AllSidesDistance"/>·D
        /// when <paramref name="drawnBefore"/> (the count the rope drew last) is already the smaller (a band against
        /// flicker). <paramref name="detailDistance"/> 0 (off) or a distance that is not a number: radialSegments.
        /// </summary>
        public static int RadialSegments(int radialSegments, float detailDistance, float viewDistance, int drawnBefore)
        {
            int fewer = FewerSides(radialSegments);
            RopeParameters.Check(detailDistance, RopeParameters.DetailDistance.Row);
            if (!(detailDistance > 0f) || fewer == radialSegments) return radialSegments;
            float from = drawnBefore == fewer ? AllSidesDistance : FewerSidesDistance;
            return viewDistance >= (double)from * detailDistance ? fewer : radialSegments;
        }

        /// <summary>
        /// The side count and ring tolerance for a rope of <paramref name="radialSegments"/> sides at
        /// <paramref name="ringTolerance"/> seen from <paramref name="viewDistance"/> (m): <see cref="RadialSegments"/>
        /// (all of them where <paramref name="keepSides"/>, e.g. a broken rope, whose burrs' strands are counted from its
        /// sides) and the tolerance for that count. <paramref name="drawnBefore"/>: the side count the rope drew last.
        /// Detail distance 0 (off) or a distance that is not a number: radialSegments and ringTolerance.
        /// </summary>
        public static void Choose(int radialSegments, float ringTolerance, float detailDistance, float viewDistance, int drawnBefore, bool keepSides,
            out int sides, out float tolerance)
        {
            sides = keepSides ? radialSegments : RadialSegments(radialSegments, detailDistance, viewDistance, drawnBefore);
            tolerance = RingTolerance(ringTolerance, detailDistance, viewDistance, radialSegments, sides);
        }

        /// <summary>
        /// <see cref="RingTolerance(float, float, float)"/> for a rope drawn with <paramref name="drawnRadialSegments"/>
        /// sides instead of its <paramref name="radialSegments"/> (<see cref="RadialSegments"/>): the tolerance is a multiple
        /// of the drawn polygon's depth, so the scale is divided by how much deeper that polygon is, and the along-rope error
        /// seen from the viewer stays what the full polygon's tolerance gives at D (never below 1).
        /// </summary>
        public static float RingTolerance(float ringTolerance, float detailDistance, float viewDistance, int radialSegments, int drawnRadialSegments)
        {
            RopeParameters.Check(radialSegments, RopeParameters.RadialSegments.Row);
            RopeParameters.Check(drawnRadialSegments, RopeParameters.RadialSegments.Row);
            double deeper = (double)RingNeed.Tolerance(drawnRadialSegments) / RingNeed.Tolerance(radialSegments);
            return Scaled(ringTolerance, detailDistance, viewDistance, deeper);
        }

        /// <summary>
        /// The ring tolerance for a rope seen from <paramref name="viewDistance"/> (m): <paramref name="ringTolerance"/>
        /// (range <see cref="RopeParameters.RingTolerance"/>) up to <paramref name="detailDistance"/> (m, range
        /// <see cref="RopeParameters.DetailDistance"/>; 0 turns the scaling off), beyond it ringTolerance · d / D, at most
        /// <see cref="RopeParameters.RingTolerance"/>.Max. A distance that is not a number gives ringTolerance.
        /// </summary>
        public static float RingTolerance(float ringTolerance, float detailDistance, float viewDistance) =>
            Scaled(ringTolerance, detailDistance, viewDistance, 1.0);

        /// <summary>ringTolerance · d / (D · <paramref name="deeper"/>) beyond D, within [1, 16]; ringTolerance up to D (see the overloads).</summary>
        private static float Scaled(float ringTolerance, float detailDistance, float viewDistance, double deeper)
        {
            RopeParameters.Check(ringTolerance, RopeParameters.RingTolerance.Row);
            RopeParameters.Check(detailDistance, RopeParameters.DetailDistance.Row);
            // NaN compares false: full detail
            if (!(detailDistance > 0f) || !(viewDistance > detailDistance)) return ringTolerance;
            double scaled = (double)ringTolerance * viewDistance / (detailDistance * deeper);
            if (scaled <= RopeParameters.RingTolerance.Min) return RopeParameters.RingTolerance.Min;
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
