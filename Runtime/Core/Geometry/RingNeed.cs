using System;
using System.Numerics;
using System.Runtime.InteropServices;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// How many rings a segment of the tube needs so that the drawn surface stays within a tolerance of the smooth
    /// tube it samples. The smooth tube's centre is the uniform Catmull–Rom curve C(t) through the particles (t ∈ [0, 1]
    /// per segment); m evenly spaced rings replace it by chords of Δt = 1/m, and a surface point at radius r from the
    /// centre is linearly interpolated between rings. Its error is at most (Δt²/8)·max|∂²S/∂t²|, where S(t) = C(t) + r·e(t)
    /// and e turns with the tangent at the rate ω (rad per unit t): |∂²S/∂t²| ≤ |C''⊥| + r·ω², C''⊥ being the part of C''
    /// across the chord (the part along it slides points along the curve, it does not move the surface; it is linear
    /// in t, so its largest size is at an end of the segment). So
    /// <code>error(m) ≤ E / m²,   E = (max|C''⊥| + r·max ω²) / 8,   m ≥ sqrt(E / tolerance)</code>
    /// with r and the tolerance in metres. Outside a Zone neck the drawn radius is exact between rings placed at the
    /// particles (the ring radii interpolate the particle radii linearly), so only the centre line and the tilt of the
    /// rings count here; the neck has its own stations (<see cref="RingLayout.Adapted"/>).
    /// </summary>
    internal static class RingNeed
    {
        /// <summary>
        /// Tolerance of the drawn surface as a fraction of the radius for <paramref name="radialSegments"/> sides:
        /// 1 − cos(π/N), the depth of the polygon's own flats below the circle. The tube is then as round along its length
        /// as around it (8 sides: 7.6 %, 16: 1.9 %, 32: 0.48 % of the radius).
        /// </summary>
        public static float Tolerance(int radialSegments) => (float)(1.0 - Math.Cos(Math.PI / Math.Max(3, radialSegments)));

        /// <summary>
        /// Writes into <paramref name="need"/>[j] the (real, unrounded) ring count each segment j ∈ [a, b) of one unbroken
        /// piece needs for a drawn radius <paramref name="radius"/> and a tolerance of <paramref name="tolerance"/>
        /// (both m, &gt; 0), from the particles <paramref name="x"/>, <paramref name="y"/>, <paramref name="z"/> (m) taken
        /// relative to (<paramref name="ox"/>, <paramref name="oy"/>, <paramref name="oz"/>) as the mesh does; the piece's
        /// ends are mirrored as in the mesh's curve. Non-finite geometry or a zero-length segment asks for
        /// <paramref name="cap"/>. Allocation-free.
        /// </summary>
        public static void OfPiece(int a, int b, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            float ox, float oy, float oz, float radius, float tolerance, float cap, Span<float> need)
        {
            float inverseTolerance = 1f / tolerance;
            int lanes = Vector<float>.Count;
            bool vector = VectorPath.Enabled;
            for (int j = a; j < b;)
            {
                // interior segments (both neighbours in the piece, nothing mirrored) a vector of them at a time
                if (vector && j > a && j + lanes + 1 <= b)
                {
                    OfInteriorLanes(j, x, y, z, ox, oy, oz, radius, inverseTolerance, cap, need);
                    j += lanes;
                    continue;
                }
                // the interior's tail too short for a vector: the last vector of interior segments, which ends at segment
                // b − 2, overlapping the ones done (each lane is the scalar's bits, so those are written again unchanged)
                if (vector && j > a && j < b - 1 && b - 1 - lanes > a)
                {
                    OfInteriorLanes(b - 1 - lanes, x, y, z, ox, oy, oz, radius, inverseTolerance, cap, need);
                    j = b - 1;
                    continue;
                }
                need[j] = OfSegment(j, a, b, x, y, z, ox, oy, oz, radius, inverseTolerance, cap);
                j++;
            }
        }

        /// <summary>The need of segment <paramref name="j"/> of piece [a, b] (see <see cref="OfPiece"/>).</summary>
        private static float OfSegment(int j, int a, int b, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            float ox, float oy, float oz, float radius, float inverseTolerance, float cap)
        {
            RopePieces.ControlPoints(j, a, b, x, y, z, ox, oy, oz, out float p0x, out float p0y, out float p0z,
                out float p1x, out float p1y, out float p1z, out float p2x, out float p2y, out float p2z, out float p3x, out float p3y, out float p3z);

            // chord direction
            float ux = p2x - p1x, uy = p2y - p1y, uz = p2z - p1z;
            float chord2 = ux * ux + uy * uy + uz * uz;
            if (!(chord2 > 1e-30f) || !float.IsFinite(chord2)) return cap;
            float inverseChord = 1f / MathF.Sqrt(chord2);
            ux *= inverseChord; uy *= inverseChord; uz *= inverseChord;

            // C''(0) = 2p0 − 5p1 + 4p2 − p3, C''(1) = −p0 + 4p1 − 5p2 + 2p3 (formed as 4p1 − p0 …: the same bits)
            float s0x = 2f * p0x - 5f * p1x + 4f * p2x - p3x, s0y = 2f * p0y - 5f * p1y + 4f * p2y - p3y, s0z = 2f * p0z - 5f * p1z + 4f * p2z - p3z;
            float s1x = 4f * p1x - p0x - 5f * p2x + 2f * p3x, s1y = 4f * p1y - p0y - 5f * p2y + 2f * p3y, s1z = 4f * p1z - p0z - 5f * p2z + 2f * p3z;
            float across0 = AcrossSquared(s0x, s0y, s0z, ux, uy, uz);
            float across1 = AcrossSquared(s1x, s1y, s1z, ux, uy, uz);
            float bend = MathF.Sqrt(MathF.Max(across0, across1));

            // C'(0) = (p2 − p0)/2, C'(1) = (p3 − p1)/2; ω = |C' × C''| / |C'|²
            float turn0 = TurnRateSquared(0.5f * (p2x - p0x), 0.5f * (p2y - p0y), 0.5f * (p2z - p0z), s0x, s0y, s0z);
            float turn1 = TurnRateSquared(0.5f * (p3x - p1x), 0.5f * (p3y - p1y), 0.5f * (p3z - p1z), s1x, s1y, s1z);
            float e = 0.125f * (bend + radius * MathF.Max(turn0, turn1));
            float m = MathF.Sqrt(e * inverseTolerance);
            return float.IsFinite(m) ? MathF.Min(m, cap) : cap;
        }

        /// <summary>
        /// <see cref="OfSegment"/> for the <see cref="Vector{T}.Count"/> interior segments j … j + lanes − 1 at once (each has
        /// both neighbours in the piece): every lane does the scalar's operations in its order (no fused multiply-add), the
        /// branches become selects of lanes computed both ways, and the maxima keep the scalar's NaN (MathF.Max returns NaN
        /// when either is NaN; the values are never −0), so the lanes hold the scalar's bits (tested with
        /// <see cref="VectorPath.Enabled"/> off and on).
        /// </summary>
        private static void OfInteriorLanes(int j, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            float ox, float oy, float oz, float radius, float inverseTolerance, float cap, Span<float> need)
        {
            int lanes = Vector<float>.Count;
            var vox = new Vector<float>(ox);
            var voy = new Vector<float>(oy);
            var voz = new Vector<float>(oz);
            Vector<float> p0x = Load(x, j - 1) - vox, p0y = Load(y, j - 1) - voy, p0z = Load(z, j - 1) - voz;
            Vector<float> p1x = Load(x, j) - vox, p1y = Load(y, j) - voy, p1z = Load(z, j) - voz;
            Vector<float> p2x = Load(x, j + 1) - vox, p2y = Load(y, j + 1) - voy, p2z = Load(z, j + 1) - voz;
            Vector<float> p3x = Load(x, j + 2) - vox, p3y = Load(y, j + 2) - voy, p3z = Load(z, j + 2) - voz;
            Vector<float> ex = p2x - p1x, ey = p2y - p1y, ez = p2z - p1z;
            Vector<float> chord2 = ex * ex + ey * ey + ez * ez;
            LimitLanes(ref p0x, ref p0y, ref p0z, p1x, p1y, p1z, p2x, p2y, p2z, chord2);
            LimitLanes(ref p3x, ref p3y, ref p3z, p2x, p2y, p2z, p1x, p1y, p1z, chord2);

            var one = new Vector<float>(1f);
            Vector<float> inverseChord = one / Vector.SquareRoot(chord2);
            Vector<float> ux = ex * inverseChord, uy = ey * inverseChord, uz = ez * inverseChord;
            var two = new Vector<float>(2f);
            var four = new Vector<float>(4f);
            var five = new Vector<float>(5f);
            Vector<float> s0x = two * p0x - five * p1x + four * p2x - p3x, s0y = two * p0y - five * p1y + four * p2y - p3y, s0z = two * p0z - five * p1z + four * p2z - p3z;
            Vector<float> s1x = four * p1x - p0x - five * p2x + two * p3x, s1y = four * p1y - p0y - five * p2y + two * p3y, s1z = four * p1z - p0z - five * p2z + two * p3z;
            Vector<float> bend = Vector.SquareRoot(MaxLanes(AcrossSquared(s0x, s0y, s0z, ux, uy, uz), AcrossSquared(s1x, s1y, s1z, ux, uy, uz)));
            var half = new Vector<float>(0.5f);
            Vector<float> turn0 = TurnRateSquared(half * (p2x - p0x), half * (p2y - p0y), half * (p2z - p0z), s0x, s0y, s0z);
            Vector<float> turn1 = TurnRateSquared(half * (p3x - p1x), half * (p3y - p1y), half * (p3z - p1z), s1x, s1y, s1z);
            Vector<float> e = new Vector<float>(0.125f) * (bend + new Vector<float>(radius) * MaxLanes(turn0, turn1));
            Vector<float> m = Vector.SquareRoot(e * new Vector<float>(inverseTolerance));
            var capLanes = new Vector<float>(cap);
            // finite: m − m is 0 (±∞ and NaN give NaN); then MathF.Min(m, cap) = m < cap ? m : cap for finite values
            Vector<int> finite = Vector.Equals(m - m, Vector<float>.Zero);
            Vector<float> result = Vector.ConditionalSelect(finite & Vector.LessThan(m, capLanes), m, capLanes);
            // a chord of length² ≤ 1e-30 or not finite asks for the cap
            Vector<int> chordKept = Vector.GreaterThan(chord2, new Vector<float>(1e-30f)) & Vector.Equals(chord2 - chord2, Vector<float>.Zero);
            result = Vector.ConditionalSelect(chordKept, result, capLanes);
            MemoryMarshal.Cast<float, Vector<float>>(need.Slice(j, lanes))[0] = result;
        }

        private static Vector<float> Load(ReadOnlySpan<float> values, int at) => MemoryMarshal.Cast<float, Vector<float>>(values.Slice(at, Vector<float>.Count))[0];

        /// <summary>MathF.Max per lane for values that are never −0: the larger, NaN when either is NaN.</summary>
        private static Vector<float> MaxLanes(Vector<float> a, Vector<float> b)
        {
            Vector<float> larger = Vector.ConditionalSelect(Vector.GreaterThan(a, b), a, b); // b when either is NaN
            return Vector.ConditionalSelect(Vector.Equals(a, a), larger, a);                 // a when a is NaN
        }

        /// <summary>RopePieces' tangent limit per lane (the same operations; the lanes whose tangent is within the limit keep q).</summary>
        private static void LimitLanes(ref Vector<float> qx, ref Vector<float> qy, ref Vector<float> qz, Vector<float> px, Vector<float> py, Vector<float> pz,
            Vector<float> ox, Vector<float> oy, Vector<float> oz, Vector<float> chord2)
        {
            Vector<float> dx = px - qx, dy = py - qy, dz = pz - qz;
            Vector<float> outer2 = dx * dx + dy * dy + dz * dz;
            var half = new Vector<float>(0.5f);
            Vector<float> mx = half * (ox - qx), my = half * (oy - qy), mz = half * (oz - qz);
            Vector<float> tangent2 = mx * mx + my * my + mz * mz;
            Vector<float> shorter2 = Vector.ConditionalSelect(Vector.LessThan(outer2, chord2), outer2, chord2);
            Vector<float> limit2 = new Vector<float>(RopePieces.TangentLimit * RopePieces.TangentLimit) * shorter2;
            Vector<int> limited = Vector.GreaterThan(tangent2, limit2);
            if (Vector.EqualsAll(limited, Vector<int>.Zero)) return;
            Vector<float> scale = Vector.SquareRoot(limit2 / tangent2);
            var two = new Vector<float>(2f);
            qx = Vector.ConditionalSelect(limited, ox - two * (mx * scale), qx);
            qy = Vector.ConditionalSelect(limited, oy - two * (my * scale), qy);
            qz = Vector.ConditionalSelect(limited, oz - two * (mz * scale), qz);
        }

        private static Vector<float> AcrossSquared(Vector<float> sx, Vector<float> sy, Vector<float> sz, Vector<float> ux, Vector<float> uy, Vector<float> uz)
        {
            Vector<float> along = sx * ux + sy * uy + sz * uz;
            Vector<float> ax = sx - along * ux, ay = sy - along * uy, az = sz - along * uz;
            return ax * ax + ay * ay + az * az;
        }

        private static Vector<float> TurnRateSquared(Vector<float> vx, Vector<float> vy, Vector<float> vz, Vector<float> sx, Vector<float> sy, Vector<float> sz)
        {
            Vector<float> speed2 = vx * vx + vy * vy + vz * vz;
            Vector<float> cx = vy * sz - vz * sy, cy = vz * sx - vx * sz, cz = vx * sy - vy * sx;
            Vector<float> cross2 = cx * cx + cy * cy + cz * cz;
            return Vector.ConditionalSelect(Vector.GreaterThan(speed2, new Vector<float>(1e-30f)), cross2 / (speed2 * speed2), new Vector<float>(float.PositiveInfinity));
        }

        private static float AcrossSquared(float sx, float sy, float sz, float ux, float uy, float uz)
        {
            float along = sx * ux + sy * uy + sz * uz;
            float ax = sx - along * ux, ay = sy - along * uy, az = sz - along * uz;
            return ax * ax + ay * ay + az * az;
        }

        private static float TurnRateSquared(float vx, float vy, float vz, float sx, float sy, float sz)
        {
            float speed2 = vx * vx + vy * vy + vz * vz;
            float cx = vy * sz - vz * sy, cy = vz * sx - vx * sz, cz = vx * sy - vy * sx;
            float cross2 = cx * cx + cy * cy + cz * cz;
            // a standing end (|C'| = 0) turns as fast as it likes: the cap decides
            return speed2 > 1e-30f ? cross2 / (speed2 * speed2) : float.PositiveInfinity;
        }
    }
}
