using System;

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
            for (int j = a; j < b; j++)
            {
                RopePieces.ControlPoints(j, a, b, x, y, z, ox, oy, oz, out float p0x, out float p0y, out float p0z,
                    out float p1x, out float p1y, out float p1z, out float p2x, out float p2y, out float p2z, out float p3x, out float p3y, out float p3z);

                // chord direction
                float ux = p2x - p1x, uy = p2y - p1y, uz = p2z - p1z;
                float chord2 = ux * ux + uy * uy + uz * uz;
                if (!(chord2 > 1e-30f) || !float.IsFinite(chord2)) { need[j] = cap; continue; }
                float inverseChord = 1f / MathF.Sqrt(chord2);
                ux *= inverseChord; uy *= inverseChord; uz *= inverseChord;

                // C''(0) = 2p0 − 5p1 + 4p2 − p3, C''(1) = −p0 + 4p1 − 5p2 + 2p3
                float s0x = 2f * p0x - 5f * p1x + 4f * p2x - p3x, s0y = 2f * p0y - 5f * p1y + 4f * p2y - p3y, s0z = 2f * p0z - 5f * p1z + 4f * p2z - p3z;
                float s1x = -p0x + 4f * p1x - 5f * p2x + 2f * p3x, s1y = -p0y + 4f * p1y - 5f * p2y + 2f * p3y, s1z = -p0z + 4f * p1z - 5f * p2z + 2f * p3z;
                float across0 = AcrossSquared(s0x, s0y, s0z, ux, uy, uz);
                float across1 = AcrossSquared(s1x, s1y, s1z, ux, uy, uz);
                float bend = MathF.Sqrt(MathF.Max(across0, across1));

                // C'(0) = (p2 − p0)/2, C'(1) = (p3 − p1)/2; ω = |C' × C''| / |C'|²
                float turn0 = TurnRateSquared(0.5f * (p2x - p0x), 0.5f * (p2y - p0y), 0.5f * (p2z - p0z), s0x, s0y, s0z);
                float turn1 = TurnRateSquared(0.5f * (p3x - p1x), 0.5f * (p3y - p1y), 0.5f * (p3z - p1z), s1x, s1y, s1z);
                float e = 0.125f * (bend + radius * MathF.Max(turn0, turn1));
                float m = MathF.Sqrt(e * inverseTolerance);
                need[j] = float.IsFinite(m) ? MathF.Min(m, cap) : cap;
            }
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
