using System;
using System.Numerics;
using HookeRope.Fracture;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Rings that never cross (issues 17 and 18): a slack rope folds tighter than its radius (the recoiling pieces of a
    /// broken cord, a stretched cord let go), and rings drawn at full radius there pass through each other, so the tube
    /// between them turns inside out (triangles wound against their own normals: holes and dark patches on a GPU that culls
    /// back faces). Ring k's circle (centre c_k, radius r_k, plane normal t_k) lies wholly in front of ring k − 1's plane
    /// iff s·t_{k−1} ≥ r_k sin θ, with s = c_k − c_{k−1} and sin θ = |t_{k−1} × t_k|, and ring k − 1 lies behind ring k's
    /// plane iff s·t_k ≥ r_{k−1} sin θ; with both, the strip between them is wound outward for any turn θ &lt; 180°.
    /// <list type="bullet">
    /// <item><b>Fold tips</b> (<see cref="RepairFold"/>, while the frames are transported): where the curve goes backwards
    /// against a ring (a particle passed its neighbour: the advance s·t of one ring past the other is too small for even a
    /// ring of <see cref="FoldRadius"/> of the radius) no radius keeps the two rings apart, and a strip turning by about
    /// 180° between two rings on one line is always half inside out. The second ring's tangent is turned back to at most
    /// <see cref="TipTurnLimit"/> from the first's (in the plane of the turn) and its centre moved by the least distance that
    /// puts each ring in front of the other's plane with room for <see cref="TipRoom"/> tip radii; both rings are drawn at
    /// <see cref="FoldRadius"/> of their radius, with radial normals. The move is a few tip radii (0.1 R), the tip a point.</item>
    /// <item><b>Crossing limit</b> (<see cref="LimitPair"/>, in the frame loop): every other ring is drawn at most
    /// <see cref="CrossingMargin"/> of both bounds above.</item>
    /// <item><b>Cone limit</b> (<see cref="LimitRadii"/>): then the drawn radius changes by at most <see cref="ConeSlope"/>
    /// per unit of centre distance both ways, r_k ≤ r_{k±1} + 2|s| (cones of at most 63°), so a thinned ring takes its
    /// neighbours down with it and the normals, tilted by dr/ds, stay on the winding's side: fold tips close into cones
    /// that read as rounded ends.</item>
    /// </list>
    /// The crossing and cone limits depend only on the centres and tangents (kept for a radius-only build); a fold tip's
    /// move depends on the radius, so a piece with one is always rebuilt whole. On a rope that bends no tighter than its
    /// radius and whose radius changes slowly all three are idle and the drawn radius is the ring radius, bit for bit.
    /// </summary>
    internal sealed partial class TubeMeshBuilder
    {
        /// <summary>Share of the distance to a neighbouring ring's plane that a ring may reach.</summary>
        internal const float CrossingMargin = 0.95f;

        /// <summary>Drawn radius of the two rings of a fold tip, as a fraction of their radius.</summary>
        internal const float FoldRadius = 1e-2f;

        /// <summary>Largest turn between the tangents of a fold tip's two rings (rad, 170°): a turn of 180° has no plane.</summary>
        internal const float TipTurnLimit = 2.9670597f;

        /// <summary>Tip radii of room a fold tip's move leaves each ring in front of the other's plane (beyond the crossing margin).</summary>
        internal const float TipRoom = 4f;

        /// <summary>
        /// The ring next to a fold tip reaches at most this many times its centre's advance along the tip's axis (less its
        /// offset from that axis): the fan from the tip to it is then steeper than 30° to the tip's plane, so each of the
        /// tip's radial normals has a cosine ≥ ½ with the fan's triangles (√3, a little under).
        /// </summary>
        internal const float TipFan = 1.7f;

        /// <summary>Largest change of the drawn radius per unit of distance between neighbouring ring centres.</summary>
        internal const float ConeSlope = 2f;

        /// <summary>Per ring: the square of the largest radius that keeps it clear of its neighbours' planes (+∞: none).</summary>
        private float[] capSquared = Array.Empty<float>();

        /// <summary>Per ring: squared distance to the previous ring's centre (0 for a piece's first ring).</summary>
        private float[] gapSquared = Array.Empty<float>();

        /// <summary>Per ring: the drawn radius of the last <see cref="LimitRadii"/>.</summary>
        private float[] drawnRadii = Array.Empty<float>();

        /// <summary>Per ring: one of the two rings of a fold tip (drawn at <see cref="FoldRadius"/>, radial normals).</summary>
        private bool[] foldTip = Array.Empty<bool>();

        /// <summary>Per ring: the last <see cref="LimitRadii"/> drew it thinner than its radius.</summary>
        private bool[] thinned = Array.Empty<bool>();

        /// <summary>Per ring: a chord to a neighbouring ring makes more than <see cref="SkewLimit"/> with its tangent (its strips are squashed).</summary>
        private bool[] skewed = Array.Empty<bool>();

        /// <summary>Cosine of the largest angle between a ring's tangent and the chord to a neighbour for which the tube's own normals are kept (45°).</summary>
        internal const float SkewLimit = 0.70710677f;

        /// <summary>
        /// Cosine of the largest angle between a ring's tangent and the chord to a neighbour before the two make a fold tip
        /// (60°): a ring at the apex of a hairpin drawn with one ring faces neither chord, and the tube creases by up to 180°
        /// there, which no normal can follow.
        /// </summary>
        internal const float FoldSkew = 0.5f;

        /// <summary>
        /// Ring <paramref name="k"/> as the last build drew it: centre (m, relative to the build's frame origin), unit
        /// tangent (the normal of its plane), drawn radius (m) and whether it is one of a fold tip's two rings.
        /// For tests and the lab's figures.
        /// </summary>
        internal void DrawnRing(int k, out Float3 centre, out Float3 tangent, out float radius, out bool tip)
        {
            centre = centers[k];
            tangent = tangents[k];
            radius = ringRadii[k];
            tip = foldTip[k];
        }

        /// <summary>Rings of the last build that are fold tips, drawn thinner than their radius, or given strip normals (all 0 on a taut rope).</summary>
        internal void FoldCounts(out int tips, out int thinnedRings, out int stripRings)
        {
            tips = 0; thinnedRings = 0; stripRings = 0;
            int rings = layout.RingCount;
            for (int k = 0; k < rings && k < foldTip.Length; k++)
            {
                if (foldTip[k]) tips++;
                if (thinned[k]) thinnedRings++;
                if (stripNormals[k]) stripRings++;
            }
        }

        private void EnsureFoldStorage(int size)
        {
            if (capSquared.Length >= size) return;
            Array.Resize(ref capSquared, size);
            Array.Resize(ref gapSquared, size);
            Array.Resize(ref drawnRadii, size);
            Array.Resize(ref foldTip, size);
            Array.Resize(ref thinned, size);
            Array.Resize(ref stripNormals, size);
            Array.Resize(ref skewed, size);
        }

        /// <summary>
        /// The part of <see cref="RepairFold"/>'s test that needs no turn angle: true when rings k − 1 and k stand far enough
        /// in front of each other's planes for any turn between them (sin θ ≤ 1, with 1e-3 to spare for rounding) and their
        /// chord is within <see cref="FoldSkew"/> of both tangents, so there is nothing to repair. The frame transport calls
        /// it first for every ring, so that a rope without folds pays for no cross product; it passes what its loop formed
        /// already: the step s = c_k − c_{k−1}, |s|² (<paramref name="gap2"/>), s·t_{k−1} (<paramref name="ahead"/>) and
        /// s·t_k (<paramref name="behind"/>).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private bool ClearOfFold(int k, float gap2, float ahead, float behind)
        {
            const float held = TipRoom * 1.001f;
            float chord2 = gap2 * (FoldSkew * FoldSkew);
            return ahead > 0f && behind > 0f
                && ahead * CrossingMargin >= FoldRadius * ringRadii[k] * held && behind * CrossingMargin >= FoldRadius * ringRadii[k - 1] * held
                && ahead * ahead >= chord2 && behind * behind >= chord2;
        }

        /// <summary>
        /// Called by the frame transport for ring k &gt; first with its tangent (tx, ty, tz) (unit) before its normal is
        /// transported: when rings k − 1 and k cannot hold rings of <see cref="FoldRadius"/> of their radius in front of each
        /// other's planes, makes them a fold tip (see the class summary): may turn the tangent and moves centre k. Returns
        /// true when it did.
        /// </summary>
        private bool RepairFold(int k, ref float tx, ref float ty, ref float tz)
        {
            Float3 c0 = centers[k - 1], c1 = centers[k], t0 = tangents[k - 1];
            float sx = c1.X - c0.X, sy = c1.Y - c0.Y, sz = c1.Z - c0.Z;
            float ahead = sx * t0.X + sy * t0.Y + sz * t0.Z, behind = sx * tx + sy * ty + sz * tz;
            float ax = t0.Y * tz - t0.Z * ty, ay = t0.Z * tx - t0.X * tz, az = t0.X * ty - t0.Y * tx;
            float sine = MathF.Sqrt(ax * ax + ay * ay + az * az);
            float tip0 = FoldRadius * ringRadii[k - 1], tip1 = FoldRadius * ringRadii[k];
            float held = TipRoom * sine;
            float chord2 = (sx * sx + sy * sy + sz * sz) * (FoldSkew * FoldSkew);
            if (ahead > 0f && behind > 0f && ahead * CrossingMargin >= tip1 * held && behind * CrossingMargin >= tip0 * held
                && ahead * ahead >= chord2 && behind * behind >= chord2) return false;

            // the plane of the turn: its axis a, and w = a × t0, the way t0 turns toward t1
            float cosine = t0.X * tx + t0.Y * ty + t0.Z * tz;
            if (sine > 1e-4f) { ax /= sine; ay /= sine; az /= sine; }
            else
            {
                // (anti)parallel tangents: turn about ring k − 1's normal (a reversal's transport keeps it)
                Float3 n0 = normals[k - 1];
                ax = n0.X; ay = n0.Y; az = n0.Z;
            }
            float wx = ay * t0.Z - az * t0.Y, wy = az * t0.X - ax * t0.Z, wz = ax * t0.Y - ay * t0.X;
            float turn = MathF.Atan2(sine, cosine);
            if (turn > TipTurnLimit)
            {
                float c = MathF.Cos(TipTurnLimit), sn = MathF.Sin(TipTurnLimit);
                tx = t0.X * c + wx * sn; ty = t0.Y * c + wy * sn; tz = t0.Z * c + wz * sn;
                Normalize(ref tx, ref ty, ref tz);
                cosine = c;
                sine = sn;
                behind = sx * tx + sy * ty + sz * tz;
            }

            // the least move of centre k that gives each ring TipRoom tip radii (and at least one tip radius of advance)
            float room = TipRoom * sine / CrossingMargin;
            float need0 = tip1 * MathF.Max(room, 1f) - ahead, need1 = tip0 * MathF.Max(room, 1f) - behind;
            float mx = 0f, my = 0f, mz = 0f;
            bool alongFirst = need0 > 0f && need1 - need0 * cosine <= 0f, alongSecond = need1 > 0f && need0 - need1 * cosine <= 0f;
            if (need0 <= 0f && need1 <= 0f) { }
            else if (alongFirst && (!alongSecond || need0 <= need1)) { mx = t0.X * need0; my = t0.Y * need0; mz = t0.Z * need0; }
            else if (alongSecond) { mx = tx * need1; my = ty * need1; mz = tz * need1; }
            else if (1f - cosine * cosine > 1e-3f)
            {
                // both planes: the least move onto their line of intersection (the tangents are ≥ 1.8° apart)
                float determinant = 1f - cosine * cosine;
                float alpha = (need0 - cosine * need1) / determinant, beta = (need1 - cosine * need0) / determinant;
                mx = t0.X * alpha + tx * beta; my = t0.Y * alpha + ty * beta; mz = t0.Z * alpha + tz * beta;
            }
            else
            {
                // (anti)parallel tangents: along their mean (or, antiparallel, the turn's side) far enough for both
                float ux = t0.X + tx, uy = t0.Y + ty, uz = t0.Z + tz;
                if (!Normalize(ref ux, ref uy, ref uz)) { ux = wx; uy = wy; uz = wz; }
                float d0 = ux * t0.X + uy * t0.Y + uz * t0.Z, d1 = ux * tx + uy * ty + uz * tz;
                float move = MathF.Max(d0 > 0f ? need0 / d0 : 0f, d1 > 0f ? need1 / d1 : 0f);
                mx = ux * move; my = uy * move; mz = uz * move;
            }
            centers[k] = new Float3(c1.X + mx, c1.Y + my, c1.Z + mz);
            foldTip[k - 1] = true;
            foldTip[k] = true;
            spacing2[k] = float.NaN; // the centre now depends on the radius: no radius-only rebuild
            return true;
        }

        /// <summary>
        /// The geometric limits of the pair of consecutive rings k − 1, k of a piece, once both centres and tangents are
        /// final (called by the frame loop): step² <paramref name="gap2"/>, the step's advance past ring k − 1's plane
        /// <paramref name="ahead"/> and past ring k's <paramref name="behind"/>, the unit tangents t0 and t1. Marks a ring
        /// whose chord is more than <see cref="SkewLimit"/> off its tangent (<paramref name="anySkewed"/> then true), makes
        /// a pair no repair could part fold tips, and lowers both rings' crossing caps (<see cref="capSquared"/>, which the
        /// loop set to +∞ for ring k) to <see cref="CrossingMargin"/> of the distance to the other's plane.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static void LimitPair(int k, float gap2, float ahead, float behind, float t0x, float t0y, float t0z,
            float t1x, float t1y, float t1z, Span<float> cap, Span<bool> skew, Span<bool> tips, ref bool anySkewed)
        {
            const float skew2 = SkewLimit * SkewLimit;
            const float margin2 = CrossingMargin * CrossingMargin;
            if (ahead * ahead < skew2 * gap2 || ahead < 0f) { skew[k - 1] = true; anySkewed = true; }
            if (behind * behind < skew2 * gap2 || behind < 0f) { skew[k] = true; anySkewed = true; }
            if (!(ahead > 0f && behind > 0f))
            {
                // only where a fold tip's repair could not part them (non-finite geometry): drawn as tips
                tips[k - 1] = true;
                tips[k] = true;
                return;
            }
            float nx = t0y * t1z - t0z * t1y, ny = t0z * t1x - t0x * t1z, nz = t0x * t1y - t0y * t1x;
            float sine2 = nx * nx + ny * ny + nz * nz;
            if (!(sine2 > 0f)) return;
            float scale = margin2 / sine2;
            float capNext = ahead * ahead * scale, capPrevious = behind * behind * scale;
            if (capNext < cap[k]) cap[k] = capNext;
            if (capPrevious < cap[k - 1]) cap[k - 1] = capPrevious;
        }

        /// <summary>The strips next to a fold tip of rings first … last are steep fans (see <see cref="TipFan"/>): lowers the other ring's cap. Only pieces with a tip.</summary>
        private void LimitTipFans(int first, int last)
        {
            for (int k = first + 1; k <= last; k++)
            {
                if (foldTip[k - 1] == foldTip[k]) continue;
                int tip = foldTip[k - 1] ? k - 1 : k, other = tip == k ? k - 1 : k;
                Float3 ct = centers[tip], t = tangents[tip], co = centers[other];
                float dx = co.X - ct.X, dy = co.Y - ct.Y, dz = co.Z - ct.Z;
                float along = dx * t.X + dy * t.Y + dz * t.Z;
                float advance = tip == k ? -along : along;
                float ox = dx - along * t.X, oy = dy - along * t.Y, oz = dz - along * t.Z;
                float offset = MathF.Sqrt(ox * ox + oy * oy + oz * oz);
                float fan = TipFan * advance - offset;
                float fan2 = fan > 0f ? fan * fan : 0f;
                if (fan2 < capSquared[other]) capSquared[other] = fan2;
            }
        }

        /// <summary>
        /// The drawn radii of rings first … last into <see cref="drawnRadii"/>: each ring's radius (<paramref name="radii"/>,
        /// clamped to ≥ 1e-6) limited by the caps of <see cref="LimitPair"/>, then by the cone slope both ways. One loop
        /// caps each ring, applies the forward cone limit against the ring before (already final) and marks it thinned; it
        /// also tells whether the backward pass can change anything: it lowers ring k only when ring k falls to ring k + 1
        /// by more than the slope allows, and a pass from the end that has changed nothing sees the forward values, so if
        /// no pair falls too steeply there the backward pass would change nothing and is skipped (the same bits). Returns
        /// true when a ring was drawn thinner than its radius.
        /// </summary>
        private bool LimitRadii(int first, int last, ReadOnlySpan<float> radii)
        {
            Span<float> drawn = drawnRadii;
            Span<bool> thin = thinned;
            const float slope2 = ConeSlope * ConeSlope;
            bool falls = false, anyThin = false;
            int count = last - first + 1;
            // where the lanes take the piece (nothing thinned, no forward cone limit) they wrote the forward loop's values
            if (!(VectorPath.Enabled && !ForceFullLimits && count >= Vector<float>.Count && LimitRadiiOnLanes(first, count, radii, out falls)))
            {
                // the forward loop over spans of exactly the piece's rings, indexed by i = k − first
                falls = false;
                ReadOnlySpan<float> given = radii.Slice(first, count);
                ReadOnlySpan<float> cap = new ReadOnlySpan<float>(capSquared, first, count).Slice(0, given.Length);
                ReadOnlySpan<float> gap = new ReadOnlySpan<float>(gapSquared, first, count).Slice(0, given.Length);
                ReadOnlySpan<bool> tip = new ReadOnlySpan<bool>(foldTip, first, count).Slice(0, given.Length);
                Span<float> drawnHere = drawn.Slice(first, count).Slice(0, given.Length);
                Span<bool> thinHere = thin.Slice(first, count).Slice(0, given.Length);
                float previous = 0f;
                for (int i = 0; i < given.Length; i++)
                {
                    float r = Clamped(given[i]);
                    float cap2 = cap[i];
                    float d = r;
                    if (tip[i]) d = FoldRadius * r;
                    else if (r * r > cap2)
                    {
                        d = MathF.Sqrt(cap2);
                        if (!(d >= FoldRadius * r)) d = FoldRadius * r;
                    }
                    if (i > 0)
                    {
                        float rise = d - previous;
                        if (rise > 0f && rise * rise > slope2 * gap[i]) d = previous + ConeSlope * MathF.Sqrt(gap[i]);
                        else if (rise < 0f && rise * rise > slope2 * gap[i]) falls = true;
                    }
                    drawnHere[i] = d;
                    bool thinner = d != r;
                    thinHere[i] = thinner;
                    anyThin |= thinner;
                    previous = d;
                }
            }
            if (!falls && !ForceFullLimits) return anyThin;
            ReadOnlySpan<float> gapSquaredAll = gapSquared;
            for (int k = last - 1; k >= first; k--)
            {
                float next = drawn[k + 1], rise = drawn[k] - next;
                if (rise > 0f && rise * rise > slope2 * gapSquaredAll[k + 1]) drawn[k] = next + ConeSlope * MathF.Sqrt(gapSquaredAll[k + 1]);
            }
            anyThin = false;
            for (int k = first; k <= last; k++)
            {
                bool thinner = drawn[k] != Clamped(radii[k]);
                thin[k] = thinner;
                anyThin |= thinner;
            }
            return anyThin;
        }

        /// <summary>Scratch of <see cref="LimitRadiiOnLanes"/>: the piece's radii, caps², steps² and drawn radii, padded for whole runs of lanes (grown by <see cref="EnsureLaneStorage"/>).</summary>
        private float[] limitGiven = Array.Empty<float>(), limitCap = Array.Empty<float>(), limitGap = Array.Empty<float>(), limitDrawn = Array.Empty<float>();

        /// <summary>
        /// <see cref="LimitRadii"/>'s forward loop on <see cref="Vector{T}"/> lanes for the <paramref name="count"/> rings
        /// from <paramref name="first"/>, when it can change nothing sequential: with no fold tip in the piece, each ring's
        /// capped radius (the clamp, the cap and the fold floor by the scalar's operations, the branches as selects) does not
        /// depend on the ring before, and the forward cone limit is the only thing that would. So one run of lanes caps 8
        /// rings, one tests 8 pairs with the scalar's comparisons; when no pair rises too steeply (the forward limit idle)
        /// and no ring comes out thinner than its radius, these are the forward loop's values: they go into
        /// <see cref="drawnRadii"/>, the piece's thinned marks are cleared and <paramref name="falls"/> tells whether the
        /// backward pass may change something. Otherwise returns false, with nothing of the loop's written (the scalar loop
        /// then takes the piece).
        /// </summary>
        private bool LimitRadiiOnLanes(int first, int count, ReadOnlySpan<float> radii, out bool falls)
        {
            falls = false;
            if (new ReadOnlySpan<bool>(foldTip, first, count).IndexOf(true) >= 0) return false;
            int lanes = Vector<float>.Count;
            // the scratch is grown with the lane scratch (EnsureLaneStorage), never here
            if (limitGiven.Length < count + 2 * lanes) return false;
            // the piece's values, then finite pads past it (a pad's step² +∞: its pair never tests true)
            Span<float> given = limitGiven, cap = limitCap, gap = limitGap, drawn = limitDrawn;
            radii.Slice(first, count).CopyTo(given);
            new ReadOnlySpan<float>(capSquared, first, count).CopyTo(cap);
            new ReadOnlySpan<float>(gapSquared, first, count).CopyTo(gap);
            given.Slice(count, 2 * lanes).Fill(1f);
            cap.Slice(count, 2 * lanes).Fill(float.PositiveInfinity);
            gap.Slice(count, 2 * lanes).Fill(float.PositiveInfinity);

            // run j: rings lanes·j …; Clamped (1e-6 < r < +∞, which a NaN fails, else 1e-6), then the cap and the fold floor
            var least = new Vector<float>(1e-6f);
            var infinity = new Vector<float>(float.PositiveInfinity);
            var foldRadius = new Vector<float>(FoldRadius);
            Vector<int> thinner = Vector<int>.Zero;
            int runs = (count + lanes - 1) / lanes;
            {
                ReadOnlySpan<Vector<float>> givenRuns = Runs(given, 0, runs), capRuns = Runs(cap, 0, runs);
                Span<Vector<float>> drawnRuns = Runs(drawn, 0, runs);
                for (int j = 0; j < runs; j++)
                {
                    Vector<float> g = givenRuns[j], cap2 = capRuns[j];
                    Vector<float> r = ClampedLanes(g, least, infinity);
                    Vector<float> root = Vector.SquareRoot(cap2), floor = foldRadius * r;
                    Vector<float> capped = Vector.ConditionalSelect(Vector.GreaterThanOrEqual(root, floor), root, floor);
                    Vector<float> d = Vector.ConditionalSelect(Vector.GreaterThan(r * r, cap2), capped, r);
                    thinner |= ~Vector.Equals(d, r);
                    drawnRuns[j] = d;
                }
            }
            if (!Vector.EqualsAll(thinner, Vector<int>.Zero)) return false;

            // the pairs i − 1, i for i = 1 + lanes·j …: a rise steeper than the slope would be limited (sequential), a fall
            // only marks the backward pass
            var slope2 = new Vector<float>(ConeSlope * ConeSlope);
            var zero = Vector<float>.Zero;
            Vector<int> rises = Vector<int>.Zero, fallsLanes = Vector<int>.Zero;
            int pairRuns = (count - 1 + lanes - 1) / lanes;
            {
                ReadOnlySpan<Vector<float>> here = Runs(drawn, 1, pairRuns), before = Runs(drawn, 0, pairRuns), gapRuns = Runs(gap, 1, pairRuns);
                for (int j = 0; j < pairRuns; j++)
                {
                    Vector<float> rise = here[j] - before[j];
                    Vector<int> steep = Vector.GreaterThan(rise * rise, slope2 * gapRuns[j]);
                    rises |= Vector.GreaterThan(rise, zero) & steep;
                    fallsLanes |= Vector.LessThan(rise, zero) & steep;
                }
            }
            if (!Vector.EqualsAll(rises, Vector<int>.Zero)) return false;
            falls = !Vector.EqualsAll(fallsLanes, Vector<int>.Zero);
            drawn.Slice(0, count).CopyTo(new Span<float>(drawnRadii, first, count));
            new Span<bool>(thinned, first, count).Clear();
            return true;
        }

        /// <summary>Tests only: every build runs the whole of the ring limits (the backward cone pass, the strip-normal marks, the frame loop with its fold repair at every ring instead of the two passes of <see cref="FramesClearOfFolds"/>), where a cheap test would have skipped them.</summary>
        internal bool ForceFullLimits { get; set; }

        /// <summary>Per ring: its normals are drawn from its two strips (<see cref="WriteRingOnStrips"/>), not the tube's own formula.</summary>
        private bool[] stripNormals = Array.Empty<bool>();

        /// <summary>
        /// Marks the rings of piece first … last whose normals come from their strips: every ring the limits thinned and its
        /// neighbours. Returns true when a ring is or was marked (a radius-only build then rewrites the whole piece).
        /// </summary>
        private bool MarkStripNormals(int first, int last)
        {
            bool any = false;
            for (int k = first; k <= last; k++)
            {
                bool marked = (thinned[k] || skewed[k] || (k > first && thinned[k - 1]) || (k < last && thinned[k + 1])) && !foldTip[k];
                any |= marked || stripNormals[k];
                stripNormals[k] = marked;
            }
            return any;
        }

        /// <summary>
        /// Writes ring k of piece first … last like <see cref="WriteRing"/> (the same positions, tangents and uv), with each
        /// vertex normal the bisector of the unit normals of its two strips, τ × (p_{k+1} − p_k) and τ × (p_k − p_{k−1}) (τ the
        /// direction around the ring; one strip at a piece's end, whose neighbour beyond is the dangling half's first ring,
        /// <paramref name="beforeFirst"/>/<paramref name="afterLast"/>, when there is one). A ring thinned between wide
        /// neighbours, or tilted across its strips at a fold, is not a surface of revolution about its tangent, and the
        /// formula's normals (e − (dr/ds) t) can face away from a strip; the bisector faces both (its dot product with either
        /// unit normal is 1 + their cosine ≥ 0).
        /// </summary>
        private void WriteRingOnStrips(int k, int first, int last, in Neighbour beforeFirst, in Neighbour afterLast, Span<TubeVertex> ring)
        {
            WriteRing(k, ring);
            Float3 c = centers[k], t = tangents[k], nrm = normals[k];
            Float3 bin = Float3.Cross(t, nrm);
            float r = ringRadii[k];
            Neighbour behind = k > first ? RingAt(k - 1) : beforeFirst;
            Neighbour ahead = k < last ? RingAt(k + 1) : afterLast;
            Float3 bb = Float3.Cross(behind.Tangent, behind.Normal), ba = Float3.Cross(ahead.Tangent, ahead.Normal);
            for (int i = 0; i < ring.Length; i++)
            {
                float ci = cos[i], si = sin[i];
                Float3 e = nrm * ci + bin * si;
                Float3 p = c + e * r;
                Float3 around = bin * ci - nrm * si;
                Float3 sum = Float3.Zero;
                if (ahead.Exists)
                {
                    Float3 q = ahead.Centre + (ahead.Normal * ci + ba * si) * ahead.Radius;
                    sum = sum + Float3.Cross(around, q - p).NormalizedOr(Float3.Zero);
                }
                if (behind.Exists)
                {
                    Float3 q = behind.Centre + (behind.Normal * ci + bb * si) * behind.Radius;
                    sum = sum + Float3.Cross(around, p - q).NormalizedOr(Float3.Zero);
                }
                Float3 normal = sum.NormalizedOr(e);
                ref TubeVertex vertex = ref ring[i];
                vertex.NX = normal.X; vertex.NY = normal.Y; vertex.NZ = normal.Z;
            }
        }

        /// <summary>A ring next to the one drawn: centre, frame and drawn radius (Exists false: none).</summary>
        private readonly struct Neighbour
        {
            public readonly bool Exists;
            public readonly Float3 Centre, Tangent, Normal;
            public readonly float Radius;

            public Neighbour(Float3 centre, Float3 tangent, Float3 normal, float radius)
            {
                Exists = true;
                Centre = centre;
                Tangent = tangent;
                Normal = normal;
                Radius = radius;
            }
        }

        private Neighbour RingAt(int k) => new Neighbour(centers[k], tangents[k], normals[k], ringRadii[k]);

        /// <summary>The first ring of the dangling half beyond ring <paramref name="joint"/> (straight along its tangent, with its frame), or none.</summary>
        private Neighbour DanglingNeighbour(bool present, int segment, bool upper, int joint)
        {
            if (!present) return default;
            DanglingEnds.Stations(layout, segment, upper, stations);
            int k = stations[0];
            float fraction = k >= 0 ? layout.RingFractions[k] : DanglingEnds.Cut;
            float r = Clamped(k >= 0 ? lastRadii[k] : dangling.CutRadius(segment, upper));
            Float3 t = tangents[joint];
            Float3 outward = upper ? -t : t;
            return new Neighbour(centers[joint] + outward * (dangling.HalfLength(segment) * DanglingEnds.ShareOfHalf(fraction, upper)), t, normals[joint], r);
        }
    }
}
