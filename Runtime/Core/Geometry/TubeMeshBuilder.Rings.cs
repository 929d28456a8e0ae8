using System;
using System.Numerics;
using System.Runtime.InteropServices;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// The per-ring work of <see cref="TubeMeshBuilder"/>: ring centres on the Catmull–Rom curve, parallel-transported
    /// frames, radius slopes, and the ring kernel that writes a ring's vertices. Written as scalar loops over the ring
    /// arrays (no <c>Float3</c> temporaries), so the cost does not depend on what a JIT or an ahead-of-time compiler inlines;
    /// the vertex kernel writes each vertex as three 4-float lanes, A + B·cos + C·sin with A, B, C per ring (see
    /// <see cref="WriteRing"/>), the cosines, sines and u of the sides taken from tables made once per builder.
    /// </summary>
    internal sealed partial class TubeMeshBuilder
    {
        private Float3[] centers = Array.Empty<Float3>();
        private Float3[] tangents = Array.Empty<Float3>();
        private Float3[] normals = Array.Empty<Float3>();
        private float[] ringRadii = Array.Empty<float>();
        private float[] ringV = Array.Empty<float>();
        private float[] slopes = Array.Empty<float>();
        private float[] slopeDistance = Array.Empty<float>();
        private float[] spacing2 = Array.Empty<float>();
        private bool[] dirty = Array.Empty<bool>();
        // the piece's raw ring centres per axis, indexed from the piece's first ring (ComputeCenters' lanes)
        private float[] rawX = Array.Empty<float>(), rawY = Array.Empty<float>(), rawZ = Array.Empty<float>();
        // the piece's Catmull–Rom weights per ring, indexed from the piece's first ring (CatmullRomWeights)
        private float[] weight0 = Array.Empty<float>(), weight1 = Array.Empty<float>(), weight2 = Array.Empty<float>(), weight3 = Array.Empty<float>();
        private Float3[] particleNormal;
        private Float3[] particleTangent;
        private bool[] particleFrameValid;

        private void AllocateParticleFrames(int segmentCount)
        {
            particleNormal = new Float3[segmentCount + 1];
            particleTangent = new Float3[segmentCount + 1];
            particleFrameValid = new bool[segmentCount + 1];
            outer0X = new float[segmentCount + 1]; outer0Y = new float[segmentCount + 1]; outer0Z = new float[segmentCount + 1];
            outer3X = new float[segmentCount + 1]; outer3Y = new float[segmentCount + 1]; outer3Z = new float[segmentCount + 1];
        }

        // the outer control points p0 and p3 of each segment of the piece, indexed by j − a (PrepareControlPoints)
        private float[] outer0X, outer0Y, outer0Z, outer3X, outer3Y, outer3Z;

        /// <summary>Grows the per-ring arrays to hold <paramref name="rings"/> rings (keeps their contents).</summary>
        private void EnsureRingStorage(int rings)
        {
            if (centers.Length >= rings) return;
            int size = Math.Max(rings, 2 * centers.Length);
            Array.Resize(ref centers, size);
            Array.Resize(ref tangents, size);
            Array.Resize(ref normals, size);
            Array.Resize(ref ringRadii, size);
            Array.Resize(ref ringV, size);
            Array.Resize(ref slopes, size);
            Array.Resize(ref slopeDistance, size);
            Array.Resize(ref spacing2, size);
            Array.Resize(ref dirty, size);
            Array.Resize(ref rawX, size);
            Array.Resize(ref rawY, size);
            Array.Resize(ref rawZ, size);
            Array.Resize(ref weight0, size);
            Array.Resize(ref weight1, size);
            Array.Resize(ref weight2, size);
            Array.Resize(ref weight3, size);
            Array.Resize(ref lastRadii, size);
            EnsureFoldStorage(size);
            EnsureLaneStorage(size);
        }

        /// <summary>
        /// Ring centres of piece [a, b] (rings first … last) relative to the frame origin: on the particles, or on the
        /// segment's Catmull–Rom cubic (the control points as <see cref="Vector4"/> lanes x, y, z, 0, once per segment: each
        /// ring's centre is then four lane products and three lane sums, the scalar's operations in its order per lane).
        /// Two passes: the raw centres (<see cref="centers"/>, and per axis in <see cref="rawX"/> …), then the settling
        /// (<see cref="SettleCenters"/>: a non-finite centre takes the previous one, a ring too close to the previous one is
        /// pushed, the spacing² kept), with the vector paths on first on <see cref="Vector{T}"/> lanes
        /// (<see cref="SettleCentersOnLanes"/>) as far as no ring needs either.
        /// </summary>
        private void ComputeCenters(int a, int b, int first, int last, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z)
        {
            // read first: the switch is a static field, whose first read may call the runtime
            bool lanes = VectorPath.Enabled;
            // spans of exactly the piece's rings, indexed by i = k − first (the loop's bound is their length)
            int count = last - first + 1;
            Span<Float3> centre = new Span<Float3>(centers, first, count);
            ReadOnlySpan<int> ringSegments = layout.RingSegments.Slice(first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> ringFractions = layout.RingFractions.Slice(first, count).Slice(0, centre.Length);
            Span<float> cx4 = new Span<float>(rawX, 0, count).Slice(0, centre.Length);
            Span<float> cy4 = new Span<float>(rawY, 0, count).Slice(0, centre.Length);
            Span<float> cz4 = new Span<float>(rawZ, 0, count).Slice(0, centre.Length);
            CatmullRomWeights(ringFractions, lanes);
            ReadOnlySpan<float> weightOf0 = new ReadOnlySpan<float>(weight0, 0, count).Slice(0, centre.Length);
            ReadOnlySpan<float> weightOf1 = new ReadOnlySpan<float>(weight1, 0, count).Slice(0, centre.Length);
            ReadOnlySpan<float> weightOf2 = new ReadOnlySpan<float>(weight2, 0, count).Slice(0, centre.Length);
            ReadOnlySpan<float> weightOf3 = new ReadOnlySpan<float>(weight3, 0, count).Slice(0, centre.Length);
            // the particles' spans of one length (the shortest: every index the loop takes is read from all three), so an
            // index checked against it once is in range for all three
            int particles = Math.Min(x.Length, Math.Min(y.Length, z.Length));
            x = x.Slice(0, particles);
            y = y.Slice(0, x.Length);
            z = z.Slice(0, x.Length);
            float ox = frameOrigin.X, oy = frameOrigin.Y, oz = frameOrigin.Z;
            // the control points of the segment the rings are in (the rings of a segment are consecutive)
            int held = -1;
            Vector4 p0 = default, p1 = default, p2 = default, p3 = default;
            // with the vector paths on, the outer control points of every segment first (their limits on lanes)
            if (lanes) PrepareControlPoints(a, b, x, y, z, ox, oy, oz);
            ReadOnlySpan<float> outerX0 = outer0X, outerY0 = outer0Y, outerZ0 = outer0Z, outerX3 = outer3X, outerY3 = outer3Y, outerZ3 = outer3Z;
            for (int i = 0; i < centre.Length; i++)
            {
                int j = ringSegments[i];
                float t = ringFractions[i];
                float cx, cy, cz;
                if (i == centre.Length - 1)
                {
                    cx = x[b] - ox; cy = y[b] - oy; cz = z[b] - oz;
                }
                else if (t == 0f)
                {
                    cx = x[j] - ox; cy = y[j] - oy; cz = z[j] - oz;
                }
                else
                {
                    if (j != held)
                    {
                        if (lanes)
                        {
                            // RopePieces.ControlPoints' p1 and p2 (the particles), and its p0 and p3 as prepared
                            int s = j - a;
                            p0 = new Vector4(outerX0[s], outerY0[s], outerZ0[s], 0f);
                            p1 = new Vector4(x[j] - ox, y[j] - oy, z[j] - oz, 0f);
                            p2 = new Vector4(x[j + 1] - ox, y[j + 1] - oy, z[j + 1] - oz, 0f);
                            p3 = new Vector4(outerX3[s], outerY3[s], outerZ3[s], 0f);
                        }
                        else
                        {
                            RopePieces.ControlPoints(j, a, b, x, y, z, ox, oy, oz, out float p0x, out float p0y, out float p0z,
                                out float p1x, out float p1y, out float p1z, out float p2x, out float p2y, out float p2z, out float p3x, out float p3y, out float p3z);
                            p0 = new Vector4(p0x, p0y, p0z, 0f);
                            p1 = new Vector4(p1x, p1y, p1z, 0f);
                            p2 = new Vector4(p2x, p2y, p2z, 0f);
                            p3 = new Vector4(p3x, p3y, p3z, 0f);
                        }
                        held = j;
                    }
                    // the uniform Catmull–Rom weights of t (CatmullRomWeights)
                    Vector4 c4 = p0 * weightOf0[i] + p1 * weightOf1[i] + p2 * weightOf2[i] + p3 * weightOf3[i];
                    cx = c4.X; cy = c4.Y; cz = c4.Z;
                }
                centre[i] = new Float3(cx, cy, cz);
                cx4[i] = cx; cy4[i] = cy; cz4[i] = cz;
            }
            SettleCenters(a, b, first, count, 0, 1, x, y, z);
            int next = 1;
            if (lanes && count > Vector<float>.Count + 1 && float.IsFinite(cx4[0]) && float.IsFinite(cy4[0]) && float.IsFinite(cz4[0]))
                next = SettleCentersOnLanes(first, count);
            SettleCenters(a, b, first, count, next, count, x, y, z);
        }

        /// <summary>
        /// The outer control points p0 and p3 of every segment j of piece [a, b] (<see cref="RopePieces.ControlPoints"/>,
        /// relative to the origin (<paramref name="ox"/>, <paramref name="oy"/>, <paramref name="oz"/>)) into
        /// <see cref="outer0X"/> … at j − a: the interior segments (both neighbours in the piece) on <see cref="Vector{T}"/>
        /// lanes as long as no tangent of a block needs its limit (<see cref="OuterControlPointsOnLanes"/>), the end segments,
        /// the tail and the rest from a limited block by <see cref="RopePieces.ControlPoints"/>.
        /// </summary>
        private void PrepareControlPoints(int a, int b, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, float ox, float oy, float oz)
        {
            int segments = b - a;
            int next = 1;
            if (segments > Vector<float>.Count + 2) next = OuterControlPointsOnLanes(a, b, x, y, z, ox, oy, oz);
            for (int s = 0; s < segments; s++)
            {
                if (s == 1) s = next;
                if (s >= segments) break;
                RopePieces.ControlPoints(a + s, a, b, x, y, z, ox, oy, oz, out outer0X[s], out outer0Y[s], out outer0Z[s],
                    out _, out _, out _, out _, out _, out _, out outer3X[s], out outer3Y[s], out outer3Z[s]);
            }
        }

        /// <summary>
        /// <see cref="PrepareControlPoints"/> of the interior segments a + 1, a + 2, … on <see cref="Vector{T}"/> lanes,
        /// <see cref="Vector{T}"/>.Count segments a step while the block's last segment has both neighbours in the piece:
        /// per lane RopePieces.ControlPoints' operations in its order (p0 the particle before, p3 the particle after, the
        /// tangent test of RopePieces.Limit on each); a block where a lane's tangent needs its limit ends the run. Returns
        /// the first segment (as j − a) not prepared.
        /// </summary>
        private int OuterControlPointsOnLanes(int a, int b, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, float ox, float oy, float oz)
        {
            // block p is segments j = a + 1 + 8p … a + 8 + 8p (with 8 lanes); the particles j − 1, j, j + 1, j + 2 from
            // a, a + 1, a + 2, a + 3 on, as whole vectors of the interior segments' count
            int interior = b - a - 2;
            ReadOnlySpan<Vector<float>> x3 = MemoryMarshal.Cast<float, Vector<float>>(x.Slice(a + 3, interior));
            ReadOnlySpan<Vector<float>> y3 = MemoryMarshal.Cast<float, Vector<float>>(y.Slice(a + 3, interior)).Slice(0, x3.Length);
            ReadOnlySpan<Vector<float>> z3 = MemoryMarshal.Cast<float, Vector<float>>(z.Slice(a + 3, interior)).Slice(0, x3.Length);
            ReadOnlySpan<Vector<float>> x2 = MemoryMarshal.Cast<float, Vector<float>>(x.Slice(a + 2, interior)).Slice(0, x3.Length);
            ReadOnlySpan<Vector<float>> y2 = MemoryMarshal.Cast<float, Vector<float>>(y.Slice(a + 2, interior)).Slice(0, x3.Length);
            ReadOnlySpan<Vector<float>> z2 = MemoryMarshal.Cast<float, Vector<float>>(z.Slice(a + 2, interior)).Slice(0, x3.Length);
            ReadOnlySpan<Vector<float>> x1 = MemoryMarshal.Cast<float, Vector<float>>(x.Slice(a + 1, interior)).Slice(0, x3.Length);
            ReadOnlySpan<Vector<float>> y1 = MemoryMarshal.Cast<float, Vector<float>>(y.Slice(a + 1, interior)).Slice(0, x3.Length);
            ReadOnlySpan<Vector<float>> z1 = MemoryMarshal.Cast<float, Vector<float>>(z.Slice(a + 1, interior)).Slice(0, x3.Length);
            ReadOnlySpan<Vector<float>> x0 = MemoryMarshal.Cast<float, Vector<float>>(x.Slice(a, interior)).Slice(0, x3.Length);
            ReadOnlySpan<Vector<float>> y0 = MemoryMarshal.Cast<float, Vector<float>>(y.Slice(a, interior)).Slice(0, x3.Length);
            ReadOnlySpan<Vector<float>> z0 = MemoryMarshal.Cast<float, Vector<float>>(z.Slice(a, interior)).Slice(0, x3.Length);
            Span<Vector<float>> q0x = MemoryMarshal.Cast<float, Vector<float>>(new Span<float>(outer0X, 1, interior)).Slice(0, x3.Length);
            Span<Vector<float>> q0y = MemoryMarshal.Cast<float, Vector<float>>(new Span<float>(outer0Y, 1, interior)).Slice(0, x3.Length);
            Span<Vector<float>> q0z = MemoryMarshal.Cast<float, Vector<float>>(new Span<float>(outer0Z, 1, interior)).Slice(0, x3.Length);
            Span<Vector<float>> q3x = MemoryMarshal.Cast<float, Vector<float>>(new Span<float>(outer3X, 1, interior)).Slice(0, x3.Length);
            Span<Vector<float>> q3y = MemoryMarshal.Cast<float, Vector<float>>(new Span<float>(outer3Y, 1, interior)).Slice(0, x3.Length);
            Span<Vector<float>> q3z = MemoryMarshal.Cast<float, Vector<float>>(new Span<float>(outer3Z, 1, interior)).Slice(0, x3.Length);
            Vector<float> vx = new Vector<float>(ox), vy = new Vector<float>(oy), vz = new Vector<float>(oz);
            var half = new Vector<float>(0.5f);
            var limit = new Vector<float>(RopePieces.TangentLimit * RopePieces.TangentLimit);
            for (int p = 0; p < q3z.Length; p++)
            {
                Vector<float> p1x = x1[p] - vx, p1y = y1[p] - vy, p1z = z1[p] - vz;
                Vector<float> p2x = x2[p] - vx, p2y = y2[p] - vy, p2z = z2[p] - vz;
                Vector<float> ex = p2x - p1x, ey = p2y - p1y, ez = p2z - p1z;
                Vector<float> chord2 = ex * ex + ey * ey + ez * ez;
                // p0 against p1 (its segment end) and p2 (the other end), as RopePieces.Limit
                Vector<float> p0x = x0[p] - vx, p0y = y0[p] - vy, p0z = z0[p] - vz;
                Vector<float> dx = p1x - p0x, dy = p1y - p0y, dz = p1z - p0z;
                Vector<float> outer2 = dx * dx + dy * dy + dz * dz;
                Vector<float> mx = half * (p2x - p0x), my = half * (p2y - p0y), mz = half * (p2z - p0z);
                Vector<float> tangent2 = mx * mx + my * my + mz * mz;
                Vector<float> limit2 = limit * Vector.ConditionalSelect(Vector.LessThan(outer2, chord2), outer2, chord2);
                if (Vector.GreaterThanAny(tangent2, limit2)) return 1 + p * Vector<float>.Count;
                // p3 against p2 and p1
                Vector<float> p3x = x3[p] - vx, p3y = y3[p] - vy, p3z = z3[p] - vz;
                dx = p2x - p3x; dy = p2y - p3y; dz = p2z - p3z;
                outer2 = dx * dx + dy * dy + dz * dz;
                mx = half * (p1x - p3x); my = half * (p1y - p3y); mz = half * (p1z - p3z);
                tangent2 = mx * mx + my * my + mz * mz;
                limit2 = limit * Vector.ConditionalSelect(Vector.LessThan(outer2, chord2), outer2, chord2);
                if (Vector.GreaterThanAny(tangent2, limit2)) return 1 + p * Vector<float>.Count;
                q0x[p] = p0x; q0y[p] = p0y; q0z[p] = p0z;
                q3x[p] = p3x; q3y[p] = p3y; q3z[p] = p3z;
            }
            return 1 + q3z.Length * Vector<float>.Count;
        }

        /// <summary>
        /// The uniform Catmull–Rom weights of each ring's fraction t, as RingLayout stores it (the Hermite cubic with the
        /// limited tangents, RopePieces.ControlPoints), into <see cref="weight0"/> … <see cref="weight3"/> from index 0:
        /// w0 = ½(−t + 2t² − t³), w1 = ½(2 − 5t² + 3t³), w2 = ½(t + 4t² − 3t³), w3 = ½(−t² + t³), with
        /// <paramref name="lanes"/> on <see cref="Vector{T}"/> lanes (per lane the scalar's operations in its order), the
        /// tail scalar.
        /// </summary>
        private void CatmullRomWeights(ReadOnlySpan<float> fractions, bool lanes)
        {
            int count = fractions.Length;
            Span<float> w0 = new Span<float>(weight0, 0, count), w1 = new Span<float>(weight1, 0, count).Slice(0, w0.Length);
            Span<float> w2 = new Span<float>(weight2, 0, count).Slice(0, w0.Length), w3 = new Span<float>(weight3, 0, count).Slice(0, w0.Length);
            int done = 0;
            if (lanes)
            {
                ReadOnlySpan<Vector<float>> t = MemoryMarshal.Cast<float, Vector<float>>(fractions);
                Span<Vector<float>> v0 = MemoryMarshal.Cast<float, Vector<float>>(w0).Slice(0, t.Length);
                Span<Vector<float>> v1 = MemoryMarshal.Cast<float, Vector<float>>(w1).Slice(0, t.Length);
                Span<Vector<float>> v2 = MemoryMarshal.Cast<float, Vector<float>>(w2).Slice(0, t.Length);
                Span<Vector<float>> v3 = MemoryMarshal.Cast<float, Vector<float>>(w3).Slice(0, t.Length);
                var half = new Vector<float>(0.5f);
                var two = new Vector<float>(2f);
                var three = new Vector<float>(3f);
                var four = new Vector<float>(4f);
                var five = new Vector<float>(5f);
                for (int p = 0; p < t.Length; p++)
                {
                    Vector<float> tp = t[p];
                    Vector<float> t2 = tp * tp, t3 = t2 * tp;
                    v0[p] = half * (-tp + two * t2 - t3);
                    v1[p] = half * (two - five * t2 + three * t3);
                    v2[p] = half * (tp + four * t2 - three * t3);
                    v3[p] = half * (-t2 + t3);
                }
                done = t.Length * Vector<float>.Count;
            }
            for (int i = done; i < w0.Length; i++)
            {
                float t = fractions[i];
                float t2 = t * t, t3 = t2 * t;
                w0[i] = 0.5f * (-t + 2f * t2 - t3);
                w1[i] = 0.5f * (2f - 5f * t2 + 3f * t3);
                w2[i] = 0.5f * (t + 4f * t2 - 3f * t3);
                w3[i] = 0.5f * (-t2 + t3);
            }
        }

        /// <summary>
        /// The settling of <see cref="ComputeCenters"/> for rings <paramref name="from"/> … <paramref name="to"/> − 1 of
        /// the piece's <paramref name="count"/> rings from <paramref name="first"/> (the rings before final): each raw centre
        /// that is not finite takes the previous ring's (ring 0: zero); a ring closer than <see cref="PushDistance"/>·r to
        /// the previous one is pushed on (<see cref="PushDirection"/>, its spacing² NaN); else its spacing² is kept
        /// (ring 0: +∞).
        /// </summary>
        private void SettleCenters(int a, int b, int first, int count, int from, int to,
            ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z)
        {
            Span<Float3> centre = new Span<Float3>(centers, first, count);
            Span<float> spacing = new Span<float>(spacing2, first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> radius = new ReadOnlySpan<float>(ringRadii, first, count).Slice(0, centre.Length);
            Float3 previous = from > 0 ? centre[from - 1] : Float3.Zero;
            for (int i = from; i < to; i++)
            {
                Float3 raw = centre[i];
                float cx = raw.X, cy = raw.Y, cz = raw.Z;
                if (!(float.IsFinite(cx) && float.IsFinite(cy) && float.IsFinite(cz)))
                {
                    Float3 fallback = i > 0 ? previous : Float3.Zero;
                    cx = fallback.X; cy = fallback.Y; cz = fallback.Z;
                }
                spacing[i] = float.PositiveInfinity;
                if (i > 0)
                {
                    // a ring closer than PushDistance·r to the previous one is pushed forward (no zero-area triangles)
                    float dx = cx - previous.X, dy = cy - previous.Y, dz = cz - previous.Z;
                    float minimum = PushDistance * radius[i] + 1e-7f;
                    float gap2 = dx * dx + dy * dy + dz * dz;
                    spacing[i] = gap2;
                    if (gap2 < minimum * minimum)
                    {
                        spacing[i] = float.NaN; // the centre now depends on the radius: no radius-only rebuild
                        PushDirection(a, b, i > 1, previous, i > 1 ? centre[i - 2] : previous, x, y, z,
                            out float ux, out float uy, out float uz);
                        cx = previous.X + ux * minimum; cy = previous.Y + uy * minimum; cz = previous.Z + uz * minimum;
                    }
                }
                previous = new Float3(cx, cy, cz);
                centre[i] = previous;
            }
        }

        /// <summary>
        /// <see cref="SettleCenters"/> from ring 1 on <see cref="Vector{T}"/> lanes, <see cref="Vector{T}"/>.Count rings a
        /// step from the per-axis raw centres (ring 0 finite), as long as every ring of a block is finite and not pushed:
        /// per lane the scalar's spacing² and push test in its order; such a ring keeps its raw centre, so the ring before
        /// a block is final. Returns the first ring it did not settle (a block with a ring that needs the scalar, or the
        /// tail shorter than a vector).
        /// </summary>
        private int SettleCentersOnLanes(int first, int count)
        {
            // block p is rings 1 + 8p … 8 + 8p (with 8 lanes), the rings before them 8p … 7 + 8p
            ReadOnlySpan<float> xs = new ReadOnlySpan<float>(rawX, 0, count), ys = new ReadOnlySpan<float>(rawY, 0, count), zs = new ReadOnlySpan<float>(rawZ, 0, count);
            ReadOnlySpan<Vector<float>> x1 = MemoryMarshal.Cast<float, Vector<float>>(xs.Slice(1));
            ReadOnlySpan<Vector<float>> y1 = MemoryMarshal.Cast<float, Vector<float>>(ys.Slice(1)).Slice(0, x1.Length);
            ReadOnlySpan<Vector<float>> z1 = MemoryMarshal.Cast<float, Vector<float>>(zs.Slice(1)).Slice(0, x1.Length);
            ReadOnlySpan<Vector<float>> x0 = MemoryMarshal.Cast<float, Vector<float>>(xs).Slice(0, x1.Length);
            ReadOnlySpan<Vector<float>> y0 = MemoryMarshal.Cast<float, Vector<float>>(ys).Slice(0, x1.Length);
            ReadOnlySpan<Vector<float>> z0 = MemoryMarshal.Cast<float, Vector<float>>(zs).Slice(0, x1.Length);
            ReadOnlySpan<Vector<float>> r = MemoryMarshal.Cast<float, Vector<float>>(new ReadOnlySpan<float>(ringRadii, first + 1, count - 1)).Slice(0, x1.Length);
            Span<Vector<float>> spacing = MemoryMarshal.Cast<float, Vector<float>>(new Span<float>(spacing2, first + 1, count - 1)).Slice(0, x1.Length);
            var push = new Vector<float>(PushDistance);
            var tiny = new Vector<float>(1e-7f);
            for (int p = 0; p < spacing.Length; p++)
            {
                Vector<float> cx = x1[p], cy = y1[p], cz = z1[p];
                // x − x is +0 for a finite x and NaN for ±∞ and NaN, so the sum is 0 only where all three are finite
                if (!Vector.EqualsAll((cx - cx) + (cy - cy) + (cz - cz), Vector<float>.Zero)) return 1 + p * Vector<float>.Count;
                Vector<float> dx = cx - x0[p], dy = cy - y0[p], dz = cz - z0[p];
                Vector<float> minimum = push * r[p] + tiny;
                Vector<float> gap2 = dx * dx + dy * dy + dz * dz;
                if (Vector.LessThanAny(gap2, minimum * minimum)) return 1 + p * Vector<float>.Count;
                spacing[p] = gap2;
            }
            return 1 + spacing.Length * Vector<float>.Count;
        }

        /// <summary>
        /// The direction a pushed ring moves along (out of the centre loop, which rarely needs it): from the ring before the
        /// previous to the previous (<paramref name="hasBefore"/>), else, or where those coincide, the piece's first particle
        /// to its last, else +x.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        private void PushDirection(int a, int b, bool hasBefore, in Float3 previous, in Float3 before,
            ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, out float ux, out float uy, out float uz)
        {
            if (hasBefore)
            {
                ux = previous.X - before.X; uy = previous.Y - before.Y; uz = previous.Z - before.Z;
                if (Normalize(ref ux, ref uy, ref uz)) return;
            }
            float ox = frameOrigin.X, oy = frameOrigin.Y, oz = frameOrigin.Z;
            ux = (x[b] - ox) - (x[a] - ox); uy = (y[b] - oy) - (y[a] - oy); uz = (z[b] - oz) - (z[a] - oz);
            if (!Normalize(ref ux, ref uy, ref uz) || !(float.IsFinite(ux) && float.IsFinite(uy) && float.IsFinite(uz))) { ux = 1f; uy = 0f; uz = 0f; }
        }

        /// <summary>
        /// Tangents (central differences of the centres) and normals by parallel transport from the piece's first ring,
        /// whose normal is the last build's normal at that particle, re-projected only when its tangent changed (so the
        /// tube does not spin between frames, and the same input gives the same bits). The same loop takes each pair of
        /// consecutive rings' fold test and geometric limits (<see cref="LimitPair"/>: the step between their centres, its
        /// advance past both planes, the crossing caps and skew marks), which need that pair's final centres and tangents
        /// and nothing further along; the fans next to fold tips follow (<see cref="LimitTipFans"/>) only when the piece has
        /// a tip. Returns true when the ring distances it left in <see cref="slopeDistance"/> hold for
        /// <see cref="ComputeSlopes"/> (no fold tip moved a centre); <paramref name="anySkewed"/> tells whether a ring was
        /// marked skewed.
        /// </summary>
        private bool ComputeFrames(int a, int b, int first, int last, out bool anySkewed)
        {
            // a piece without folds: the two passes (the same bits)
            if (!ForceFullLimits && FramesClearOfFolds(a, first, last, out anySkewed))
            {
                KeepParticleFrames(a, b);
                return true;
            }
            // the ring arrays once (RepairFold writes centers[k] through the field: the same array)
            ReadOnlySpan<Float3> c = centers;
            Span<Float3> tangent = tangents, normal = normals;
            Span<float> distance = slopeDistance, cap = capSquared, gap = gapSquared;
            Span<bool> tip = foldTip, skew = skewed;
            Float3 span = c[last] - c[first];
            float px = span.X, py = span.Y, pz = span.Z;
            if (!Normalize(ref px, ref py, ref pz)) { px = 1f; py = 0f; pz = 0f; }
            // (px, py, pz): ring k − 1's tangent, before the first ring the piece's direction (the last fallback)
            float nx = 0f, ny = 0f, nz = 0f;
            bool moved = false, tips = false, skews = false;
            for (int k = first; k <= last; k++)
            {
                Float3 here = c[k];
                Float3 ahead = k < last ? c[k + 1] : here;
                Float3 behind = k > first ? c[k - 1] : here;
                float tx = ahead.X - behind.X, ty = ahead.Y - behind.Y, tz = ahead.Z - behind.Z;
                // the length is ComputeSlopes' ring distance (the same centres)
                if (!Normalize(ref tx, ref ty, ref tz, out distance[k]))
                    FallbackTangent(k > first, k < last, here, ahead, behind, px, py, pz, out tx, out ty, out tz);
                tip[k] = false;
                cap[k] = float.PositiveInfinity;
                skew[k] = false;
                if (k == first)
                {
                    gap[k] = 0f;
                    Float3 seed = particleNormal[a];
                    nx = seed.X; ny = seed.Y; nz = seed.Z;
                    if (!(particleFrameValid[a] && particleTangent[a].Equals(new Float3(tx, ty, tz))))
                        FrameTransport.Perpendicular(ref nx, ref ny, ref nz, tx, ty, tz);
                }
                else
                {
                    // ring k − 1's tangent is (px, py, pz), its centre behind: the step s between the two centres and its
                    // advance past both planes, for the fold test and, once the pair is final, its limits
                    float sx = here.X - behind.X, sy = here.Y - behind.Y, sz = here.Z - behind.Z;
                    float gap2 = sx * sx + sy * sy + sz * sz;
                    float past = sx * px + sy * py + sz * pz, before = sx * tx + sy * ty + sz * tz;
                    if (!ClearOfFold(k, gap2, past, before) && RepairFold(k, ref tx, ref ty, ref tz))
                    {
                        moved = true;
                        here = c[k];
                        sx = here.X - behind.X; sy = here.Y - behind.Y; sz = here.Z - behind.Z;
                        gap2 = sx * sx + sy * sy + sz * sz;
                        past = sx * px + sy * py + sz * pz; before = sx * tx + sy * ty + sz * tz;
                    }
                    gap[k] = gap2;
                    LimitPair(k, gap2, past, before, px, py, pz, tx, ty, tz, cap, skew, tip, ref skews);
                    FrameTransport.Transport(ref nx, ref ny, ref nz, px, py, pz, tx, ty, tz);
                }
                tips |= tip[k];
                tangent[k] = new Float3(tx, ty, tz);
                normal[k] = new Float3(nx, ny, nz);
                px = tx; py = ty; pz = tz;
            }
            KeepParticleFrames(a, b);
            if (tips) LimitTipFans(first, last);
            anySkewed = skews;
            // a fold tip moved a centre after its neighbours' distances were taken: ComputeSlopes measures them again
            return !moved;
        }

        /// <summary>
        /// A ring's tangent where its neighbours' centres coincide (out of the frame loop, which rarely needs it): the step
        /// to the ring ahead, else the step from the ring behind, else the previous tangent (px, py, pz).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        private static void FallbackTangent(bool hasBehind, bool hasAhead, in Float3 here, in Float3 ahead, in Float3 behind,
            float px, float py, float pz, out float tx, out float ty, out float tz)
        {
            bool found = false;
            tx = 0f; ty = 0f; tz = 0f;
            if (hasAhead)
            {
                Float3 d = ahead - here;
                tx = d.X; ty = d.Y; tz = d.Z;
                found = Normalize(ref tx, ref ty, ref tz);
            }
            if (!found && hasBehind)
            {
                Float3 d = here - behind;
                tx = d.X; ty = d.Y; tz = d.Z;
                found = Normalize(ref tx, ref ty, ref tz);
            }
            if (!found) { tx = px; ty = py; tz = pz; }
        }

        /// <summary>
        /// Radius slopes dr/ds over the distance between each ring's neighbours (the ring itself at a piece's end). The
        /// frames took those distances already (the length of the central difference they normalise), bit for bit the
        /// same, unless a fold tip moved a centre afterwards (<paramref name="distancesKept"/> false, from <see cref="ComputeFrames"/>).
        /// With the vector paths on, the interior rings' slopes are taken on <see cref="Vector{T}"/> lanes
        /// (<see cref="InteriorSlopesOnLanes"/>), the end rings and the tail on the scalar loop.
        /// </summary>
        private void ComputeSlopes(int first, int last, bool distancesKept)
        {
            // read first: the switch is a static field, whose first read may call the runtime
            bool lanes = VectorPath.Enabled;
            // spans of exactly the piece's rings, indexed by i = k − first
            int count = last - first + 1;
            ReadOnlySpan<Float3> c = new ReadOnlySpan<Float3>(centers, first, count);
            ReadOnlySpan<float> r = new ReadOnlySpan<float>(ringRadii, first, count).Slice(0, c.Length);
            ReadOnlySpan<bool> tip = new ReadOnlySpan<bool>(foldTip, first, count).Slice(0, c.Length);
            Span<float> distance = new Span<float>(slopeDistance, first, count).Slice(0, c.Length);
            Span<float> slope = new Span<float>(slopes, first, count).Slice(0, c.Length);
            if (!distancesKept)
            {
                for (int i = 0; i < c.Length; i++)
                {
                    int ahead = i < c.Length - 1 ? i + 1 : i;
                    int behind = i > 0 ? i - 1 : i;
                    Float3 ca = c[ahead], cb = c[behind];
                    float dx = ca.X - cb.X, dy = ca.Y - cb.Y, dz = ca.Z - cb.Z;
                    distance[i] = MathF.Sqrt(dx * dx + dy * dy + dz * dz);
                }
            }
            if (lanes && c.Length > Vector<float>.Count + 1)
            {
                // ring 0, the interior rings 1 … done − 1 on lanes (a fold tip's slope is 0: set afterwards), the rest
                int done = InteriorSlopesOnLanes(r, distance, slope);
                ScalarSlopes(0, 1, r, tip, distance, slope);
                if (tip.Slice(1, done - 1).IndexOf(true) >= 0)
                    for (int i = 1; i < done; i++)
                        if (tip[i]) slope[i] = 0f;
                ScalarSlopes(done, c.Length, r, tip, distance, slope);
            }
            else ScalarSlopes(0, c.Length, r, tip, distance, slope);
        }

        /// <summary>The slopes of rings <paramref name="from"/> … <paramref name="to"/> − 1 of a piece's spans (<see cref="ComputeSlopes"/>).</summary>
        private static void ScalarSlopes(int from, int to, ReadOnlySpan<float> r, ReadOnlySpan<bool> tip, ReadOnlySpan<float> distance, Span<float> slope)
        {
            for (int i = from; i < to; i++)
            {
                int ahead = i < r.Length - 1 ? i + 1 : i;
                int behind = i > 0 ? i - 1 : i;
                slope[i] = tip[i] ? 0f : Slope(r[ahead], r[behind], distance[i]);
            }
        }

        /// <summary>
        /// <see cref="Slope"/> of the interior rings 1, 2, … of a piece's spans (at least two rings more than a vector's
        /// lanes), <see cref="Vector{T}"/>.Count rings a step while the block's ring ahead is in the piece: per lane the scalar's operations (the quotient where the
        /// distance is above 1e-12, else +0; below −10 or NaN −10; above 10 10), fold tips not looked at. Returns the
        /// first ring not written.
        /// </summary>
        internal static int InteriorSlopesOnLanes(ReadOnlySpan<float> r, ReadOnlySpan<float> distance, Span<float> slope)
        {
            var small = new Vector<float>(1e-12f);
            var low = new Vector<float>(-MaxSlope);
            var high = new Vector<float>(MaxSlope);
            // block p is rings 1 + 8p … 8 + 8p (with 8 lanes): the radii ahead from ring 2 on, behind from ring 0, the
            // distances and slopes from ring 1, as whole vectors; the bound is the blocks whose ring ahead is in the piece
            ReadOnlySpan<Vector<float>> ahead = MemoryMarshal.Cast<float, Vector<float>>(r.Slice(2));
            ReadOnlySpan<Vector<float>> behind = MemoryMarshal.Cast<float, Vector<float>>(r).Slice(0, ahead.Length);
            ReadOnlySpan<Vector<float>> d = MemoryMarshal.Cast<float, Vector<float>>(distance.Slice(1)).Slice(0, ahead.Length);
            Span<Vector<float>> s = MemoryMarshal.Cast<float, Vector<float>>(slope.Slice(1)).Slice(0, ahead.Length);
            for (int p = 0; p < s.Length; p++)
            {
                Vector<float> q = Vector.ConditionalSelect(Vector.GreaterThan(d[p], small), (ahead[p] - behind[p]) / d[p], Vector<float>.Zero);
                q = Vector.ConditionalSelect(Vector.GreaterThanOrEqual(q, low), q, low);
                s[p] = Vector.ConditionalSelect(Vector.GreaterThan(q, high), high, q);
            }
            return 1 + s.Length * Vector<float>.Count;
        }

        /// <summary>dr/ds between two rings <paramref name="distance"/> apart, clamped to ±10 (NaN counts as −10).</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        internal static float Slope(float ahead, float behind, float distance)
        {
            float slope = distance > 1e-12f ? (ahead - behind) / distance : 0f;
            if (!(slope >= -MaxSlope)) slope = -MaxSlope;
            if (slope > MaxSlope) slope = MaxSlope;
            return slope;
        }

        /// <summary>
        /// The radius work alone (positions unchanged): new drawn radii (the kept ring limits applied), slopes from the kept
        /// ring distances, and a ring marked for rewriting only when its drawn radius or slope changed.
        /// </summary>
        private void UpdateRadii(int first, int last, ReadOnlySpan<float> radii)
        {
            LimitRadii(first, last, radii);
            for (int k = first; k <= last; k++)
            {
                float r = drawnRadii[k];
                dirty[k] = BitConverter.SingleToInt32Bits(r) != BitConverter.SingleToInt32Bits(ringRadii[k]);
                ringRadii[k] = r;
            }
            for (int k = first; k <= last; k++)
            {
                int ahead = k < last ? k + 1 : k;
                int behind = k > first ? k - 1 : k;
                float slope = foldTip[k] ? 0f : Slope(ringRadii[ahead], ringRadii[behind], slopeDistance[k]);
                if (BitConverter.SingleToInt32Bits(slope) != BitConverter.SingleToInt32Bits(slopes[k])) { slopes[k] = slope; dirty[k] = true; }
            }
            // normals drawn from the strips depend on the neighbours' radii too
            if (MarkStripNormals(first, last))
                for (int k = first; k <= last; k++) dirty[k] = true;
        }

        /// <summary>
        /// The ring kernel: writes ring <paramref name="k"/>'s radial + 1 vertices (seam duplicated) into <paramref name="ring"/>.
        /// Every field of a ring's vertex i is linear in (cos φ_i, sin φ_i): field = A + B·cos φ_i + C·sin φ_i (+ u_i), with
        /// A, B, C worked out once per ring (position: c, r·n, r·b, then + the frame origin o; normal: −slope·t, n, b, all over sqrt(1 + slope²);
        /// tangent: 0, b, −n). The 48-byte vertex is three 4-float lanes (position.xyz normal.x | normal.yz tangent.xy |
        /// tangent.zw u v), so a vertex is 6 multiplications, 8 additions and 3 stores of 4-float vectors, read from the
        /// side table (<see cref="SideLanes"/>: cos, sin and u of each side) made once per builder, written in place in
        /// SetVertexBufferData's layout. Where <see cref="Vector{T}"/> of float has 8 lanes (AVX2) and the vector paths are
        /// on, two vertices at a time are three 8-float vectors (<see cref="PairLanes"/>), each float with the same
        /// operations in the same order (<see cref="WritePairs"/>; the odd last vertex of an even side count is the seam).
        /// </summary>
        private void WriteRing(int k, Span<TubeVertex> ring) => WriteRings(k, k, ring);

        /// <summary>
        /// <see cref="WriteRing"/> for rings <paramref name="first"/> … <paramref name="last"/>, each written by the ring
        /// kernel into the next radial + 1 vertices of <paramref name="rings"/> (one ring: at most radial + 1 of them). One
        /// call per piece: the switch, the tables and the frame origin's lanes are read once, not once per ring.
        /// </summary>
        private void WriteRings(int first, int last, Span<TubeVertex> rings)
        {
            // read first: the switch is a static field, whose first read may call the runtime, which would push the
            // ring's coefficients out of registers
            bool wide = Vector<float>.Count == 8 && VectorPath.Enabled;
            ReadOnlySpan<SideLanes> sides = sideLanes;
            int stride = first == last ? Math.Min(rings.Length, sides.Length) : sides.Length;
            if (wide && sixteenSided && stride == 2 * UnrolledPairs + 1)
            {
                WriteSixteenSidedRings(first, last - first + 1, rings);
                return;
            }
            var o0 = new Vector4(frameOrigin.X, frameOrigin.Y, frameOrigin.Z, 0f);
            // the wide kernel's coefficient vectors, two 4-float lanes each, through the builder's scratch (no
            // allocation): the origin's (and −0's) once, the ring's per ring
            Span<Vector<float>> coefficients = ringCoefficients;
            Span<Vector4> half = MemoryMarshal.Cast<Vector<float>, Vector4>(coefficients);
            ReadOnlySpan<PairLanes> pairs = pairLanes;
            if (wide)
            {
                var negativeZero = new Vector4(-0f);
                half[21] = o0; half[20] = negativeZero; half[19] = negativeZero; half[18] = o0;
            }
            // the rings' values from spans of exactly the rings (the loop's bound is their length)
            int count = last - first + 1;
            ReadOnlySpan<Float3> centre = new ReadOnlySpan<Float3>(centers, first, count);
            ReadOnlySpan<Float3> tangent = new ReadOnlySpan<Float3>(tangents, first, count).Slice(0, centre.Length);
            ReadOnlySpan<Float3> normal = new ReadOnlySpan<Float3>(normals, first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> radius = new ReadOnlySpan<float>(ringRadii, first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> slopeOf = new ReadOnlySpan<float>(slopes, first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> vOf = new ReadOnlySpan<float>(ringV, first, count).Slice(0, centre.Length);
            for (int k = 0, at = 0; k < centre.Length; k++, at += stride)
            {
                RingCoefficients(centre[k], tangent[k], normal[k], radius[k], slopeOf[k],
                    out Vector4 a0, out Vector4 b0, out Vector4 c0, out Vector4 a1, out Vector4 b1, out Vector4 c1, out Vector4 c2, out float bz);
                float v = vOf[k];
                Span<VertexLanes> vertices = MemoryMarshal.Cast<TubeVertex, VertexLanes>(rings.Slice(at, stride));
                if (wide && vertices.Length >= 2)
                {
                    // the wide kernel: vertices 2p and 2p + 1 are the 24 floats First Middle | Last First | Middle Last, three
                    // 8-float vectors, each ((B·cos + C·sin) + A) + O with B, C, A, O per ring in that lane pattern (O the frame
                    // origin on the position lanes and −0 elsewhere, which adds nothing; the third vector has no O) and cos, sin
                    // per pair of sides (PairLanes). The last lane's u moves into the cos table (1·u + 0·sin + −0 is u, as
                    // 0·cos + 0·sin + u is) and its other constants a2 + U are added here, as the loop below adds them per
                    // vertex (0 + 0, 0 + 1, v + 0).
                    var a2u = new Vector4(0f + 0f, 0f + 1f, -0f, v + 0f);
                    var b2u = new Vector4(bz, 0f, 1f, 0f);
                    half[0] = b0; half[1] = b1; half[2] = b2u; half[3] = b0; half[4] = b1; half[5] = b2u;
                    half[6] = c0; half[7] = c1; half[8] = c2; half[9] = c0; half[10] = c1; half[11] = c2;
                    half[12] = a0; half[13] = a1; half[14] = a2u; half[15] = a0; half[16] = a1; half[17] = a2u;
                    WritePairs(vertices, pairs, coefficients);
                    continue;
                }
                var a2 = new Vector4(0f, 0f, 0f, v);
                var b2 = new Vector4(bz, 0f, 0f, 0f);
                // one table entry and one vertex per side, read and written through refs: the loop runs over the vertices'
                // span, so its index is range-checked only against the side table (once per side, not once per lane)
                for (int i = 0; i < vertices.Length; i++)
                {
                    ref readonly SideLanes side = ref sides[i];
                    ref VertexLanes vertex = ref vertices[i];
                    Vector4 ci = side.Cos, si = side.Sin;
                    vertex.Last = (b2 * ci + c2 * si) + (a2 + side.U);
                    vertex.First = ((b0 * ci + c0 * si) + a0) + o0;
                    vertex.Middle = (b1 * ci + c1 * si) + a1;
                }
            }
        }

        /// <summary>
        /// The wide kernel's loop (<see cref="WriteRing"/>), with the ring's coefficient vectors in
        /// <paramref name="q"/> (<see cref="ringCoefficients"/>) and the pair table <paramref name="pairs"/> (<see cref="pairLanes"/>): pairs of vertices, then an odd last vertex as the first 8 floats of a pair and
        /// the last 4 through the scratch vector (the same operations per float); at the seam, a copy of vertex 0 with the
        /// seam's u. Inlined: the eleven coefficient vectors stay in registers through the loop.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private void WritePairs(Span<VertexLanes> vertices, ReadOnlySpan<PairLanes> pairs, Span<Vector<float>> q)
        {
            Vector<float> bA = q[0], bB = q[1], bC = q[2], cA = q[3], cB = q[4], cC = q[5];
            Vector<float> aA = q[6], aB = q[7], aC = q[8], oA = q[9], oB = q[10];
            // one table entry and one pair of vertices per step, through refs (one range check each, as the 4-float loop)
            Span<VertexPair> wide = MemoryMarshal.Cast<VertexLanes, VertexPair>(vertices);
            if (wide.Length > pairs.Length) wide = wide.Slice(0, pairs.Length);
            for (int p = 0; p < wide.Length; p++)
                WritePair(ref wide[p], in pairs[p], bA, bB, bC, cA, cB, cC, aA, aB, aC, oA, oB);
            int last = 2 * wide.Length;
            if (last >= vertices.Length) return;
            if (last == pairSeam)
            {
                // the odd last vertex is the seam, side 0 again (cos 1, sin 0: the same operations on the same numbers give
                // the same bits) but for its u
                Span<TubeVertex> plain = MemoryMarshal.Cast<VertexLanes, TubeVertex>(vertices);
                plain[last] = plain[0];
                plain[last].U = seamU;
            }
            else if (wide.Length < pairs.Length)
            {
                // another odd last vertex: floats 0–7 are the pair's first vector (in the ring: the vertex is 12 floats),
                // 8–11 the low half of its second
                ref readonly PairLanes side = ref pairs[wide.Length];
                MemoryMarshal.Cast<VertexLanes, Vector<float>>(vertices.Slice(last))[0] = ((bA * side.CosA + cA * side.SinA) + aA) + oA;
                q[11] = ((bB * side.CosB + cB * side.SinB) + aB) + oB;
                vertices[last].Last = MemoryMarshal.Cast<Vector<float>, Vector4>(q)[22];
            }
        }

        /// <summary>
        /// The wide kernel (<see cref="WriteRing"/>) of 16 sides, the default, for the <paramref name="count"/> rings from
        /// <paramref name="first"/>, 17 vertices each: the ring's coefficient vectors as <see cref="WriteRings"/> makes them
        /// (<see cref="RingCoefficients"/>, through <see cref="ringCoefficients"/>: 12 stores of 4 floats and 11 loads of 8 a ring), then the eight
        /// pairs in a row (<see cref="WritePair"/>'s operations written out, the table entries fields of <see cref="sixteenPairs"/>, the ring one
        /// <see cref="SixteenSidedRing"/>: constant offsets, no range check, no loop counter) and the seam, a copy of vertex 0
        /// with the seam's u (<see cref="MakePairLanes"/> checked that its cos and sin are side 0's bits).
        /// </summary>
        private void WriteSixteenSidedRings(int first, int count, Span<TubeVertex> rings)
        {
            var o0 = new Vector4(frameOrigin.X, frameOrigin.Y, frameOrigin.Z, 0f);
            // the coefficient vectors through the scratch as groups of four halves X0 X1 X2 X0 (B, C, A, then O), so the
            // lane patterns X0 X1 and X2 X0 are whole vectors and X1 X2 a vector of the view shifted by one half; the
            // views' lengths are constants, so their constant indices need no range check
            Span<Vector<float>> q = new Span<Vector<float>>(ringCoefficients, 0, 8);
            Span<Vector4> half = MemoryMarshal.Cast<Vector<float>, Vector4>(q).Slice(0, 16);
            Span<Vector<float>> shifted = MemoryMarshal.Cast<Vector4, Vector<float>>(half.Slice(1, 14));
            var negativeZero = new Vector4(-0f);
            half[12] = o0; half[13] = negativeZero; half[14] = negativeZero; half[15] = o0;
            ReadOnlySpan<Float3> centre = new ReadOnlySpan<Float3>(centers, first, count);
            ReadOnlySpan<Float3> tangent = new ReadOnlySpan<Float3>(tangents, first, count).Slice(0, centre.Length);
            ReadOnlySpan<Float3> normal = new ReadOnlySpan<Float3>(normals, first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> radius = new ReadOnlySpan<float>(ringRadii, first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> slopeOf = new ReadOnlySpan<float>(slopes, first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> vOf = new ReadOnlySpan<float>(ringV, first, count).Slice(0, centre.Length);
            float u = seamU;
            ref readonly SixteenPairLanes table = ref sixteenPairs;
            for (int k = 0, at = 0; k < centre.Length; k++, at += 2 * UnrolledPairs + 1)
            {
                RingCoefficients(centre[k], tangent[k], normal[k], radius[k], slopeOf[k],
                    out Vector4 a0, out Vector4 b0, out Vector4 c0, out Vector4 a1, out Vector4 b1, out Vector4 c1, out Vector4 c2, out float bz);
                float v = vOf[k];
                var a2u = new Vector4(0f + 0f, 0f + 1f, -0f, v + 0f);
                var b2u = new Vector4(bz, 0f, 1f, 0f);
                half[0] = b0; half[1] = b1; half[2] = b2u; half[3] = b0;
                half[4] = c0; half[5] = c1; half[6] = c2; half[7] = c0;
                half[8] = a0; half[9] = a1; half[10] = a2u; half[11] = a0;
                Vector<float> bA = q[0], bB = q[1], bC = shifted[0], cA = q[2], cB = q[3], cC = shifted[2];
                Vector<float> aA = q[4], aB = q[5], aC = shifted[4], oA = q[6], oB = q[7];
                Span<TubeVertex> vertices = rings.Slice(at, 2 * UnrolledPairs + 1);
                ref SixteenSidedRing ring = ref MemoryMarshal.Cast<TubeVertex, SixteenSidedRing>(vertices)[0];
                // each pair WritePair's three vectors, written out: refs to the fields through a helper would cost two address
                // computations a pair, field accesses are constant offsets from the ring and the table
                ring.Pair0.First = ((bA * table.Pair0.CosA + cA * table.Pair0.SinA) + aA) + oA;
                ring.Pair0.Middle = ((bB * table.Pair0.CosB + cB * table.Pair0.SinB) + aB) + oB;
                ring.Pair0.Last = (bC * table.Pair0.CosC + cC * table.Pair0.SinC) + aC;
                ring.Pair1.First = ((bA * table.Pair1.CosA + cA * table.Pair1.SinA) + aA) + oA;
                ring.Pair1.Middle = ((bB * table.Pair1.CosB + cB * table.Pair1.SinB) + aB) + oB;
                ring.Pair1.Last = (bC * table.Pair1.CosC + cC * table.Pair1.SinC) + aC;
                ring.Pair2.First = ((bA * table.Pair2.CosA + cA * table.Pair2.SinA) + aA) + oA;
                ring.Pair2.Middle = ((bB * table.Pair2.CosB + cB * table.Pair2.SinB) + aB) + oB;
                ring.Pair2.Last = (bC * table.Pair2.CosC + cC * table.Pair2.SinC) + aC;
                ring.Pair3.First = ((bA * table.Pair3.CosA + cA * table.Pair3.SinA) + aA) + oA;
                ring.Pair3.Middle = ((bB * table.Pair3.CosB + cB * table.Pair3.SinB) + aB) + oB;
                ring.Pair3.Last = (bC * table.Pair3.CosC + cC * table.Pair3.SinC) + aC;
                ring.Pair4.First = ((bA * table.Pair4.CosA + cA * table.Pair4.SinA) + aA) + oA;
                ring.Pair4.Middle = ((bB * table.Pair4.CosB + cB * table.Pair4.SinB) + aB) + oB;
                ring.Pair4.Last = (bC * table.Pair4.CosC + cC * table.Pair4.SinC) + aC;
                ring.Pair5.First = ((bA * table.Pair5.CosA + cA * table.Pair5.SinA) + aA) + oA;
                ring.Pair5.Middle = ((bB * table.Pair5.CosB + cB * table.Pair5.SinB) + aB) + oB;
                ring.Pair5.Last = (bC * table.Pair5.CosC + cC * table.Pair5.SinC) + aC;
                ring.Pair6.First = ((bA * table.Pair6.CosA + cA * table.Pair6.SinA) + aA) + oA;
                ring.Pair6.Middle = ((bB * table.Pair6.CosB + cB * table.Pair6.SinB) + aB) + oB;
                ring.Pair6.Last = (bC * table.Pair6.CosC + cC * table.Pair6.SinC) + aC;
                ring.Pair7.First = ((bA * table.Pair7.CosA + cA * table.Pair7.SinA) + aA) + oA;
                ring.Pair7.Middle = ((bB * table.Pair7.CosB + cB * table.Pair7.SinB) + aB) + oB;
                ring.Pair7.Last = (bC * table.Pair7.CosC + cC * table.Pair7.SinC) + aC;
                // the seam is side 0 again (cos 1, sin 0: the same operations on the same numbers give the same bits) but for its u
                vertices[2 * UnrolledPairs] = vertices[0];
                vertices[2 * UnrolledPairs].U = u;
            }
        }

        /// <summary>
        /// A ring's coefficient lanes (<see cref="WriteRing"/>) from its centre <paramref name="c"/>, tangent
        /// <paramref name="t"/>, normal <paramref name="nrm"/>, radius <paramref name="r"/> and radius slope: A, B, C of the
        /// vertex's first and middle 4-float lanes and C of its last, and the binormal's z (B of the last lane's first float).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static void RingCoefficients(Float3 c, Float3 t, Float3 nrm, float r, float slope, out Vector4 a0, out Vector4 b0,
            out Vector4 c0, out Vector4 a1, out Vector4 b1, out Vector4 c1, out Vector4 c2, out float bz)
        {
            float nx = nrm.X, ny = nrm.Y, nz = nrm.Z;
            // binormal = t × n
            float bx = t.Y * nz - t.Z * ny, by = t.Z * nx - t.X * nz;
            bz = t.X * ny - t.Y * nx;
            // the normal tilts for a varying radius: (e_r − slope·t)/sqrt(1 + slope²)
            float inverse = 1f / MathF.Sqrt(1f + slope * slope);
            float sx = t.X * slope, sy = t.Y * slope, sz = t.Z * slope;
            // the radial offset first, then the centre, then the origin: (c + offset) + origin rounds monotonically in the
            // offset, so the ring's bounds (c ± r·sqrt(1 − t²)·(1 + 1e-6), + origin) hold its vertices
            a0 = new Vector4(c.X, c.Y, c.Z, -(sx * inverse));
            b0 = new Vector4(nx * r, ny * r, nz * r, nx * inverse);
            c0 = new Vector4(bx * r, by * r, bz * r, bx * inverse);
            a1 = new Vector4(-(sy * inverse), -(sz * inverse), 0f, 0f);
            b1 = new Vector4(ny * inverse, nz * inverse, bx, by);
            c1 = new Vector4(by * inverse, bz * inverse, -nx, -ny);
            c2 = new Vector4(-nz, 0f, 0f, 0f);
        }

        /// <summary>The 17 vertices of a 16-sided ring as the wide kernel writes them: eight pairs and the seam.</summary>
        [StructLayout(LayoutKind.Sequential)]
        private struct SixteenSidedRing
        {
            public VertexPair Pair0, Pair1, Pair2, Pair3, Pair4, Pair5, Pair6, Pair7;
            public TubeVertex Seam;
        }

        /// <summary>The first eight entries of the pair table (<see cref="pairLanes"/>) of 16 sides, read at constant offsets.</summary>
        private struct SixteenPairLanes
        {
            public PairLanes Pair0, Pair1, Pair2, Pair3, Pair4, Pair5, Pair6, Pair7;
        }

        // the 16-sided wide kernel's table (WriteSixteenSidedRings), set with pairLanes where it applies
        private SixteenPairLanes sixteenPairs;
        private bool sixteenSided;

        /// <summary>The pairs <see cref="WriteSixteenSidedRings"/> writes without a loop: 16 sides (the default) make 8 pairs and the seam.</summary>
        private const int UnrolledPairs = 8;

        /// <summary>
        /// One pair of vertices of the wide kernel (<see cref="WritePairs"/>): each of its three 8-float vectors
        /// ((B·cos + C·sin) + A) + O, the third with no O. Inlined, so the coefficient vectors stay in registers.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static void WritePair(ref VertexPair pair, in PairLanes side, Vector<float> bA, Vector<float> bB, Vector<float> bC,
            Vector<float> cA, Vector<float> cB, Vector<float> cC, Vector<float> aA, Vector<float> aB, Vector<float> aC,
            Vector<float> oA, Vector<float> oB)
        {
            pair.First = ((bA * side.CosA + cA * side.SinA) + aA) + oA;
            pair.Middle = ((bB * side.CosB + cB * side.SinB) + aB) + oB;
            pair.Last = (bC * side.CosC + cC * side.SinC) + aC;
        }

        /// <summary>
        /// The pair table of the wide kernel, made once per builder at its construction where <see cref="Vector{T}"/> of float has 8 lanes (the only width the wide kernel runs at): per pair of sides i = 2p, 2p + 1
        /// (the last side twice at an odd count) the cosines and sines in the wide kernel's lane pattern (<see cref="WriteRing"/>;
        /// cos φ_i in vertex i's lanes), with the cos lane under u holding u_i (its coefficient is 1).
        /// </summary>
        private PairLanes[] MakePairLanes()
        {
            ReadOnlySpan<SideLanes> sides = sideLanes;
            var table = new PairLanes[(sides.Length + 1) / 2];
            Span<float> cos = stackalloc float[24], sin = stackalloc float[24];
            for (int p = 0; p < table.Length; p++)
            {
                for (int f = 0; f < 24; f++)
                {
                    int i = Math.Min(2 * p + f / 12, sides.Length - 1);
                    cos[f] = f % 12 == 10 ? sides[i].U.Z : sides[i].Cos.X;
                    sin[f] = sides[i].Sin.X;
                }
                table[p] = new PairLanes(new Vector<float>(cos), new Vector<float>(cos.Slice(8)), new Vector<float>(cos.Slice(16)),
                    new Vector<float>(sin), new Vector<float>(sin.Slice(8)), new Vector<float>(sin.Slice(16)));
            }
            // the seam (the last side) writes side 0's bits but for u when their cos and sin are the same bits
            int seam = sides.Length - 1;
            bool same = BitConverter.SingleToInt32Bits(sides[seam].Cos.X) == BitConverter.SingleToInt32Bits(sides[0].Cos.X)
                && BitConverter.SingleToInt32Bits(sides[seam].Sin.X) == BitConverter.SingleToInt32Bits(sides[0].Sin.X);
            pairSeam = same && seam % 2 == 0 ? seam : -1;
            seamU = sides[seam].U.Z;
            sixteenSided = pairSeam == 2 * UnrolledPairs && table.Length > UnrolledPairs;
            if (sixteenSided)
                sixteenPairs = new SixteenPairLanes
                {
                    Pair0 = table[0], Pair1 = table[1], Pair2 = table[2], Pair3 = table[3],
                    Pair4 = table[4], Pair5 = table[5], Pair6 = table[6], Pair7 = table[7],
                };
            return table;
        }

        private readonly PairLanes[] pairLanes;
        private int pairSeam = -1;
        private float seamU;
        private readonly Vector<float>[] ringCoefficients = new Vector<float>[12];

        /// <summary>The wide kernel's table entry of two sides: cos and sin of their 24 floats as three 8-float vectors.</summary>
        private readonly struct PairLanes
        {
            public readonly Vector<float> CosA, CosB, CosC, SinA, SinB, SinC;

            public PairLanes(Vector<float> cosA, Vector<float> cosB, Vector<float> cosC, Vector<float> sinA, Vector<float> sinB, Vector<float> sinC)
            {
                CosA = cosA; CosB = cosB; CosC = cosC;
                SinA = sinA; SinB = sinB; SinC = sinC;
            }
        }

        /// <summary>The ring kernel's table entry of one side: cos φ and sin φ in every lane, and (0, 1, u, 0) for the last lane.</summary>
        private readonly struct SideLanes
        {
            public readonly Vector4 Cos, Sin, U;

            public SideLanes(Vector4 cos, Vector4 sin, Vector4 u)
            {
                Cos = cos;
                Sin = sin;
                U = u;
            }
        }

        /// <summary>A <see cref="TubeVertex"/> as the ring kernel writes it: position.xyz normal.x | normal.yz tangent.xy | tangent.zw u v.</summary>
        [StructLayout(LayoutKind.Sequential)]
        private struct VertexLanes
        {
            public Vector4 First, Middle, Last;
        }

        /// <summary>Two <see cref="TubeVertex"/> values as the wide kernel writes them: three 8-float vectors.</summary>
        [StructLayout(LayoutKind.Sequential)]
        private struct VertexPair
        {
            public Vector<float> First, Middle, Last;
        }

        /// <summary>
        /// The ring lies on the circle of radius r around c in the plane normal to t: per axis c ± r·sqrt(1 − t²)
        /// (<see cref="RingExtent"/>), and the box goes into the bounds with one comparison per axis and side (c − e ≤ c + e).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private void AddRingBounds(int k, ref Bounds bounds)
        {
            Float3 c = centers[k];
            Float3 e = RingExtent(tangents[k], ringRadii[k]);
            bounds.AddBox(c.X - e.X, c.Y - e.Y, c.Z - e.Z, c.X + e.X, c.Y + e.Y, c.Z + e.Z);
        }

        /// <summary>
        /// Half the extent per axis (m) of a ring of radius <paramref name="r"/> normal to unit <paramref name="t"/>:
        /// r·sqrt(max(0, 1 − t²))·(1 + 1e-6) per axis, the three square roots as one 4-lane square root (correctly rounded
        /// per lane, so the same bits as three scalar ones).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static Float3 RingExtent(Float3 t, float r)
        {
            var t4 = new Vector4(t.X, t.Y, t.Z, 0f);
            Vector4 root = Vector4.SquareRoot(Vector4.Max(Vector4.Zero, Vector4.One - t4 * t4));
            return new Float3(r * root.X * 1.000001f, r * root.Y * 1.000001f, r * root.Z * 1.000001f);
        }

        /// <summary>
        /// <see cref="AddRingBounds"/> for rings first … last: the box's corners carried in locals through the loop (the
        /// same comparisons in the same order, so the same bits) and written back once.
        /// </summary>
        private void AddRingsBounds(int first, int last, ref Bounds bounds)
        {
            int count = last - first + 1;
            // a piece whose frame pass ran on lanes: its centres and tangents are in the lane scratch
            if (lanePieceFirst == first && lanePieceCount == count && VectorPath.Enabled && AddRingsBoundsOnLanes(first, count, ref bounds))
                return;
            ReadOnlySpan<Float3> centre = new ReadOnlySpan<Float3>(centers, first, count);
            ReadOnlySpan<Float3> tangent = new ReadOnlySpan<Float3>(tangents, first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> radius = new ReadOnlySpan<float>(ringRadii, first, count).Slice(0, centre.Length);
            float minX = bounds.Min.X, minY = bounds.Min.Y, minZ = bounds.Min.Z;
            float maxX = bounds.Max.X, maxY = bounds.Max.Y, maxZ = bounds.Max.Z;
            for (int i = 0; i < centre.Length; i++)
            {
                Float3 c = centre[i];
                Float3 e = RingExtent(tangent[i], radius[i]);
                float ex = e.X, ey = e.Y, ez = e.Z;
                float lx = c.X - ex, ly = c.Y - ey, lz = c.Z - ez, hx = c.X + ex, hy = c.Y + ey, hz = c.Z + ez;
                minX = lx < minX ? lx : minX; minY = ly < minY ? ly : minY; minZ = lz < minZ ? lz : minZ;
                maxX = hx > maxX ? hx : maxX; maxY = hy > maxY ? hy : maxY; maxZ = hz > maxZ ? hz : maxZ;
            }
            bounds.Min = new Float3(minX, minY, minZ);
            bounds.Max = new Float3(maxX, maxY, maxZ);
        }

        /// <summary>(x, y, z) scaled to unit length and true, or unchanged and false when its length² is not above 1e-20 (as Float3.NormalizedOr).</summary>
        private static bool Normalize(ref float x, ref float y, ref float z) => Normalize(ref x, ref y, ref z, out _);

        /// <summary><see cref="Normalize(ref float, ref float, ref float)"/> that also gives the length of (x, y, z) before scaling (set either way).</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static bool Normalize(ref float x, ref float y, ref float z, out float length)
        {
            float lengthSquared = x * x + y * y + z * z;
            length = MathF.Sqrt(lengthSquared);
            if (!(lengthSquared > 1e-20f)) return false;
            float inverse = 1f / length;
            x *= inverse; y *= inverse; z *= inverse;
            return true;
        }
    }
}
