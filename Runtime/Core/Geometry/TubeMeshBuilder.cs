using System;
using HookeRope.Fracture;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Builds the procedural tube mesh of a rope into caller-owned buffers: rings along a Catmull–Rom curve through
    /// the particles, oriented by parallel transport, normals tilted for a varying radius, v along the rest arc
    /// length, flat caps at intact ends, and at each broken end a cap plus seeded burr strands. Vertex positions are
    /// relative to the first particle. The index buffer is rewritten only when the topology changes (first build,
    /// a newly broken segment, another index array). Allocation-free after construction.
    /// </summary>
    internal sealed class TubeMeshBuilder
    {
        private const float MaxSlope = 10f;

        private readonly TubeMeshSettings settings;
        private readonly RingLayout layout;
        private readonly int radial;
        private readonly bool capEnds;
        private readonly bool burrEnabled;
        private readonly int fibreCount;
        private readonly float[] cos;
        private readonly float[] sin;
        private readonly float[] w0, w1, w2, w3;
        private readonly Float3[] centers;
        private readonly Float3[] tangents;
        private readonly Float3[] normals;
        private readonly float[] ringRadii;
        private readonly float[] ringV;
        private readonly float[] slopes;
        private readonly double[] restArc;
        private readonly float[] particleRadii;
        private readonly bool[] lastBroken;
        private readonly int spareFirst;
        private readonly int[] stations;
        private DanglingEnds dangling;
        private int[] lastIndices;
        private Float3 frameOrigin;
        private HookeRope.Solver.Rope contactRope;
        private MeshFrame contactFrame;
        private bool topologyValid;

        /// <summary>Builder for <paramref name="segmentCount"/> segments (≥ 1) with settings.RingsPerSegment rings in each.</summary>
        public TubeMeshBuilder(TubeMeshSettings settings, int segmentCount)
            : this(settings, new RingLayout(segmentCount, (settings ?? throw new ArgumentNullException(nameof(settings))).RingsPerSegment))
        {
        }

        /// <summary>
        /// Builder with an explicit ring layout (e.g. adapted to the neck zone) for a rope of rest radius
        /// <paramref name="restRadius"/> (m; 0 = unknown), which sets the number of burr fibres at a broken end.
        /// </summary>
        internal TubeMeshBuilder(TubeMeshSettings settings, RingLayout layout, float restRadius = 0f)
        {
            this.settings = settings ?? throw new ArgumentNullException(nameof(settings));
            this.layout = layout ?? throw new ArgumentNullException(nameof(layout));
            radial = settings.RadialSegments;
            capEnds = settings.CapEnds;
            burrEnabled = settings.Burr.Enabled;
            fibreCount = settings.Burr.FibreCount(restRadius, radial);
            cos = new float[radial + 1];
            sin = new float[radial + 1];
            for (int i = 0; i <= radial; i++)
            {
                double angle = 2.0 * Math.PI * i / radial;
                cos[i] = i == radial ? 1f : (float)Math.Cos(angle);
                sin[i] = i == radial ? 0f : (float)Math.Sin(angle);
            }
            int rings = layout.RingCount;
            w0 = new float[rings]; w1 = new float[rings]; w2 = new float[rings]; w3 = new float[rings];
            ReadOnlySpan<float> fractions = layout.RingFractions;
            for (int k = 0; k < rings; k++)
            {
                float t = fractions[k], t2 = t * t, t3 = t2 * t;
                w0[k] = 0.5f * (-t + 2f * t2 - t3);
                w1[k] = 0.5f * (2f - 5f * t2 + 3f * t3);
                w2[k] = 0.5f * (t + 4f * t2 - 3f * t3);
                w3[k] = 0.5f * (-t2 + t3);
            }
            // the rings of a broken end's dangling half go to spare slots after the layout's (one half at a time)
            int spare = DanglingEnds.MaxRingCount(layout);
            spareFirst = rings;
            stations = new int[spare];
            centers = new Float3[rings + spare];
            tangents = new Float3[rings + spare];
            normals = new Float3[rings + spare];
            ringRadii = new float[rings + spare];
            ringV = new float[rings + spare];
            slopes = new float[rings + spare];
            int n = layout.SegmentCount;
            restArc = new double[n + 1];
            particleRadii = new float[n + 1];
            lastBroken = new bool[n];
        }

        /// <summary>The ring layout (ring count and stations).</summary>
        internal RingLayout Layout => layout;

        /// <summary>Number of rope segments.</summary>
        public int SegmentCount => layout.SegmentCount;

        /// <summary>Vertices around the tube (fixed at construction).</summary>
        public int RadialSegments => radial;

        /// <summary>Burr fibres at each broken end (fixed at construction; see <see cref="BurrSettings.FibreCount"/>).</summary>
        public int FibreCount => fibreCount;

        /// <summary>
        /// Colliders to keep the drawn tube out of (null = none): before a build whose positions are in
        /// <paramref name="frame"/> (placed in <paramref name="rope"/>'s world frame, where its colliders are), each
        /// ring centre closer to a collider than its drawn ring radius (radius × |frame scale| in metres) is pushed out
        /// along the collider's normal, so the drawn surface does not sink into a collider the rope wraps between its
        /// contact particles.
        /// </summary>
        internal void SetContactColliders(HookeRope.Solver.Rope rope, MeshFrame frame)
        {
            contactRope = rope;
            contactFrame = frame;
        }

        /// <summary>
        /// Draw each broken segment's two halves (null = none: the pieces end at the particles): every piece with a broken
        /// end continues straight along its end tangent by the half's drawn length to the cut, with the half's rings, and
        /// the cap and burr sit on the cut. Changes the vertex and index counts.
        /// </summary>
        internal void SetDanglingEnds(DanglingEnds ends)
        {
            if (ends != null && ends.SegmentCount != layout.SegmentCount)
                throw new ArgumentException("ends must hold SegmentCount = " + layout.SegmentCount + " segments.", nameof(ends));
            if (ReferenceEquals(ends, dangling)) return;
            dangling = ends;
            topologyValid = false;
        }

        /// <summary>Vertices the mesh needs for these broken-segment flags (empty = intact rope).</summary>
        public int GetVertexCount(ReadOnlySpan<bool> brokenSegments)
        {
            Count(brokenSegments, out int vertices, out _, out _);
            return vertices;
        }

        /// <summary>Indices the mesh needs for these broken-segment flags (tube, caps and burr strands).</summary>
        public int GetIndexCount(ReadOnlySpan<bool> brokenSegments)
        {
            Count(brokenSegments, out _, out int tube, out int burr);
            return tube + burr;
        }

        /// <summary>
        /// Builds the mesh from particle positions (m; SegmentCount + 1 each), rest segment lengths (m), per-segment
        /// radii (m; smoothed to the particles and interpolated to the rings) and broken flags (empty = none).
        /// </summary>
        public TubeMeshUpdate Build(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            ReadOnlySpan<float> restLengths, ReadOnlySpan<float> segmentRadii, ReadOnlySpan<bool> brokenSegments,
            TubeVertex[] vertices, int[] indices)
        {
            int n = layout.SegmentCount;
            if (segmentRadii.Length != n)
                throw new ArgumentException("segmentRadii must hold SegmentCount = " + n + " values.", nameof(segmentRadii));
            bool hasBroken = brokenSegments.Length > 0;
            for (int i = 0; i <= n; i++)
            {
                bool left = i > 0 && !(hasBroken && brokenSegments[i - 1]);
                bool right = i < n && !(hasBroken && brokenSegments[i]);
                float r;
                if (left && right) r = 0.5f * (segmentRadii[i - 1] + segmentRadii[i]);
                else if (left) r = segmentRadii[i - 1];
                else if (right) r = segmentRadii[i];
                else r = segmentRadii[i < n ? i : n - 1];
                particleRadii[i] = r;
            }
            ReadOnlySpan<int> segments = layout.RingSegments;
            ReadOnlySpan<float> fractions = layout.RingFractions;
            for (int k = 0; k < layout.RingCount; k++)
            {
                int j = segments[k];
                ringRadii[k] = particleRadii[j] + (particleRadii[j + 1] - particleRadii[j]) * fractions[k];
            }
            return BuildWithRingRadii(x, y, z, restLengths, ringRadii.AsSpan(0, layout.RingCount), brokenSegments, vertices, indices);
        }

        /// <summary>
        /// Builds the mesh from particle positions (m), rest segment lengths (m), one radius per ring (m;
        /// <see cref="RingLayout.RingCount"/> values, e.g. from RadiusModel.FillRadiiAt) and broken flags (empty =
        /// none). Non-finite or non-positive radii count as 1e-6 m; non-finite positions repeat the previous ring.
        /// Throws ArgumentException when a span has the wrong length or a buffer is too small.
        /// </summary>
        public TubeMeshUpdate BuildWithRingRadii(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            ReadOnlySpan<float> restLengths, ReadOnlySpan<float> radii, ReadOnlySpan<bool> brokenSegments,
            TubeVertex[] vertices, int[] indices)
        {
            int n = layout.SegmentCount;
            if (x.Length != n + 1 || y.Length != n + 1 || z.Length != n + 1)
                throw new ArgumentException("x, y and z must each hold SegmentCount + 1 = " + (n + 1) + " positions.", nameof(x));
            if (restLengths.Length != n)
                throw new ArgumentException("restLengths must hold SegmentCount = " + n + " values.", nameof(restLengths));
            if (radii.Length != layout.RingCount)
                throw new ArgumentException("radii must hold RingCount = " + layout.RingCount + " values.", nameof(radii));
            bool hasBroken = brokenSegments.Length > 0;
            if (hasBroken && brokenSegments.Length != n)
                throw new ArgumentException("brokenSegments must be empty or hold SegmentCount = " + n + " flags.", nameof(brokenSegments));
            if (vertices == null) throw new ArgumentNullException(nameof(vertices));
            if (indices == null) throw new ArgumentNullException(nameof(indices));
            Count(brokenSegments, out int vertexCount, out int tubeIndexCount, out int burrIndexCount);
            if (vertices.Length < vertexCount)
                throw new ArgumentException("vertices must hold at least GetVertexCount = " + vertexCount + " vertices.", nameof(vertices));
            if (indices.Length < tubeIndexCount + burrIndexCount)
                throw new ArgumentException("indices must hold at least GetIndexCount = " + (tubeIndexCount + burrIndexCount) + " indices.", nameof(indices));

            bool topologyChanged = !topologyValid || !ReferenceEquals(indices, lastIndices);
            for (int j = 0; j < n; j++)
            {
                bool b = hasBroken && brokenSegments[j];
                if (b != lastBroken[j]) { topologyChanged = true; lastBroken[j] = b; }
            }

            double arc = 0.0;
            restArc[0] = 0.0;
            for (int j = 0; j < n; j++) { arc += restLengths[j]; restArc[j + 1] = arc; }
            float vScale = settings.VPerMetre;
            ReadOnlySpan<int> ringSegments = layout.RingSegments;
            ReadOnlySpan<float> ringFractions = layout.RingFractions;
            for (int k = 0; k < layout.RingCount; k++)
            {
                int j = ringSegments[k];
                double s = restArc[j] + (restArc[j + 1] - restArc[j]) * ringFractions[k];
                ringV[k] = (float)(s * vScale);
                float r = radii[k];
                ringRadii[k] = float.IsFinite(r) && r > 1e-6f ? r : 1e-6f;
            }

            // Geometry is computed relative to the first particle (precision far from the origin); SetVertex adds the
            // origin back, so vertices and bounds are in the frame of the input positions.
            Float3 origin = new Float3(x[0], y[0], z[0]);
            if (!origin.IsFinite) origin = Float3.Zero;
            frameOrigin = origin;
            var bounds = new Bounds(true);
            int vertexBase = 0;
            int tubeCursor = 0;
            int burrCursor = tubeIndexCount;
            int segment = 0;
            while (NextPiece(brokenSegments, n, ref segment, out int a, out int b))
            {
                BuildPiece(a, b, x, y, z, origin, vertices, indices, topologyChanged,
                    ref vertexBase, ref tubeCursor, ref burrCursor, ref bounds);
            }

            if (topologyChanged) { lastIndices = indices; topologyValid = true; }
            if (vertexCount == 0) bounds = new Bounds(false);
            else { bounds.Min = bounds.Min + origin; bounds.Max = bounds.Max + origin; }
            return new TubeMeshUpdate(vertexCount, tubeIndexCount + burrIndexCount, tubeIndexCount, topologyChanged,
                bounds.Min, bounds.Max);
        }

        /// <summary>
        /// Finds the next intact piece at or after <paramref name="segment"/>: segments [a, b) with no break
        /// among them (an empty span means nothing is broken). Advances <paramref name="segment"/> to b.
        /// </summary>
        private static bool NextPiece(ReadOnlySpan<bool> brokenSegments, int n, ref int segment, out int a, out int b)
        {
            bool hasBroken = brokenSegments.Length > 0;
            while (segment < n && hasBroken && brokenSegments[segment]) segment++;
            a = segment;
            while (segment < n && !(hasBroken && brokenSegments[segment])) segment++;
            b = segment;
            return a < n;
        }

        private void Count(ReadOnlySpan<bool> brokenSegments, out int vertexCount, out int tubeIndexCount, out int burrIndexCount)
        {
            int n = layout.SegmentCount;
            bool hasBroken = brokenSegments.Length > 0;
            if (hasBroken && brokenSegments.Length != n)
                throw new ArgumentException("brokenSegments must be empty or hold SegmentCount = " + n + " flags.", nameof(brokenSegments));
            vertexCount = 0; tubeIndexCount = 0; burrIndexCount = 0;
            int segment = 0;
            while (NextPiece(brokenSegments, n, ref segment, out int a, out int b))
            {
                int rings = layout.FirstRing(b) - layout.FirstRing(a) + 1;
                vertexCount += rings * (radial + 1);
                tubeIndexCount += (rings - 1) * radial * 6;
                CountEnd(a > 0, a > 0 ? DanglingRingCount(a - 1, true) : 0, ref vertexCount, ref tubeIndexCount, ref burrIndexCount);
                CountEnd(b < n, b < n ? DanglingRingCount(b, false) : 0, ref vertexCount, ref tubeIndexCount, ref burrIndexCount);
            }
        }

        /// <summary>Rings the dangling half of broken segment j on the given side adds (0 without dangling ends).</summary>
        private int DanglingRingCount(int segment, bool upper) => dangling == null ? 0 : DanglingEnds.RingCount(layout, segment, upper);

        private void CountEnd(bool brokenEnd, int danglingRings, ref int vertexCount, ref int tubeIndexCount, ref int burrIndexCount)
        {
            vertexCount += danglingRings * (radial + 1);
            tubeIndexCount += danglingRings * radial * 6;
            if (brokenEnd || capEnds) { vertexCount += radial + 1; tubeIndexCount += radial * 3; }
            if (brokenEnd && burrEnabled) { vertexCount += fibreCount * 9; burrIndexCount += fibreCount * 9; }
        }

        private void BuildPiece(int a, int b, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            Float3 origin, TubeVertex[] vertices, int[] indices, bool writeIndices,
            ref int vertexBase, ref int tubeCursor, ref int burrCursor, ref Bounds bounds)
        {
            int n = layout.SegmentCount;
            int first = layout.FirstRing(a);
            int last = layout.FirstRing(b);
            ComputeCenters(a, b, first, last, x, y, z, origin);
            if (contactRope != null && contactRope.ColliderCount > 0) PushCentersOutOfColliders(first, last);
            ComputeFrames(first, last);
            ComputeSlopes(first, last);

            bool startBroken = a > 0, endBroken = b < n;
            int stride = radial + 1;
            // a broken start: the dangling upper half of segment a − 1 (spare slots, tip last), drawn from its tip inward
            int startRings = startBroken && dangling != null ? PlaceDanglingHalf(a - 1, true, first) : 0;
            int startTip = startRings > 0 ? spareFirst + startRings - 1 : first;
            if (startBroken || capEnds) WriteCap(startTip, false, vertices, indices, writeIndices, ref vertexBase, ref tubeCursor, ref bounds);
            if (startBroken && burrEnabled) WriteStrands(startTip, false, 2 * (a - 1) + 1, vertices, indices, writeIndices, ref vertexBase, ref burrCursor, ref bounds);
            for (int q = startRings - 1; q >= 0; q--)
            {
                WriteRing(spareFirst + q, vertices, vertexBase, ref bounds);
                WriteStrip(vertexBase, vertexBase + stride, indices, writeIndices, ref tubeCursor);
                vertexBase += stride;
            }

            for (int k = first; k <= last; k++)
            {
                int ringBase = vertexBase + (k - first) * stride;
                WriteRing(k, vertices, ringBase, ref bounds);
                if (k < last) WriteStrip(ringBase, ringBase + stride, indices, writeIndices, ref tubeCursor);
            }
            vertexBase += (last - first + 1) * stride;

            // a broken end: the dangling lower half of segment b, from the last ring out to its tip
            int endRings = endBroken && dangling != null ? PlaceDanglingHalf(b, false, last) : 0;
            for (int q = 0; q < endRings; q++)
            {
                WriteStrip(vertexBase - stride, vertexBase, indices, writeIndices, ref tubeCursor);
                WriteRing(spareFirst + q, vertices, vertexBase, ref bounds);
                vertexBase += stride;
            }
            int endTip = endRings > 0 ? spareFirst + endRings - 1 : last;
            if (endBroken || capEnds) WriteCap(endTip, true, vertices, indices, writeIndices, ref vertexBase, ref tubeCursor, ref bounds);
            if (endBroken && burrEnabled) WriteStrands(endTip, true, 2 * b, vertices, indices, writeIndices, ref vertexBase, ref burrCursor, ref bounds);
        }

        /// <summary>Two triangles per radial step between the rings whose first vertices are baseA and baseB (B further along v).</summary>
        private void WriteStrip(int baseA, int baseB, int[] indices, bool writeIndices, ref int tubeCursor)
        {
            if (!writeIndices) { tubeCursor += radial * 6; return; }
            for (int i = 0; i < radial; i++)
            {
                int a0 = baseA + i, a1 = a0 + 1, b0 = baseB + i, b1 = b0 + 1;
                indices[tubeCursor++] = a0; indices[tubeCursor++] = a1; indices[tubeCursor++] = b0;
                indices[tubeCursor++] = a1; indices[tubeCursor++] = b1; indices[tubeCursor++] = b0;
            }
        }

        /// <summary>
        /// Places the rings of a dangling half of broken segment <paramref name="segment"/> (upper: the half on particle
        /// segment + 1, joined to the piece's first ring; else on particle segment, joined to its last ring) in the spare
        /// slots, from the joint ring <paramref name="joint"/> out to the cut: straight along the joint's tangent (outward),
        /// with its frame, by each station's share of the half's drawn length; radii from the layout rings and the cut
        /// radius; v on the rest arc. Returns the number of rings (the last is the cut).
        /// </summary>
        private int PlaceDanglingHalf(int segment, bool upper, int joint)
        {
            int count = DanglingEnds.Stations(layout, segment, upper, stations);
            Float3 c = centers[joint], t = tangents[joint];
            Float3 outward = upper ? -t : t;
            float half = dangling.HalfLength(segment);
            float cutV = (float)((restArc[segment] + (restArc[segment + 1] - restArc[segment]) * DanglingEnds.Cut) * settings.VPerMetre);
            ReadOnlySpan<float> fractions = layout.RingFractions;
            for (int q = 0; q < count; q++)
            {
                int k = stations[q], slot = spareFirst + q;
                float fraction = k >= 0 ? fractions[k] : DanglingEnds.Cut;
                float r = k >= 0 ? ringRadii[k] : dangling.CutRadius(segment, upper);
                centers[slot] = c + outward * (half * DanglingEnds.ShareOfHalf(fraction, upper));
                tangents[slot] = t;
                normals[slot] = normals[joint];
                ringRadii[slot] = float.IsFinite(r) && r > 1e-6f ? r : 1e-6f;
                ringV[slot] = k >= 0 ? ringV[k] : cutV;
            }
            if (contactRope != null && contactRope.ColliderCount > 0) PushCentersOutOfColliders(spareFirst, spareFirst + count - 1);
            // dr/ds along the straight half (the joint ring keeps the slope its piece gave it)
            for (int q = 0; q < count; q++)
            {
                int slot = spareFirst + q;
                int behind = q > 0 ? slot - 1 : joint, ahead = q < count - 1 ? slot + 1 : slot;
                float distance = (centers[ahead] - centers[behind]).Length;
                float slope = distance > 1e-12f ? (ringRadii[ahead] - ringRadii[behind]) / distance : 0f;
                if (upper) slope = -slope;
                slopes[slot] = slope < -MaxSlope ? -MaxSlope : (slope > MaxSlope ? MaxSlope : slope);
            }
            return count;
        }

        private void ComputeCenters(int a, int b, int first, int last, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, Float3 origin)
        {
            ReadOnlySpan<int> ringSegments = layout.RingSegments;
            ReadOnlySpan<float> ringFractions = layout.RingFractions;
            Float3 fallbackDirection = (Particle(b, x, y, z, origin) - Particle(a, x, y, z, origin)).NormalizedOr(new Float3(1f, 0f, 0f));
            if (!fallbackDirection.IsFinite) fallbackDirection = new Float3(1f, 0f, 0f);
            for (int k = first; k <= last; k++)
            {
                int j = ringSegments[k];
                float t = ringFractions[k];
                Float3 c;
                if (k == last)
                {
                    c = Particle(b, x, y, z, origin);
                }
                else if (t == 0f)
                {
                    c = Particle(j, x, y, z, origin);
                }
                else
                {
                    Float3 p1 = Particle(j, x, y, z, origin);
                    Float3 p2 = Particle(j + 1, x, y, z, origin);
                    Float3 p0 = j - 1 >= a ? Particle(j - 1, x, y, z, origin) : p1 * 2f - p2;
                    Float3 p3 = j + 2 <= b ? Particle(j + 2, x, y, z, origin) : p2 * 2f - p1;
                    c = p0 * w0[k] + p1 * w1[k] + p2 * w2[k] + p3 * w3[k];
                }
                if (!c.IsFinite) c = k > first ? centers[k - 1] : Float3.Zero;
                if (k > first)
                {
                    Float3 previous = centers[k - 1];
                    float minimum = 1e-3f * ringRadii[k] + 1e-7f;
                    if ((c - previous).LengthSquared < minimum * minimum)
                    {
                        Float3 direction = k > first + 1 ? (previous - centers[k - 2]).NormalizedOr(fallbackDirection) : fallbackDirection;
                        c = previous + direction * minimum;
                    }
                }
                centers[k] = c;
            }
        }

        private void PushCentersOutOfColliders(int first, int last)
        {
            // centres are relative to the first particle: map that offset once, then only the (small) relative part
            Float3 firstInWorld = contactFrame.ToWorld(frameOrigin);
            float metresPerUnit = Math.Abs(contactFrame.Scale);
            int colliders = contactRope.ColliderCount;
            for (int k = first; k <= last; k++)
            {
                float r = ringRadii[k] * metresPerUnit;
                for (int q = 0; q < colliders; q++)
                {
                    Float3 world = contactFrame.DisplacementToWorld(centers[k]) + firstInWorld;
                    float d = contactRope.ColliderDistance(q, world);
                    if (!(d < r) || !float.IsFinite(d)) continue;
                    float h = 0.01f * r + 1e-6f;
                    var gradient = new Float3(
                        contactRope.ColliderDistance(q, world + new Float3(h, 0f, 0f)) - contactRope.ColliderDistance(q, world - new Float3(h, 0f, 0f)),
                        contactRope.ColliderDistance(q, world + new Float3(0f, h, 0f)) - contactRope.ColliderDistance(q, world - new Float3(0f, h, 0f)),
                        contactRope.ColliderDistance(q, world + new Float3(0f, 0f, h)) - contactRope.ColliderDistance(q, world - new Float3(0f, 0f, h)));
                    Float3 normal = gradient.NormalizedOr(Float3.Zero);
                    if (normal.LengthSquared == 0f) continue;
                    centers[k] = centers[k] + contactFrame.DisplacementFromWorld(normal * (r - d));
                }
            }
        }

        private void ComputeFrames(int first, int last)
        {
            Float3 previousTangent = (centers[last] - centers[first]).NormalizedOr(new Float3(1f, 0f, 0f));
            for (int k = first; k <= last; k++)
            {
                Float3 ahead = k < last ? centers[k + 1] : centers[k];
                Float3 behind = k > first ? centers[k - 1] : centers[k];
                Float3 t = (ahead - behind).NormalizedOr(Float3.Zero);
                if (t.LengthSquared == 0f && k < last) t = (centers[k + 1] - centers[k]).NormalizedOr(Float3.Zero);
                if (t.LengthSquared == 0f && k > first) t = (centers[k] - centers[k - 1]).NormalizedOr(Float3.Zero);
                if (t.LengthSquared == 0f) t = previousTangent;
                tangents[k] = t;
                if (k == first)
                {
                    normals[k] = FrameTransport.Perpendicular(normals[k], t);
                }
                else
                {
                    normals[k] = FrameTransport.Transport(normals[k - 1], tangents[k - 1], t);
                }
                previousTangent = t;
            }
        }

        private void ComputeSlopes(int first, int last)
        {
            for (int k = first; k <= last; k++)
            {
                int ahead = k < last ? k + 1 : k;
                int behind = k > first ? k - 1 : k;
                float distance = (centers[ahead] - centers[behind]).Length;
                float slope = distance > 1e-12f ? (ringRadii[ahead] - ringRadii[behind]) / distance : 0f;
                if (!(slope >= -MaxSlope)) slope = -MaxSlope;
                if (slope > MaxSlope) slope = MaxSlope;
                slopes[k] = slope;
            }
        }

        private void WriteRing(int k, TubeVertex[] vertices, int ringBase, ref Bounds bounds)
        {
            Float3 c = centers[k], t = tangents[k], nrm = normals[k];
            Float3 bin = Float3.Cross(t, nrm);
            float r = ringRadii[k];
            float slope = slopes[k];
            float inverse = 1f / MathF.Sqrt(1f + slope * slope);
            float v = ringV[k];
            for (int i = 0; i <= radial; i++)
            {
                Float3 radialDirection = nrm * cos[i] + bin * sin[i];
                Float3 around = bin * cos[i] - nrm * sin[i];
                Float3 p = c + radialDirection * r;
                Float3 normal = (radialDirection - t * slope) * inverse;
                ref TubeVertex vertex = ref vertices[ringBase + i];
                vertex.PX = p.X + frameOrigin.X; vertex.PY = p.Y + frameOrigin.Y; vertex.PZ = p.Z + frameOrigin.Z;
                vertex.NX = normal.X; vertex.NY = normal.Y; vertex.NZ = normal.Z;
                vertex.TX = around.X; vertex.TY = around.Y; vertex.TZ = around.Z; vertex.TW = 1f;
                vertex.U = (float)i / radial;
                vertex.V = v;
            }
            // The ring lies on the circle of radius r around c in the plane normal to t: per axis c ± r·sqrt(1 − t²).
            float ex = r * MathF.Sqrt(MathF.Max(0f, 1f - t.X * t.X)) * 1.000001f;
            float ey = r * MathF.Sqrt(MathF.Max(0f, 1f - t.Y * t.Y)) * 1.000001f;
            float ez = r * MathF.Sqrt(MathF.Max(0f, 1f - t.Z * t.Z)) * 1.000001f;
            bounds.Add(new Float3(c.X - ex, c.Y - ey, c.Z - ez));
            bounds.Add(new Float3(c.X + ex, c.Y + ey, c.Z + ez));
        }

        private void WriteCap(int k, bool atEnd, TubeVertex[] vertices, int[] indices, bool writeIndices,
            ref int vertexBase, ref int tubeCursor, ref Bounds bounds)
        {
            Float3 c = centers[k], t = tangents[k], nrm = normals[k];
            Float3 bin = Float3.Cross(t, nrm);
            Float3 outward = atEnd ? t : -t;
            float r = ringRadii[k];
            SetVertex(vertices, vertexBase, c, outward, nrm, 0.5f, 0.5f);
            bounds.Add(c);
            for (int i = 0; i < radial; i++)
            {
                Float3 p = c + (nrm * cos[i] + bin * sin[i]) * r;
                SetVertex(vertices, vertexBase + 1 + i, p, outward, nrm, 0.5f + 0.5f * cos[i], 0.5f + 0.5f * sin[i]);
                bounds.Add(p);
            }
            if (writeIndices)
            {
                for (int i = 0; i < radial; i++)
                {
                    int r0 = vertexBase + 1 + i;
                    int r1 = vertexBase + 1 + (i + 1) % radial;
                    indices[tubeCursor++] = vertexBase;
                    indices[tubeCursor++] = atEnd ? r0 : r1;
                    indices[tubeCursor++] = atEnd ? r1 : r0;
                }
            }
            else
            {
                tubeCursor += radial * 3;
            }
            vertexBase += radial + 1;
        }

        private void WriteStrands(int k, bool atEnd, int endKey, TubeVertex[] vertices, int[] indices, bool writeIndices,
            ref int vertexBase, ref int burrCursor, ref Bounds bounds)
        {
            BurrSettings burr = settings.Burr;
            Float3 c = centers[k], t = tangents[k], nrm = normals[k];
            Float3 bin = Float3.Cross(t, nrm);
            Float3 outward = atEnd ? t : -t;
            float r = ringRadii[k];
            // Triangular bases of circumradius ≈ sqrt(π/N)·r: together 1.3× the cut's area, so the fibres hide the cap.
            float baseRadius = r * MathF.Sqrt(MathF.PI / fibreCount);
            float reach = MathF.Max(0f, r - 0.5f * baseRadius);
            (int Step, int Offset) shuffle = BurrStrand.ShuffleOf(burr.Seed, endKey, fibreCount);
            for (int f = 0; f < fibreCount; f++)
            {
                BurrStrand fibre = BurrStrand.Draw(burr, endKey, f, fibreCount, shuffle);
                float ca = MathF.Cos(fibre.Angle), sa = MathF.Sin(fibre.Angle);
                Float3 radialDirection = nrm * ca + bin * sa;
                Float3 around = bin * ca - nrm * sa;
                Float3 centre = c + radialDirection * (fibre.Radial * reach);
                Float3 b0 = centre + Corner(nrm, bin, fibre.BaseTurn) * baseRadius;
                Float3 b1 = centre + Corner(nrm, bin, fibre.BaseTurn + 2.0943951f) * baseRadius;
                Float3 b2 = centre + Corner(nrm, bin, fibre.BaseTurn + 4.1887902f) * baseRadius;
                if (!atEnd) { Float3 swap = b0; b0 = b1; b1 = swap; }
                Float3 side = radialDirection * MathF.Cos(fibre.Twist) + around * MathF.Sin(fibre.Twist);
                Float3 direction = outward * MathF.Cos(fibre.Tilt) + side * MathF.Sin(fibre.Tilt);
                Float3 tip = centre + direction * (fibre.Length * 2f * r);
                int v = vertexBase + f * 9;
                WriteStrandFace(vertices, v, b0, b1, tip, outward, ref bounds);
                WriteStrandFace(vertices, v + 3, b1, b2, tip, outward, ref bounds);
                WriteStrandFace(vertices, v + 6, b2, b0, tip, outward, ref bounds);
                if (writeIndices)
                {
                    for (int q = 0; q < 9; q++) indices[burrCursor++] = v + q;
                }
                else
                {
                    burrCursor += 9;
                }
            }
            vertexBase += fibreCount * 9;
        }

        private static Float3 Corner(Float3 nrm, Float3 bin, float angle) => nrm * MathF.Cos(angle) + bin * MathF.Sin(angle);

        private void WriteStrandFace(TubeVertex[] vertices, int v, Float3 p0, Float3 p1, Float3 tip, Float3 fallback, ref Bounds bounds)
        {
            Float3 edge = p1 - p0;
            Float3 normal = Float3.Cross(edge, tip - p0).NormalizedOr(fallback);
            Float3 tangent = edge.NormalizedOr(FrameTransport.Perpendicular(fallback, normal));
            SetVertex(vertices, v, p0, normal, tangent, 0f, 1f);
            SetVertex(vertices, v + 1, p1, normal, tangent, 1f, 1f);
            SetVertex(vertices, v + 2, tip, normal, tangent, 0.5f, 0f);
            bounds.Add(p0);
            bounds.Add(tip);
        }

        private void SetVertex(TubeVertex[] vertices, int index, Float3 p, Float3 normal, Float3 tangent, float u, float v)
        {
            ref TubeVertex vertex = ref vertices[index];
            vertex.PX = p.X + frameOrigin.X; vertex.PY = p.Y + frameOrigin.Y; vertex.PZ = p.Z + frameOrigin.Z;
            vertex.NX = normal.X; vertex.NY = normal.Y; vertex.NZ = normal.Z;
            vertex.TX = tangent.X; vertex.TY = tangent.Y; vertex.TZ = tangent.Z; vertex.TW = 1f;
            vertex.U = u; vertex.V = v;
        }

        private static Float3 Particle(int i, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, Float3 origin) =>
            new Float3(x[i] - origin.X, y[i] - origin.Y, z[i] - origin.Z);

        private struct Bounds
        {
            public Float3 Min;
            public Float3 Max;

            public Bounds(bool empty)
            {
                float big = empty ? float.MaxValue : 0f;
                Min = new Float3(big, big, big);
                Max = new Float3(-big, -big, -big);
            }

            public void Add(Float3 p)
            {
                Min = new Float3(MathF.Min(Min.X, p.X), MathF.Min(Min.Y, p.Y), MathF.Min(Min.Z, p.Z));
                Max = new Float3(MathF.Max(Max.X, p.X), MathF.Max(Max.Y, p.Y), MathF.Max(Max.Z, p.Z));
            }
        }
    }
}
