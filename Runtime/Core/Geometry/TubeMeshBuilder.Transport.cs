using System;
using System.Numerics;
using System.Runtime.InteropServices;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// The frames of a piece without folds in two passes (issue 18, "a mesh that costs less than the physics"): the
    /// frame loop of <see cref="ComputeFrames"/> does per ring the tangent, the fold test, the pair limits and the
    /// normal's transport, and only the transport depends on the ring before (the normal is carried from ring to ring);
    /// the rest depends on the centres alone. So the first pass takes the tangents, ring distances, steps, fold tests and
    /// pair limits of every ring, and the second only transports the normal along the finished tangents: two short loops
    /// whose values stay in registers, where the one loop spilled its many live values to the stack. Each value is the
    /// one loop's, by the same operations in the same order (the same bits). A piece where some pair fails the fold test
    /// (<see cref="ClearOfFold"/>: a fold tip may move a centre, which changes the tangents further on) is left to the one
    /// loop, from its first ring, as is every piece while <see cref="ForceFullLimits"/> is set (the tests' reference).
    /// </summary>
    internal sealed partial class TubeMeshBuilder
    {
        /// <summary>
        /// The frames of rings first … last of piece [a, b] in the two passes, when no pair of the piece needs a fold
        /// repair: returns true with everything <see cref="ComputeFrames"/> writes written (no fold tip, the ring
        /// distances kept), <paramref name="anySkewed"/> telling whether a ring was marked skewed; false as soon as a pair
        /// fails the fold test (the one loop then writes every ring again).
        /// </summary>
        private bool FramesClearOfFolds(int a, int first, int last, out bool anySkewed)
        {
            int count = last - first + 1;
            anySkewed = false;
            ReadOnlySpan<Float3> c = new ReadOnlySpan<Float3>(centers, first, count);
            Span<Float3> tangent = new Span<Float3>(tangents, first, count);
            Span<float> distance = new Span<float>(slopeDistance, first, count);
            Span<float> cap = new Span<float>(capSquared, first, count), gap = new Span<float>(gapSquared, first, count);
            Span<bool> tip = new Span<bool>(foldTip, first, count), skew = new Span<bool>(skewed, first, count);
            lanePieceFirst = -1;
            if (VectorPath.Enabled && count >= Vector<float>.Count && FramePassOnLanes(first, count))
            {
                FramePiecesOnLanes++;
                lanePieceFirst = first;
                lanePieceCount = count;
                TransportNormals(a, first, count, true);
                return true;
            }
            Float3 span = c[count - 1] - c[0];
            float px = span.X, py = span.Y, pz = span.Z;
            if (!Normalize(ref px, ref py, ref pz)) { px = 1f; py = 0f; pz = 0f; }
            // pass 1: per ring what the centres decide; (px, py, pz) is ring i − 1's tangent (before the first ring the
            // piece's direction, the last fallback), behind and here the centres of rings i − 1 (i at the first) and i
            // the marks and caps the pair limits may set, cleared in bulk (the one loop clears them ring by ring)
            tip.Clear();
            skew.Clear();
            cap.Fill(float.PositiveInfinity);
            gap[0] = 0f;
            bool skews = false;
            // the centres of rings i − 1 (i at the first) and i as values (no local is passed by reference here: those
            // live on the stack)
            float bx = c[0].X, by = c[0].Y, bz = c[0].Z, hx = bx, hy = by, hz = bz;
            for (int i = 0; i < count; i++)
            {
                float ax = hx, ay = hy, az = hz;
                if (i + 1 < count) { Float3 ahead = c[i + 1]; ax = ahead.X; ay = ahead.Y; az = ahead.Z; }
                float tx = ax - bx, ty = ay - by, tz = az - bz;
                // Normalize's operations in its order; the length is ComputeSlopes' ring distance
                float lengthSquared = tx * tx + ty * ty + tz * tz;
                float length = MathF.Sqrt(lengthSquared);
                distance[i] = length;
                if (lengthSquared > 1e-20f)
                {
                    float inverse = 1f / length;
                    tx *= inverse; ty *= inverse; tz *= inverse;
                }
                else
                {
                    Float3 fallback = FallbackTangentOf(i > 0, i + 1 < count, new Float3(hx, hy, hz), new Float3(ax, ay, az),
                        new Float3(bx, by, bz), new Float3(px, py, pz));
                    tx = fallback.X; ty = fallback.Y; tz = fallback.Z;
                }
                if (i > 0)
                {
                    float sx = hx - bx, sy = hy - by, sz = hz - bz;
                    float gap2 = sx * sx + sy * sy + sz * sz;
                    float past = sx * px + sy * py + sz * pz, before = sx * tx + sy * ty + sz * tz;
                    if (!ClearOfFold(first + i, gap2, past, before)) return false;
                    gap[i] = gap2;
                    // past and before are positive here (ClearOfFold), so the limits mark no fold tip
                    LimitPair(i, gap2, past, before, px, py, pz, tx, ty, tz, cap, skew, tip, ref skews);
                }
                tangent[i] = new Float3(tx, ty, tz);
                px = tx; py = ty; pz = tz;
                bx = hx; by = hy; bz = hz;
                hx = ax; hy = ay; hz = az;
            }
            TransportNormals(a, first, count, false);
            anySkewed = skews;
            return true;
        }

        /// <summary>Scratch of <see cref="FramePassOnLanes"/>: centres (one ring of padding each side) and tangents per axis, distances, steps², caps from the pair ahead and the pair behind, radii.</summary>
        private float[] laneX = Array.Empty<float>(), laneY = Array.Empty<float>(), laneZ = Array.Empty<float>();
        private float[] laneTX = Array.Empty<float>(), laneTY = Array.Empty<float>(), laneTZ = Array.Empty<float>();
        private float[] laneDistance = Array.Empty<float>(), laneGap = Array.Empty<float>(), laneCap = Array.Empty<float>(), lanePrevious = Array.Empty<float>();
        private float[] laneRadius = Array.Empty<float>();

        /// <summary>Scratch of <see cref="FramePassOnLanes"/> for the transport: per ring i its pair's t_{i−1}·t_i and t_{i−1} × t_i (slot i; ring 0 none).</summary>
        private float[] laneCosine = Array.Empty<float>(), laneKX = Array.Empty<float>(), laneKY = Array.Empty<float>(), laneKZ = Array.Empty<float>();

        /// <summary>Pieces whose first frame pass ran on lanes (<see cref="FramePassOnLanes"/>), since construction: for tests.</summary>
        internal int FramePiecesOnLanes { get; private set; }

        /// <summary>The piece whose centres and tangents the lane scratch holds (first ring, −1: none; ring count), from the last <see cref="FramePassOnLanes"/>.</summary>
        private int lanePieceFirst = -1, lanePieceCount;

        /// <summary>
        /// <see cref="AddRingsBounds"/> on lanes for the piece the lane scratch holds (its centres and final tangents
        /// from <see cref="FramePassOnLanes"/>, the drawn radii from the ring array): each lane with the scalar's
        /// operations (Vector4.Max(0, q) as its select: +0 where q ≤ 0, q otherwise and for NaN), a running corner per
        /// lane over its rings, then the lanes into the corners in order. The minimum and maximum of a set do not depend
        /// on the order but for the sign of a zero (−0 and +0 compare equal, the first seen stays): a corner that comes
        /// out zero returns false (nothing written) and the scalar loop takes the piece.
        /// </summary>
        private bool AddRingsBoundsOnLanes(int first, int count, ref Bounds bounds)
        {
            int lanes = Vector<float>.Count;
            Span<float> radius = laneRadius;
            new ReadOnlySpan<float>(ringRadii, first, count).CopyTo(radius);
            radius.Slice(count, lanes).Clear();
            Span<float> x = laneX, y = laneY, z = laneZ, tx = laneTX, ty = laneTY, tz = laneTZ;
            var countLanes = new Vector<int>(count);
            var zero = Vector<float>.Zero;
            var one = new Vector<float>(1f);
            var grow = new Vector<float>(1.000001f);
            Vector<float> minX = new Vector<float>(bounds.Min.X), minY = new Vector<float>(bounds.Min.Y), minZ = new Vector<float>(bounds.Min.Z);
            Vector<float> maxX = new Vector<float>(bounds.Max.X), maxY = new Vector<float>(bounds.Max.Y), maxZ = new Vector<float>(bounds.Max.Z);
            // run j of lanes is rings i = lanes·j …; ring i's centre is scratch slot i + 1
            int runs = (count + lanes - 1) / lanes;
            ReadOnlySpan<Vector<float>> radiusRuns = Runs(radius, 0, runs), txRuns = Runs(tx, 0, runs), tyRuns = Runs(ty, 0, runs), tzRuns = Runs(tz, 0, runs);
            ReadOnlySpan<Vector<float>> xRuns = Runs(x, 1, runs), yRuns = Runs(y, 1, runs), zRuns = Runs(z, 1, runs);
            for (int j = 0; j < runs; j++)
            {
                Vector<int> inside = Vector.LessThan(laneIndex + new Vector<int>(j * lanes), countLanes);
                Vector<float> r = radiusRuns[j];
                Vector<float> qx = txRuns[j], qy = tyRuns[j], qz = tzRuns[j];
                qx = one - qx * qx; qy = one - qy * qy; qz = one - qz * qz;
                qx = Vector.ConditionalSelect(Vector.LessThanOrEqual(qx, zero), zero, qx);
                qy = Vector.ConditionalSelect(Vector.LessThanOrEqual(qy, zero), zero, qy);
                qz = Vector.ConditionalSelect(Vector.LessThanOrEqual(qz, zero), zero, qz);
                Vector<float> ex = r * Vector.SquareRoot(qx) * grow, ey = r * Vector.SquareRoot(qy) * grow, ez = r * Vector.SquareRoot(qz) * grow;
                Vector<float> cx = xRuns[j], cy = yRuns[j], cz = zRuns[j];
                Vector<float> lx = cx - ex, ly = cy - ey, lz = cz - ez, hx = cx + ex, hy = cy + ey, hz = cz + ez;
                minX = Vector.ConditionalSelect(inside & Vector.LessThan(lx, minX), lx, minX);
                minY = Vector.ConditionalSelect(inside & Vector.LessThan(ly, minY), ly, minY);
                minZ = Vector.ConditionalSelect(inside & Vector.LessThan(lz, minZ), lz, minZ);
                maxX = Vector.ConditionalSelect(inside & Vector.GreaterThan(hx, maxX), hx, maxX);
                maxY = Vector.ConditionalSelect(inside & Vector.GreaterThan(hy, maxY), hy, maxY);
                maxZ = Vector.ConditionalSelect(inside & Vector.GreaterThan(hz, maxZ), hz, maxZ);
            }
            float loX = bounds.Min.X, loY = bounds.Min.Y, loZ = bounds.Min.Z, hiX = bounds.Max.X, hiY = bounds.Max.Y, hiZ = bounds.Max.Z;
            for (int j = 0; j < lanes; j++)
            {
                float ax = minX[j], ay = minY[j], az = minZ[j], bx = maxX[j], by = maxY[j], bz = maxZ[j];
                loX = ax < loX ? ax : loX; loY = ay < loY ? ay : loY; loZ = az < loZ ? az : loZ;
                hiX = bx > hiX ? bx : hiX; hiY = by > hiY ? by : hiY; hiZ = bz > hiZ ? bz : hiZ;
            }
            if (loX == 0f || loY == 0f || loZ == 0f || hiX == 0f || hiY == 0f || hiZ == 0f) return false;
            bounds.Min = new Float3(loX, loY, loZ);
            bounds.Max = new Float3(hiX, hiY, hiZ);
            return true;
        }

        /// <summary>Lane i holds i (which lanes of a run lie inside the piece).</summary>
        private readonly Vector<int> laneIndex = LaneIndex();

        private static Vector<int> LaneIndex()
        {
            Span<int> index = stackalloc int[Vector<int>.Count];
            for (int i = 0; i < index.Length; i++) index[i] = i;
            return new Vector<int>(index);
        }

        /// <summary>Grows <see cref="FramePassOnLanes"/>' scratch for pieces of up to <paramref name="rings"/> rings (with a run of lanes and two rings of padding), and <see cref="LimitRadiiOnLanes"/>' (two runs of padding).</summary>
        private void EnsureLaneStorage(int rings)
        {
            int limitSize = rings + 2 * Vector<float>.Count;
            if (limitGiven.Length < limitSize)
            {
                limitGiven = new float[limitSize]; limitCap = new float[limitSize]; limitGap = new float[limitSize]; limitDrawn = new float[limitSize];
            }
            int size = rings + Vector<float>.Count + 2;
            if (laneX.Length >= size) return;
            laneX = new float[size]; laneY = new float[size]; laneZ = new float[size];
            laneTX = new float[size]; laneTY = new float[size]; laneTZ = new float[size];
            laneDistance = new float[size]; laneGap = new float[size]; laneCap = new float[size]; lanePrevious = new float[size];
            laneRadius = new float[size];
            laneCosine = new float[size]; laneKX = new float[size]; laneKY = new float[size]; laneKZ = new float[size];
        }

        /// <summary>
        /// Pass 1 of <see cref="FramesClearOfFolds"/> on <see cref="Vector{T}"/> lanes, for the <paramref name="count"/>
        /// rings from <paramref name="first"/>: one run of lanes for the tangents and ring distances of as many rings, one
        /// for the steps, fold tests and crossing caps of as many pairs, each lane with the scalar's operations in the
        /// scalar's order (no fused multiply-add; the scalar's branches become selects), so the same bits (tested with
        /// <see cref="VectorPath.Enabled"/> off and on). The centres go into per-axis scratch first (with ring 0 repeated
        /// before and the last ring after, the neighbours the end rings take), the tangents come back from it last. Returns
        /// false, having written nothing the scalar pass does not write again, when some ring needs what the lanes leave to
        /// the scalar pass: a fallback tangent (neighbours on one point), a fold (a failed <see cref="ClearOfFold"/>) or a
        /// skew mark.
        /// </summary>
        private bool FramePassOnLanes(int first, int count)
        {
            int lanes = Vector<float>.Count;
            Span<float> x = laneX, y = laneY, z = laneZ;
            ReadOnlySpan<Float3> c = new ReadOnlySpan<Float3>(centers, first, count);
            {
                // ring i's centre into slot i + 1, through slices of exactly the piece's rings (no range checks)
                Span<float> xs = x.Slice(1, c.Length), ys = y.Slice(1, c.Length), zs = z.Slice(1, c.Length);
                for (int i = 0; i < c.Length; i++)
                {
                    Float3 p = c[i];
                    xs[i] = p.X; ys[i] = p.Y; zs[i] = p.Z;
                }
            }
            x[0] = x[1]; y[0] = y[1]; z[0] = z[1];
            // the last ring after itself, and again under the lanes past the piece (finite values, never used)
            for (int i = count + 1; i <= count + lanes; i++) { x[i] = x[count]; y[i] = y[count]; z[i] = z[count]; }
            Span<float> radius = laneRadius;
            new ReadOnlySpan<float>(ringRadii, first, count).CopyTo(radius);
            radius.Slice(count, lanes).Clear();
            Span<float> tx = laneTX, ty = laneTY, tz = laneTZ, distance = laneDistance, gap = laneGap, cap = laneCap, previous = lanePrevious;
            var countLanes = new Vector<int>(count);
            Vector<int> failed = Vector<int>.Zero;

            // the tangents: ring i's neighbours are scratch slots i and i + 2; run j of lanes is rings i = lanes·j …,
            // read and written through views of whole vectors from slot 0, 1 or 2 (Runs: one range check a vector)
            var one = new Vector<float>(1f);
            var tiny = new Vector<float>(1e-20f);
            int runs = (count + lanes - 1) / lanes;
            {
                ReadOnlySpan<Vector<float>> x0 = Runs(x, 0, runs), y0 = Runs(y, 0, runs), z0 = Runs(z, 0, runs);
                ReadOnlySpan<Vector<float>> x2 = Runs(x, 2, runs), y2 = Runs(y, 2, runs), z2 = Runs(z, 2, runs);
                Span<Vector<float>> distanceRuns = Runs(distance, 0, runs), txRuns = Runs(tx, 0, runs), tyRuns = Runs(ty, 0, runs), tzRuns = Runs(tz, 0, runs);
                for (int j = 0; j < runs; j++)
                {
                    Vector<float> dx = x2[j] - x0[j], dy = y2[j] - y0[j], dz = z2[j] - z0[j];
                    Vector<float> lengthSquared = dx * dx + dy * dy + dz * dz;
                    Vector<float> length = Vector.SquareRoot(lengthSquared);
                    Vector<int> inside = Vector.LessThan(laneIndex + new Vector<int>(j * lanes), countLanes);
                    failed |= Vector.AndNot(inside, Vector.GreaterThan(lengthSquared, tiny));
                    Vector<float> inverse = one / length;
                    distanceRuns[j] = length;
                    txRuns[j] = dx * inverse;
                    tyRuns[j] = dy * inverse;
                    tzRuns[j] = dz * inverse;
                }
            }
            if (!Vector.EqualsAll(failed, Vector<int>.Zero)) return false;

            // the pairs i − 1, i: ring i's centre is scratch slot i + 1
            const float held = TipRoom * 1.001f;
            const float skew2 = SkewLimit * SkewLimit;
            const float margin2 = CrossingMargin * CrossingMargin;
            var zero = Vector<float>.Zero;
            var infinity = new Vector<float>(float.PositiveInfinity);
            var chordShare = new Vector<float>(FoldSkew * FoldSkew);
            var margin = new Vector<float>(CrossingMargin);
            var foldRadius = new Vector<float>(FoldRadius);
            var heldLanes = new Vector<float>(held);
            var skewLanes = new Vector<float>(skew2);
            var marginLanes = new Vector<float>(margin2);
            // run j of pairs: rings i − 1, i for i = 1 + lanes·j …, through views from slot 0, 1 or 2
            int pairRuns = (count - 1 + lanes - 1) / lanes;
            ReadOnlySpan<Vector<float>> x1 = Runs(x, 1, pairRuns), y1 = Runs(y, 1, pairRuns), z1 = Runs(z, 1, pairRuns);
            ReadOnlySpan<Vector<float>> xa = Runs(x, 2, pairRuns), ya = Runs(y, 2, pairRuns), za = Runs(z, 2, pairRuns);
            ReadOnlySpan<Vector<float>> pxRuns = Runs(tx, 0, pairRuns), pyRuns = Runs(ty, 0, pairRuns), pzRuns = Runs(tz, 0, pairRuns);
            ReadOnlySpan<Vector<float>> qxRuns = Runs(tx, 1, pairRuns), qyRuns = Runs(ty, 1, pairRuns), qzRuns = Runs(tz, 1, pairRuns);
            ReadOnlySpan<Vector<float>> radiusHere = Runs(radius, 1, pairRuns), radiusBefore = Runs(radius, 0, pairRuns);
            Span<Vector<float>> gapRuns = Runs(gap, 1, pairRuns), capRuns = Runs(cap, 1, pairRuns), previousRuns = Runs(previous, 0, pairRuns);
            Span<Vector<float>> cosineRuns = Runs(laneCosine, 1, pairRuns), kxRuns = Runs(laneKX, 1, pairRuns), kyRuns = Runs(laneKY, 1, pairRuns), kzRuns = Runs(laneKZ, 1, pairRuns);
            for (int j = 0; j < pairRuns; j++)
            {
                int i = 1 + j * lanes;
                Vector<float> sx = xa[j] - x1[j], sy = ya[j] - y1[j], sz = za[j] - z1[j];
                Vector<float> gap2 = sx * sx + sy * sy + sz * sz;
                Vector<float> px = pxRuns[j], py = pyRuns[j], pz = pzRuns[j];
                Vector<float> qx = qxRuns[j], qy = qyRuns[j], qz = qzRuns[j];
                Vector<float> past = sx * px + sy * py + sz * pz, before = sx * qx + sy * qy + sz * qz;
                // ClearOfFold, then LimitPair's skew marks (none on the lanes)
                Vector<float> chord2 = gap2 * chordShare;
                Vector<int> clear = Vector.GreaterThan(past, zero) & Vector.GreaterThan(before, zero)
                    & Vector.GreaterThanOrEqual(past * margin, foldRadius * radiusHere[j] * heldLanes)
                    & Vector.GreaterThanOrEqual(before * margin, foldRadius * radiusBefore[j] * heldLanes)
                    & Vector.GreaterThanOrEqual(past * past, chord2) & Vector.GreaterThanOrEqual(before * before, chord2);
                Vector<float> skewGap = skewLanes * gap2;
                Vector<int> skews = Vector.LessThan(past * past, skewGap) | Vector.LessThan(past, zero)
                    | Vector.LessThan(before * before, skewGap) | Vector.LessThan(before, zero);
                Vector<int> inside = Vector.LessThan(laneIndex + new Vector<int>(i), countLanes);
                failed |= Vector.AndNot(inside, clear) | (inside & skews);
                gapRuns[j] = gap2;
                // LimitPair's caps: the pair's cap of ring i (+∞ unless lower) and of ring i − 1 (+∞: none)
                Vector<float> nx = py * qz - pz * qy, ny = pz * qx - px * qz, nz = px * qy - py * qx;
                // the transport's cosine and axis of the pair (FrameTransport.Transported's operations in its order)
                cosineRuns[j] = px * qx + py * qy + pz * qz;
                kxRuns[j] = nx; kyRuns[j] = ny; kzRuns[j] = nz;
                Vector<float> sine2 = nx * nx + ny * ny + nz * nz;
                Vector<int> bent = Vector.GreaterThan(sine2, zero);
                Vector<float> scale = marginLanes / sine2;
                Vector<float> capNext = past * past * scale, capPrevious = before * before * scale;
                capRuns[j] = Vector.ConditionalSelect(bent & Vector.LessThan(capNext, infinity), capNext, infinity);
                previousRuns[j] = Vector.ConditionalSelect(bent, capPrevious, infinity);
            }
            if (!Vector.EqualsAll(failed, Vector<int>.Zero)) return false;

            // everything final: into the ring arrays (ring 0 has no pair behind it, the last ring none ahead)
            Span<Float3> tangent = new Span<Float3>(tangents, first, count);
            cap[0] = float.PositiveInfinity;
            previous[count - 1] = float.PositiveInfinity;
            gap[0] = 0f;
            {
                // each ring's cap, the scalar's merge (behind < ahead ? behind : ahead) as a select, into the cap scratch
                Span<Vector<float>> aheadRuns = Runs(cap, 0, runs);
                ReadOnlySpan<Vector<float>> behindRuns = Runs(previous, 0, runs);
                for (int j = 0; j < aheadRuns.Length; j++)
                {
                    Vector<float> ahead = aheadRuns[j], behind = behindRuns[j];
                    aheadRuns[j] = Vector.ConditionalSelect(Vector.LessThan(behind, ahead), behind, ahead);
                }
            }
            ReadOnlySpan<float> ux = tx.Slice(0, tangent.Length), uy = ty.Slice(0, tangent.Length), uz = tz.Slice(0, tangent.Length);
            for (int i = 0; i < tangent.Length; i++) tangent[i] = new Float3(ux[i], uy[i], uz[i]);
            cap.Slice(0, count).CopyTo(new Span<float>(capSquared, first, count));
            distance.Slice(0, count).CopyTo(new Span<float>(slopeDistance, first, count));
            gap.Slice(0, count).CopyTo(new Span<float>(gapSquared, first, count));
            new Span<bool>(foldTip, first, count).Clear();
            new Span<bool>(skewed, first, count).Clear();
            return true;
        }

        /// <summary><paramref name="runs"/> whole vectors of <paramref name="values"/> from slot <paramref name="from"/>: vector j holds slots from + lanes·j ….</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static Span<Vector<float>> Runs(Span<float> values, int from, int runs) => VectorPath.AsLanes(values.Slice(from)).Slice(0, runs);

        /// <summary>
        /// Pass 2 of <see cref="FramesClearOfFolds"/>: the normals of the <paramref name="count"/> rings from
        /// <paramref name="first"/> along their finished tangents, the first ring's from the last build's normal at
        /// particle <paramref name="a"/> (re-projected only when its tangent changed), each next by parallel transport;
        /// <paramref name="prepared"/>: with the pairs' cosines and cross products <see cref="FramePassOnLanes"/> left in
        /// the lane scratch (ring i at slot i).
        /// </summary>
        private void TransportNormals(int a, int first, int count, bool prepared)
        {
            ReadOnlySpan<Float3> tangent = new ReadOnlySpan<Float3>(tangents, first, count);
            Span<Float3> normal = new Span<Float3>(normals, first, count).Slice(0, tangent.Length);
            Float3 t0 = tangent[0];
            Float3 n = particleNormal[a];
            if (!(particleFrameValid[a] && particleTangent[a].Equals(t0)))
                n = FrameTransport.Perpendicular(n.X, n.Y, n.Z, t0.X, t0.Y, t0.Z);
            normal[0] = n;
            // the rings whose re-normalisation holds in the call-free run; from a ring that needs Perpendicular's axis
            // fallback on, ring by ring (rare), then the run again
            int i = 1;
            while ((i = prepared
                       ? FrameTransport.TransportRun(tangent, normal, i, laneCosine, laneKX, laneKY, laneKZ)
                       : FrameTransport.TransportRun(tangent, normal, i)) < tangent.Length)
            {
                Float3 before = tangent[i - 1], t = tangent[i];
                n = normal[i - 1];
                normal[i] = FrameTransport.Transported(n.X, n.Y, n.Z, before.X, before.Y, before.Z, t.X, t.Y, t.Z);
                i++;
            }
        }

        /// <summary><see cref="FallbackTangent"/> by value (out of line: pass 1 rarely needs it).</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        private static Float3 FallbackTangentOf(bool hasBehind, bool hasAhead, Float3 here, Float3 ahead, Float3 behind, Float3 previous)
        {
            FallbackTangent(hasBehind, hasAhead, here, ahead, behind, previous.X, previous.Y, previous.Z, out float tx, out float ty, out float tz);
            return new Float3(tx, ty, tz);
        }

        /// <summary>Keeps each particle's ring frame of piece [a, b] (the seed of the next build's transport).</summary>
        private void KeepParticleFrames(int a, int b)
        {
            // spans of exactly the piece's particles (their ring index read once, one range check per ring array)
            ReadOnlySpan<int> ring = layout.FirstRings.Slice(a, b - a + 1);
            Span<Float3> keptNormal = new Span<Float3>(particleNormal, a, ring.Length).Slice(0, ring.Length);
            Span<Float3> keptTangent = new Span<Float3>(particleTangent, a, ring.Length).Slice(0, ring.Length);
            ReadOnlySpan<Float3> normal = normals, tangent = tangents;
            for (int i = 0; i < ring.Length; i++)
            {
                int k = ring[i];
                keptNormal[i] = normal[k];
                keptTangent[i] = tangent[k];
            }
            new Span<bool>(particleFrameValid, a, ring.Length).Fill(true);
        }
    }
}
