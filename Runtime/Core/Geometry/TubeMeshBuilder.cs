using System;
using System.Numerics;
using HookeRope.Fracture;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Builds the procedural tube mesh of a rope into caller-owned buffers: rings along a Catmull–Rom curve through
    /// the particles, oriented by parallel transport, normals tilted for a varying radius, v along the rest arc
    /// length, flat caps at intact ends, and at each broken end a cap plus seeded burr strands. Vertex positions are
    /// relative to the first particle. The rings sit where a <see cref="RingLayout"/> says: a fixed one, or one the
    /// adaptive rings (<see cref="AdaptiveRings"/>) rewrite by need before each build (<see cref="PlanRings"/>).
    /// <para>
    /// Incremental: a build recomputes only what its inputs changed (compared bitwise with the last build's): nothing
    /// when positions, radii, rest lengths, layout, settings, broken flags and buffers are all the same (the last
    /// result is returned and no vertex is written); only the radius work (ring radii, slopes, the rings, caps and
    /// strands whose radius or slope changed) when just the radii changed; the whole tube otherwise (and always while
    /// colliders push the rings). The result is bit-identical to a full recompute (tested), provided the caller does
    /// not write into the vertex buffer between builds (another buffer forces a full build). The index buffer is
    /// rewritten only when the topology changes (first build, a newly broken segment, a piece's ring count, another
    /// index array). Allocation-free after construction: an adaptive builder's ring storage is made at construction for
    /// the most rings its ring budget allows (<see cref="AdaptiveRings.MostRings"/>), and buffers of
    /// <see cref="GetVertexCapacity"/> and <see cref="GetIndexCapacity"/> take every budget until a segment breaks.
    /// </para>
    /// </summary>
    internal sealed partial class TubeMeshBuilder
    {
        private const float MaxSlope = 10f;

        /// <summary>
        /// Least distance between consecutive ring centres, as a fraction of the ring radius: a ring closer to the one before
        /// (coincident particles, a segment squeezed to a point) is pushed forward by it, so no triangle has zero area. Equal to
        /// <see cref="FoldRadius"/>, so that a fold tip next to such rings still keeps its triangles ≥ 1e-6 r² at 64 sides.
        /// </summary>
        internal const float PushDistance = FoldRadius;

        /// <summary>What a build recomputed.</summary>
        internal enum BuildKind
        {
            /// <summary>Everything (centres, frames, radii, rings, caps, strands, bounds).</summary>
            Full,
            /// <summary>Only the radius work: positions were unchanged.</summary>
            RadiiOnly,
            /// <summary>Nothing: every input was unchanged, the last result was returned.</summary>
            Skipped,
        }

        private readonly TubeMeshSettings settings;
        private readonly RingLayout layout;
        private readonly AdaptiveRings adaptive;
        private readonly int radial;
        private readonly bool capEnds;
        private readonly bool burrEnabled;
        private readonly int fibreCount;
        private readonly float[] cos;
        private readonly float[] sin;
        private readonly SideLanes[] sideLanes;
        private readonly TubeVertex[] capRim;
        private readonly double[] restArc;
        private readonly float[] particleRadii;
        private float[] segmentRingRadii = Array.Empty<float>();
        private readonly bool[] lastBroken;
        private readonly int[] pieceRings;
        private readonly int spareFirst;
        private readonly int[] stations;
        private DanglingEnds dangling;
        private readonly float[] lastDangling;
        private readonly float[] lastX, lastY, lastZ, lastRest;
        private float[] lastRadii = Array.Empty<float>();
        private int[] lastIndices;
        // the vertex buffer of the last full build: a TubeVertex[] or a LeanTubeVertex[] (another buffer, of either kind, is a full build)
        private object lastVertices;
        // the caller's vertex buffer of the build under way: one of the two, the other null
        private TubeVertex[] fullOut;
        private LeanTubeVertex[] leanOut;
        private int lastLayoutVersion = -1;
        private int ringVLayoutVersion = -1;
        private float lastVScale = float.NaN;
        private BurrKey lastBurr;
        private bool haveLast;
        private TubeMeshUpdate lastUpdate;
        private Bounds strandBounds;
        private Float3 frameOrigin;
        private HookeRope.Solver.Rope contactRope;
        private MeshFrame contactFrame;
        private bool topologyValid;
        private bool lastContacts;

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
            : this(settings, layout, null, restRadius)
        {
        }

        private TubeMeshBuilder(TubeMeshSettings settings, RingLayout layout, AdaptiveRings adaptive, float restRadius)
        {
            this.settings = settings ?? throw new ArgumentNullException(nameof(settings));
            this.layout = layout ?? throw new ArgumentNullException(nameof(layout));
            this.adaptive = adaptive;
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
            // the u coordinate i/radial around the ring is only read through the side table
            sideLanes = new SideLanes[radial + 1];
            for (int i = 0; i <= radial; i++)
                sideLanes[i] = new SideLanes(new Vector4(cos[i]), new Vector4(sin[i]), new Vector4(0f, 1f, (float)i / radial, 0f));
            // the wide kernel's pair table, where Vector<float> has its 8 lanes (made here: a mesh update never allocates)
            if (Vector<float>.Count == 8) pairLanes = MakePairLanes();
            MakeLeanTables();
            capRim = new TubeVertex[radial + 1];
            int n = layout.SegmentCount;
            restArc = new double[n + 1];
            particleRadii = new float[n + 1];
            lastBroken = new bool[n];
            pieceRings = new int[n];
            lastX = new float[n + 1];
            lastY = new float[n + 1];
            lastZ = new float[n + 1];
            lastRest = new float[n];
            AllocateParticleFrames(n);
            // the rings of a broken end's dangling half go to spare slots after the layout's (one half at a time)
            int spare = adaptive != null ? adaptive.MostRingsInOneSegment + 1 : DanglingEnds.MaxRingCount(layout);
            spareFirst = adaptive != null ? adaptive.MostRings : layout.RingCount;
            stations = new int[spare];
            lastDangling = new float[3 * n];
            EnsureRingStorage(spareFirst + spare);
        }

        /// <summary>
        /// An adaptive builder: rings placed by need (<see cref="AdaptiveRings"/>, tolerance from the side count and
        /// <see cref="TubeMeshSettings.RingTolerance"/>, set at every prime and plan) for a
        /// rope of <paramref name="segmentCount"/> segments and rest radius <paramref name="restRadius"/> (m; 0 = unknown,
        /// sets the burr fibres); <paramref name="neckStations"/> (null = none) holds a Zone neck's stations
        /// (<see cref="RingLayout.Adapted"/> with one ring per segment), drawn while the neck is active. Call
        /// <see cref="PlanRings"/> before each build. <paramref name="meanRingsPerSegment"/> is the ring budget's cap
        /// (<see cref="AdaptiveRings.MaxMeanRingsPerSegment"/>; the tests pass <see cref="AdaptiveRings.MaxRingsPerSegment"/>
        /// for the placement without a budget).
        /// </summary>
        internal static TubeMeshBuilder Adaptive(TubeMeshSettings settings, int segmentCount, float restRadius, RingLayout neckStations,
            int meanRingsPerSegment = AdaptiveRings.MaxMeanRingsPerSegment)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            var rings = new AdaptiveRings(segmentCount, settings.RadialSegments, neckStations, meanRingsPerSegment);
            return new TubeMeshBuilder(settings, RingLayout.Rewritable(segmentCount, rings.MostRings), rings, restRadius);
        }

        /// <summary>The ring layout of the next build (for an adaptive builder, the one <see cref="PlanRings"/> last wrote).</summary>
        internal RingLayout Layout => layout;

        /// <summary>Most rings <see cref="Layout"/> can hold without growing (an adaptive builder's storage is made for it).</summary>
        internal int MostRings => adaptive?.MostRings ?? layout.RingCount;

        /// <summary>True when the rings are placed by need before each build.</summary>
        internal bool IsAdaptive => adaptive != null;

        /// <summary>Adaptive builders: incremented whenever the counts the builder reports change (a topology change ahead); 0 otherwise.</summary>
        internal int BudgetVersion => adaptive?.BudgetVersion ?? 0;

        /// <summary>Adaptive builders: true when the ring budget's cap limited a piece's budget in the last <see cref="PlanRings"/> (<see cref="AdaptiveRings.BudgetHit"/>); false otherwise.</summary>
        internal bool BudgetHit => adaptive?.BudgetHit ?? false;

        /// <summary>Adaptive builders: the tolerance of the drawn surface as a fraction of the drawn radius; 0 otherwise.</summary>
        internal float ToleranceFraction => adaptive?.ToleranceFraction ?? 0f;

        /// <summary>What the last build recomputed.</summary>
        internal BuildKind LastBuild { get; private set; }

        /// <summary>Tests only: every build recomputes everything (the reference the incremental builds are compared with).</summary>
        internal bool AlwaysRebuild { get; set; }

        /// <summary>Number of rope segments.</summary>
        public int SegmentCount => layout.SegmentCount;

        /// <summary>Vertices around the tube (fixed at construction).</summary>
        public int RadialSegments => radial;

        /// <summary>
        /// Forgets the last build, so the next one writes every vertex and index: for a builder taken up again after another
        /// builder wrote into the caller's buffers (a side count switched back, <see cref="RopeMesh"/>).
        /// </summary>
        internal void ForgetLastBuild()
        {
            haveLast = false;
            topologyValid = false;
        }

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

        /// <summary>
        /// Vertices the mesh needs for these broken-segment flags (empty = intact rope). For an adaptive builder: what its
        /// next build will use when the buffers hold it (the budgets may have grown or shrunk with the last build).
        /// </summary>
        public int GetVertexCount(ReadOnlySpan<bool> brokenSegments)
        {
            Count(brokenSegments, Counted.Reported, out int vertices, out _, out _);
            return vertices;
        }

        /// <summary>Indices the mesh needs for these broken-segment flags (tube, caps and burr strands).</summary>
        public int GetIndexCount(ReadOnlySpan<bool> brokenSegments)
        {
            Count(brokenSegments, Counted.Reported, out _, out int tube, out int burr);
            return tube + burr;
        }

        /// <summary>
        /// Most vertices any build can need for these broken-segment flags: every piece at its ring cap
        /// (<see cref="AdaptiveRings.CapOfPiece"/>) for an adaptive builder, the layout's count for a fixed one. Buffers of
        /// this size (and <see cref="GetIndexCapacity"/>) take every budget the adaptive rings choose until a segment breaks.
        /// </summary>
        public int GetVertexCapacity(ReadOnlySpan<bool> brokenSegments)
        {
            Count(brokenSegments, adaptive != null ? Counted.Capacity : Counted.Layout, out int vertices, out _, out _);
            return vertices;
        }

        /// <summary>Most indices any build can need for these broken-segment flags (see <see cref="GetVertexCapacity"/>).</summary>
        public int GetIndexCapacity(ReadOnlySpan<bool> brokenSegments)
        {
            Count(brokenSegments, adaptive != null ? Counted.Capacity : Counted.Layout, out _, out int tube, out int burr);
            return tube + burr;
        }

        /// <summary>
        /// Adaptive builders: sets the ring budgets to what these positions need (no hysteresis) and places the rings, so the
        /// first build needs no catching up. <paramref name="radius"/> is the drawn radius (m, in the positions' frame)
        /// the tolerance refers to; <paramref name="neckActive"/> draws the neck's stations.
        /// </summary>
        internal void PrimeRings(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, ReadOnlySpan<bool> brokenSegments,
            bool neckActive, float radius)
        {
            if (adaptive == null) return;
            CheckPositions(x, y, z, brokenSegments);
            adaptive.ToleranceScale = settings.RingTolerance;
            adaptive.Prime(x, y, z, brokenSegments, neckActive, radius);
            adaptive.Plan(x, y, z, brokenSegments, neckActive, radius, true, layout);
            EnsureRingStorage(layout.RingCount);
        }

        /// <summary>
        /// Adaptive builders: places this build's rings by need for positions <paramref name="x"/>, <paramref name="y"/>,
        /// <paramref name="z"/> (m) and drawn radius <paramref name="radius"/> (m, in the positions' frame), taking the
        /// budgets the counts reported when buffers of <paramref name="vertexCapacity"/> vertices and
        /// <paramref name="indexCapacity"/> indices hold them (else the last build's). Call before filling the ring radii
        /// for <see cref="Layout"/> and building; returns true when the layout changed. Fixed layouts: returns false.
        /// </summary>
        internal bool PlanRings(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, ReadOnlySpan<bool> brokenSegments,
            bool neckActive, float radius, int vertexCapacity, int indexCapacity)
        {
            if (adaptive == null) return false;
            CheckPositions(x, y, z, brokenSegments);
            // read at every plan (TubeMeshSettings.RingTolerance: a new value needs no new builder)
            adaptive.ToleranceScale = settings.RingTolerance;
            bool takeNext = true;
            if (adaptive.BudgetPending(brokenSegments))
            {
                Count(brokenSegments, Counted.Reported, out int vertices, out int tube, out int burr);
                takeNext = vertices <= vertexCapacity && tube + burr <= indexCapacity;
            }
            bool changed = adaptive.Plan(x, y, z, brokenSegments, neckActive, radius, takeNext, layout);
            EnsureRingStorage(layout.RingCount);
            return changed;
        }

        /// <summary>
        /// Builds the mesh from particle positions (m; SegmentCount + 1 each), rest segment lengths (m), per-segment
        /// radii (m; smoothed to the particles and interpolated to the rings) and broken flags (empty = none).
        /// </summary>
        public TubeMeshUpdate Build(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            ReadOnlySpan<float> restLengths, ReadOnlySpan<float> segmentRadii, ReadOnlySpan<bool> brokenSegments,
            TubeVertex[] vertices, int[] indices) =>
            BuildWithRingRadii(x, y, z, restLengths, RingRadiiOfSegments(segmentRadii, brokenSegments), brokenSegments, vertices, indices);

        /// <summary>Per-segment radii (m) smoothed to the particles and interpolated to the rings of <see cref="Layout"/>.</summary>
        private ReadOnlySpan<float> RingRadiiOfSegments(ReadOnlySpan<float> segmentRadii, ReadOnlySpan<bool> brokenSegments)
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
            int rings = layout.RingCount;
            if (segmentRingRadii.Length < rings) segmentRingRadii = new float[rings];
            ReadOnlySpan<int> segments = layout.RingSegments;
            ReadOnlySpan<float> fractions = layout.RingFractions;
            for (int k = 0; k < rings; k++)
            {
                int j = segments[k];
                segmentRingRadii[k] = particleRadii[j] + (particleRadii[j + 1] - particleRadii[j]) * fractions[k];
            }
            return new ReadOnlySpan<float>(segmentRingRadii, 0, rings);
        }

        /// <summary>
        /// Builds the mesh from particle positions (m), rest segment lengths (m), one radius per ring (m;
        /// <see cref="RingLayout.RingCount"/> values, e.g. from RadiusModel.FillRadiiAt) and broken flags (empty =
        /// none). Non-finite or non-positive radii count as 1e-6 m; non-finite positions repeat the previous ring.
        /// Throws ArgumentException when a span has the wrong length or a buffer is too small.
        /// </summary>
        public TubeMeshUpdate BuildWithRingRadii(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            ReadOnlySpan<float> restLengths, ReadOnlySpan<float> radii, ReadOnlySpan<bool> brokenSegments,
            TubeVertex[] vertices, int[] indices) =>
            BuildWithRingRadii(x, y, z, restLengths, radii, brokenSegments, vertices, null, indices);

        /// <summary>
        /// <see cref="BuildWithRingRadii(ReadOnlySpan{float}, ReadOnlySpan{float}, ReadOnlySpan{float}, ReadOnlySpan{float}, ReadOnlySpan{float}, ReadOnlySpan{bool}, TubeVertex[], int[])"/>
        /// into <paramref name="fullVertices"/> or, when it is null, into <paramref name="leanVertices"/>: vertices without
        /// tangents (<see cref="LeanTubeVertex"/>, each field the bits of the same field of a <see cref="TubeVertex"/>
        /// build). A build into another buffer than the last one, of either kind, is a full build.
        /// </summary>
        internal TubeMeshUpdate BuildWithRingRadii(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            ReadOnlySpan<float> restLengths, ReadOnlySpan<float> radii, ReadOnlySpan<bool> brokenSegments,
            TubeVertex[] fullVertices, LeanTubeVertex[] leanVertices, int[] indices)
        {
            if (fullVertices != null) leanVertices = null;
            object vertices = (object)fullVertices ?? leanVertices;
            int n = layout.SegmentCount;
            CheckPositions(x, y, z, brokenSegments);
            if (restLengths.Length != n)
                throw new ArgumentException("restLengths must hold SegmentCount = " + n + " values.", nameof(restLengths));
            int rings = layout.RingCount;
            if (radii.Length != rings)
                throw new ArgumentException("radii must hold RingCount = " + rings + " values.", nameof(radii));
            if (vertices == null) throw new ArgumentNullException(nameof(vertices));
            if (indices == null) throw new ArgumentNullException(nameof(indices));
            Count(brokenSegments, Counted.Layout, out int vertexCount, out int tubeIndexCount, out int burrIndexCount);
            int vertexLength = fullVertices?.Length ?? leanVertices.Length;
            if (vertexLength < vertexCount)
                throw new ArgumentException("vertices must hold at least GetVertexCount = " + vertexCount + " vertices.", nameof(vertices));
            if (indices.Length < tubeIndexCount + burrIndexCount)
                throw new ArgumentException("indices must hold at least GetIndexCount = " + (tubeIndexCount + burrIndexCount) + " indices.", nameof(indices));
            EnsureRingStorage(rings);

            bool topologyChanged = TopologyMoved(brokenSegments, indices);
            bool layoutMoved = layout.Version != lastLayoutVersion;
            bool restMoved = !Same(restLengths, lastRest);
            float vScale = settings.VPerMetre;
            var burr = new BurrKey(settings.Burr);
            bool contacts = contactRope != null && contactRope.ColliderCount > 0;
            bool dangles = dangling != null && HasBroken(brokenSegments);
            bool danglingMoved = dangles && DanglingMoved(brokenSegments);
            bool full = AlwaysRebuild || !haveLast || topologyChanged || layoutMoved || restMoved || contacts || lastContacts || danglingMoved
                        || !vScale.Equals(lastVScale) || !burr.Equals(lastBurr) || !ReferenceEquals(vertices, lastVertices);
            bool positionsMoved = full || !Same(x, lastX) || !Same(y, lastY) || !Same(z, lastZ);
            bool radiiMoved = full || !Same(radii, new ReadOnlySpan<float>(lastRadii, 0, rings));
            if (!positionsMoved && !radiiMoved)
            {
                LastBuild = BuildKind.Skipped;
                return Unchanged(lastUpdate);
            }
            // the dangling halves share the spare ring slots within a build: with them a change always rebuilds all
            bool radiiOnly = !positionsMoved && !dangles && CentresKeep(radii, brokenSegments);
            LastBuild = radiiOnly ? BuildKind.RadiiOnly : BuildKind.Full;

            radii.CopyTo(lastRadii);
            lastContacts = contacts;
            if (!radiiOnly)
            {
                x.CopyTo(lastX); y.CopyTo(lastY); z.CopyTo(lastZ);
                restLengths.CopyTo(lastRest);
                if (layoutMoved || restMoved || !vScale.Equals(lastVScale) || ringVLayoutVersion != layout.Version) ComputeRingV(restLengths, vScale);
                lastLayoutVersion = layout.Version;
                lastVScale = vScale;
                lastBurr = burr;
                lastVertices = vertices;
                // Geometry is computed relative to the first particle (precision far from the origin); the vertices get
                // the origin back as they are written, so vertices and bounds are in the frame of the input positions.
                Float3 origin = new Float3(x[0], y[0], z[0]);
                if (!origin.IsFinite) origin = Float3.Zero;
                frameOrigin = origin;
            }

            var bounds = new Bounds(true);
            if (radiiOnly) UpdateAllRadii(radii, brokenSegments);
            bool rewriteStrands = !radiiOnly || StrandEndsMoved(brokenSegments);
            if (rewriteStrands) strandBounds = new Bounds(true);
            int vertexBase = 0;
            int tubeCursor = 0;
            int burrCursor = tubeIndexCount;
            int segment = 0;
            fullOut = fullVertices;
            leanOut = leanVertices;
            while (NextPiece(brokenSegments, n, ref segment, out int a, out int b))
            {
                BuildPiece(a, b, x, y, z, radii, indices, topologyChanged, radiiOnly, rewriteStrands,
                    ref vertexBase, ref tubeCursor, ref burrCursor, ref bounds);
            }
            fullOut = null;
            leanOut = null;
            bounds.Add(strandBounds);

            if (topologyChanged) { lastIndices = indices; topologyValid = true; }
            haveLast = true;
            if (vertexCount == 0) bounds = new Bounds(false);
            else { bounds.Min = bounds.Min + frameOrigin; bounds.Max = bounds.Max + frameOrigin; }
            lastUpdate = new TubeMeshUpdate(vertexCount, tubeIndexCount + burrIndexCount, tubeIndexCount, topologyChanged,
                bounds.Min, bounds.Max);
            return lastUpdate;
        }

        private static bool HasBroken(ReadOnlySpan<bool> brokenSegments)
        {
            for (int j = 0; j < brokenSegments.Length; j++) if (brokenSegments[j]) return true;
            return false;
        }

        /// <summary>True when a broken segment's half length or cut radii changed since the last build (and records them).</summary>
        private bool DanglingMoved(ReadOnlySpan<bool> brokenSegments)
        {
            bool moved = false;
            for (int j = 0; j < brokenSegments.Length; j++)
            {
                if (!brokenSegments[j]) continue;
                moved |= Record(3 * j, dangling.HalfLength(j)) | Record(3 * j + 1, dangling.CutRadius(j, false)) | Record(3 * j + 2, dangling.CutRadius(j, true));
            }
            return moved;
        }

        private bool Record(int slot, float value)
        {
            bool moved = BitConverter.SingleToInt32Bits(lastDangling[slot]) != BitConverter.SingleToInt32Bits(value);
            lastDangling[slot] = value;
            return moved;
        }

        private static TubeMeshUpdate Unchanged(TubeMeshUpdate last) =>
            new TubeMeshUpdate(last.VertexCount, last.IndexCount, last.TubeIndexCount, false, last.BoundsMin, last.BoundsMax);

        private void CheckPositions(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z, ReadOnlySpan<bool> brokenSegments)
        {
            int n = layout.SegmentCount;
            if (x.Length != n + 1 || y.Length != n + 1 || z.Length != n + 1)
                throw new ArgumentException("x, y and z must each hold SegmentCount + 1 = " + (n + 1) + " positions.", nameof(x));
            if (brokenSegments.Length > 0 && brokenSegments.Length != n)
                throw new ArgumentException("brokenSegments must be empty or hold SegmentCount = " + n + " flags.", nameof(brokenSegments));
        }

        /// <summary>True when the index buffer must be rewritten; records the broken flags and the piece ring counts.</summary>
        private bool TopologyMoved(ReadOnlySpan<bool> brokenSegments, int[] indices)
        {
            int n = layout.SegmentCount;
            bool hasBroken = brokenSegments.Length > 0;
            bool changed = !topologyValid || !ReferenceEquals(indices, lastIndices);
            for (int j = 0; j < n; j++)
            {
                bool b = hasBroken && brokenSegments[j];
                if (b != lastBroken[j]) { changed = true; lastBroken[j] = b; }
            }
            int segment = 0;
            while (NextPiece(brokenSegments, n, ref segment, out int a, out int end))
            {
                int rings = layout.FirstRing(end) - layout.FirstRing(a) + 1;
                if (pieceRings[a] != rings) { changed = true; pieceRings[a] = rings; }
            }
            return changed;
        }

        /// <summary>
        /// True when new <paramref name="radii"/> leave the ring centres as they are: the last full build pushed no ring
        /// forward for being closer than <see cref="PushDistance"/>·r to the one before, and none would be with these radii.
        /// </summary>
        private bool CentresKeep(ReadOnlySpan<float> radii, ReadOnlySpan<bool> brokenSegments)
        {
            int n = layout.SegmentCount;
            int segment = 0;
            while (NextPiece(brokenSegments, n, ref segment, out int a, out int b))
            {
                int first = layout.FirstRing(a), last = layout.FirstRing(b);
                for (int k = first + 1; k <= last; k++)
                {
                    float minimum = PushDistance * Clamped(radii[k]) + 1e-7f;
                    if (!(spacing2[k] >= minimum * minimum)) return false;
                }
            }
            return true;
        }

        /// <summary>The radius work of a radius-only build, piece by piece (before anything is written, so the strands know whether their ends moved).</summary>
        private void UpdateAllRadii(ReadOnlySpan<float> radii, ReadOnlySpan<bool> brokenSegments)
        {
            int n = layout.SegmentCount;
            int segment = 0;
            while (NextPiece(brokenSegments, n, ref segment, out int a, out int b))
                UpdateRadii(layout.FirstRing(a), layout.FirstRing(b), radii);
        }

        /// <summary>After <see cref="UpdateAllRadii"/>: true when a broken end's ring was rewritten (its cap and strands move).</summary>
        private bool StrandEndsMoved(ReadOnlySpan<bool> brokenSegments)
        {
            if (!burrEnabled || brokenSegments.Length == 0) return false;
            int n = layout.SegmentCount;
            int segment = 0;
            while (NextPiece(brokenSegments, n, ref segment, out int a, out int b))
            {
                if (a > 0 && dirty[layout.FirstRing(a)]) return true;
                if (b < n && dirty[layout.FirstRing(b)]) return true;
            }
            return false;
        }

        private static float Clamped(float r) => float.IsFinite(r) && r > 1e-6f ? r : 1e-6f;

        /// <summary>
        /// <see cref="Clamped"/> per lane: r where <paramref name="floor"/> (1e-6) &lt; r &lt; <paramref name="infinity"/> (+∞),
        /// both false for NaN, so exactly where r is finite and above 1e-6; else 1e-6. The caller broadcasts the two constants
        /// once, outside its loop.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static Vector<float> ClampedLanes(Vector<float> r, Vector<float> floor, Vector<float> infinity) =>
            Vector.ConditionalSelect(Vector.GreaterThan(r, floor) & Vector.LessThan(r, infinity), r, floor);

        /// <summary>
        /// <see cref="Clamped"/> of each of <paramref name="given"/> into <paramref name="clamped"/> (of the same length):
        /// with the vector paths on, whole <see cref="Vector{T}"/> blocks first (<see cref="ClampedLanes"/>), the tail by the scalar.
        /// </summary>
        private static void ClampRadii(ReadOnlySpan<float> given, Span<float> clamped)
        {
            given = given.Slice(0, clamped.Length);
            int done = 0;
            if (VectorPath.Enabled)
            {
                ReadOnlySpan<Vector<float>> r = VectorPath.AsLanes(given);
                Span<Vector<float>> c = VectorPath.AsLanes(clamped).Slice(0, r.Length);
                var floor = new Vector<float>(1e-6f);
                var infinity = new Vector<float>(float.PositiveInfinity);
                for (int p = 0; p < c.Length; p++) c[p] = ClampedLanes(r[p], floor, infinity);
                done = c.Length * Vector<float>.Count;
            }
            for (int i = done; i < clamped.Length; i++) clamped[i] = Clamped(given[i]);
        }

        private void ComputeRingV(ReadOnlySpan<float> restLengths, float vScale)
        {
            int n = layout.SegmentCount;
            double arc = 0.0;
            restArc[0] = 0.0;
            for (int j = 0; j < n; j++) { arc += restLengths[j]; restArc[j + 1] = arc; }
            ReadOnlySpan<int> ringSegments = layout.RingSegments;
            ReadOnlySpan<float> ringFractions = layout.RingFractions;
            ReadOnlySpan<double> arcs = restArc;
            Span<float> v = new Span<float>(ringV, 0, ringSegments.Length);
            ringFractions = ringFractions.Slice(0, v.Length);
            // the rings of a segment are consecutive: its arc and rest length once per run (the same operations per ring)
            int segment = -1;
            double start = 0.0, length = 0.0;
            for (int k = 0; k < v.Length; k++)
            {
                int j = ringSegments[k];
                if (j != segment)
                {
                    segment = j;
                    start = arcs[j];
                    length = arcs[j + 1] - start;
                }
                double s = start + length * ringFractions[k];
                v[k] = (float)(s * vScale);
            }
            ringVLayoutVersion = layout.Version;
        }

        private static bool NextPiece(ReadOnlySpan<bool> brokenSegments, int n, ref int segment, out int a, out int b) =>
            RopePieces.Next(brokenSegments, n, ref segment, out a, out b);

        /// <summary>What <see cref="Count"/> counts.</summary>
        private enum Counted
        {
            /// <summary>The layout of the next build.</summary>
            Layout,
            /// <summary>The next adaptive budgets (the layout for a fixed builder).</summary>
            Reported,
            /// <summary>Every adaptive piece at its ring cap.</summary>
            Capacity,
        }

        /// <summary>Vertex and index counts: of the layout, of the next adaptive budgets or of the caps (<paramref name="what"/>).</summary>
        private void Count(ReadOnlySpan<bool> brokenSegments, Counted what, out int vertexCount, out int tubeIndexCount, out int burrIndexCount)
        {
            bool reported = what != Counted.Layout;
            int n = layout.SegmentCount;
            bool hasBroken = brokenSegments.Length > 0;
            if (hasBroken && brokenSegments.Length != n)
                throw new ArgumentException("brokenSegments must be empty or hold SegmentCount = " + n + " flags.", nameof(brokenSegments));
            vertexCount = 0; tubeIndexCount = 0; burrIndexCount = 0;
            int segment = 0;
            while (NextPiece(brokenSegments, n, ref segment, out int a, out int b))
            {
                int rings = !reported || adaptive == null ? layout.FirstRing(b) - layout.FirstRing(a) + 1
                    : what == Counted.Capacity ? adaptive.CapOfPiece(a, b) + 1
                    : adaptive.RingsOfPiece(a, brokenSegments);
                vertexCount += rings * (radial + 1);
                tubeIndexCount += (rings - 1) * radial * 6;
                CountEnd(a > 0, a > 0 ? DanglingRingCount(a - 1, true, reported) : 0, ref vertexCount, ref tubeIndexCount, ref burrIndexCount);
                CountEnd(b < n, b < n ? DanglingRingCount(b, false, reported) : 0, ref vertexCount, ref tubeIndexCount, ref burrIndexCount);
            }
        }

        /// <summary>
        /// Rings the dangling half of broken segment j on the given side adds (0 without dangling ends): of the layout, or,
        /// reported by an adaptive builder, of what its next layout holds there (the neck's stations or one ring).
        /// </summary>
        private int DanglingRingCount(int segment, bool upper, bool reported)
        {
            if (dangling == null) return 0;
            if (!reported || adaptive == null) return DanglingEnds.RingCount(layout, segment, upper);
            return adaptive.KeepsNeckStations(segment) ? DanglingEnds.RingCount(adaptive.NeckStations, segment, upper) : 1;
        }

        private void CountEnd(bool brokenEnd, int danglingRings, ref int vertexCount, ref int tubeIndexCount, ref int burrIndexCount)
        {
            vertexCount += danglingRings * (radial + 1);
            tubeIndexCount += danglingRings * radial * 6;
            if (brokenEnd || capEnds) { vertexCount += radial + 1; tubeIndexCount += radial * 3; }
            if (brokenEnd && burrEnabled) { vertexCount += fibreCount * 9; burrIndexCount += fibreCount * 9; }
        }

        private void BuildPiece(int a, int b, ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            ReadOnlySpan<float> radii, int[] indices, bool writeIndices, bool radiiOnly, bool rewriteStrands,
            ref int vertexBase, ref int tubeCursor, ref int burrCursor, ref Bounds bounds)
        {
            int n = layout.SegmentCount;
            int first = layout.FirstRing(a);
            int last = layout.FirstRing(b);
            // which rings must be written: all of them after new positions, the changed ones after new radii only
            // a full build of a piece no ring of which takes strip normals: every ring dirty and drawn by WriteRing
            bool plain = false;
            lanePieceFirst = -1;
            if (!radiiOnly)
            {
                int count = last - first + 1;
                Span<float> clamped = new Span<float>(ringRadii, first, count);
                ReadOnlySpan<float> given = radii.Slice(first, count);
                ClampRadii(given, clamped);
                dirty.AsSpan(first, count).Fill(true);
                ComputeCenters(a, b, first, last, x, y, z);
                if (contactRope != null && contactRope.ColliderCount > 0) PushCentersOutOfColliders(first, last);
                bool distancesKept = ComputeFrames(a, b, first, last, out bool anySkewed);
                bool anyThinned = LimitRadii(first, last, radii);
                drawnRadii.AsSpan(first, count).CopyTo(ringRadii.AsSpan(first, count));
                ComputeSlopes(first, last, distancesKept);
                // no ring thinned or skewed: no ring of the piece takes strip normals (what MarkStripNormals would find)
                if (anySkewed || anyThinned || ForceFullLimits) MarkStripNormals(first, last);
                else { stripNormals.AsSpan(first, count).Clear(); plain = true; }
            }

            bool startBroken = a > 0, endBroken = b < n;
            int stride = radial + 1;
            // a broken start: the dangling upper half of segment a − 1 (spare slots, tip last), drawn from its tip inward
            int startRings = startBroken && dangling != null ? PlaceDanglingHalf(a - 1, true, first) : 0;
            int startTip = startRings > 0 ? spareFirst + startRings - 1 : first;
            bool startDirty = startRings > 0 || dirty[first];
            if (startBroken || capEnds) WriteCap(startTip, false, indices, writeIndices, startDirty, ref vertexBase, ref tubeCursor, ref bounds);
            if (startBroken && burrEnabled) WriteStrands(startTip, false, 2 * (a - 1) + 1, indices, writeIndices, rewriteStrands, ref vertexBase, ref burrCursor);
            for (int q = startRings - 1; q >= 0; q--)
            {
                WriteRingAt(spareFirst + q, vertexBase);
                AddRingBounds(spareFirst + q, ref bounds);
                WriteStrip(vertexBase, vertexBase + stride, indices, writeIndices, ref tubeCursor);
                vertexBase += stride;
            }

            // the dangling halves' first rings, for the normals of end rings drawn from their strips
            Neighbour beforeFirst = DanglingNeighbour(startRings > 0 && stripNormals[first], a - 1, true, first);
            Neighbour afterLast = DanglingNeighbour(endBroken && dangling != null && stripNormals[last], b, false, last);
            if (plain && !writeIndices)
            {
                // the loop below with its tests decided: each ring written (in one call for the piece) and bounded, the
                // strips' indices kept
                WriteRingsAt(first, last, vertexBase);
                AddRingsBounds(first, last, ref bounds);
                tubeCursor += (last - first) * radial * 6;
            }
            else
            {
                for (int k = first; k <= last; k++)
                {
                    int ringBase = vertexBase + (k - first) * stride;
                    if (dirty[k] && stripNormals[k]) WriteRingOnStripsAt(k, first, last, beforeFirst, afterLast, ringBase);
                    else if (dirty[k]) WriteRingAt(k, ringBase);
                    AddRingBounds(k, ref bounds);
                    if (k < last) WriteStrip(ringBase, ringBase + stride, indices, writeIndices, ref tubeCursor);
                }
            }
            vertexBase += (last - first + 1) * stride;

            // a broken end: the dangling lower half of segment b, from the last ring out to its tip
            int endRings = endBroken && dangling != null ? PlaceDanglingHalf(b, false, last) : 0;
            for (int q = 0; q < endRings; q++)
            {
                WriteStrip(vertexBase - stride, vertexBase, indices, writeIndices, ref tubeCursor);
                WriteRingAt(spareFirst + q, vertexBase);
                AddRingBounds(spareFirst + q, ref bounds);
                vertexBase += stride;
            }
            int endTip = endRings > 0 ? spareFirst + endRings - 1 : last;
            bool endDirty = endRings > 0 || dirty[last];
            if (endBroken || capEnds) WriteCap(endTip, true, indices, writeIndices, endDirty, ref vertexBase, ref tubeCursor, ref bounds);
            if (endBroken && burrEnabled) WriteStrands(endTip, true, 2 * b, indices, writeIndices, rewriteStrands, ref vertexBase, ref burrCursor);
        }

        /// <summary>Two triangles per radial step between the rings whose first vertices are baseA and baseB (B further along v).</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private void WriteStrip(int baseA, int baseB, int[] indices, bool writeIndices, ref int tubeCursor)
        {
            if (writeIndices) WriteStripIndices(baseA, baseB, indices, ref tubeCursor);
            else tubeCursor += radial * 6;
        }

        private void WriteStripIndices(int baseA, int baseB, int[] indices, ref int tubeCursor)
        {
            // the strip's span once and each step's six indices through a slice of length 6 (one range check per step,
            // the cursor in a register rather than through its reference)
            Span<int> strip = new Span<int>(indices, tubeCursor, radial * 6);
            for (int i = 0; i < radial; i++)
            {
                int a0 = baseA + i, a1 = a0 + 1, b0 = baseB + i, b1 = b0 + 1;
                Span<int> step = strip.Slice(6 * i, 6);
                step[0] = a0; step[1] = a1; step[2] = b0;
                step[3] = a1; step[4] = b1; step[5] = b0;
            }
            tubeCursor += radial * 6;
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
                float r = k >= 0 ? lastRadii[k] : dangling.CutRadius(segment, upper);
                centers[slot] = c + outward * (half * DanglingEnds.ShareOfHalf(fraction, upper));
                tangents[slot] = t;
                normals[slot] = normals[joint];
                ringRadii[slot] = Clamped(r);
                ringV[slot] = k >= 0 ? ringV[k] : cutV;
            }
            if (contactRope != null && contactRope.ColliderCount > 0) PushCentersOutOfColliders(spareFirst, spareFirst + count - 1);
            // dr/ds along the straight half (the joint ring keeps the slope its piece gave it)
            for (int q = 0; q < count; q++)
            {
                int slot = spareFirst + q;
                int behind = q > 0 ? slot - 1 : joint, ahead = q < count - 1 ? slot + 1 : slot;
                float distance = (centers[ahead] - centers[behind]).Length;
                // the ring formula, clamped and then turned for the upper half (the clamp is symmetric)
                float slope = Slope(ringRadii[ahead], ringRadii[behind], distance);
                slopes[slot] = upper ? -slope : slope;
            }
            return count;
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

        private void WriteCap(int k, bool atEnd, int[] indices, bool writeIndices, bool rewrite,
            ref int vertexBase, ref int tubeCursor, ref Bounds bounds)
        {
            Float3 c = centers[k], t = tangents[k], nrm = normals[k];
            Float3 outward = atEnd ? t : -t;
            if (rewrite)
            {
                SetVertex(vertexBase, c, outward, nrm, 0.5f, 0.5f);
                // the rim is the ring's own vertices (the same kernel, so the cap and the tube share exact positions)
                WriteRings(k, k, capRim);
                for (int i = 0; i < radial; i++)
                {
                    ref readonly TubeVertex rim = ref capRim[i];
                    SetVertexInFrame(vertexBase + 1 + i, rim.PX, rim.PY, rim.PZ, outward, nrm, 0.5f + 0.5f * cos[i], 0.5f + 0.5f * sin[i]);
                }
            }
            // the rim lies on ring k, whose bounds the piece adds (AddRingBounds)
            bounds.Add(c);
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

        private void WriteStrands(int k, bool atEnd, int endKey, int[] indices, bool writeIndices, bool rewrite,
            ref int vertexBase, ref int burrCursor)
        {
            if (rewrite)
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
                    Float3 aroundDirection = bin * ca - nrm * sa;
                    Float3 centre = c + radialDirection * (fibre.Radial * reach);
                    Float3 b0 = centre + Corner(nrm, bin, fibre.BaseTurn) * baseRadius;
                    Float3 b1 = centre + Corner(nrm, bin, fibre.BaseTurn + 2.0943951f) * baseRadius;
                    Float3 b2 = centre + Corner(nrm, bin, fibre.BaseTurn + 4.1887902f) * baseRadius;
                    if (!atEnd) { Float3 swap = b0; b0 = b1; b1 = swap; }
                    Float3 side = radialDirection * MathF.Cos(fibre.Twist) + aroundDirection * MathF.Sin(fibre.Twist);
                    Float3 direction = outward * MathF.Cos(fibre.Tilt) + side * MathF.Sin(fibre.Tilt);
                    Float3 tip = centre + direction * (fibre.Length * 2f * r);
                    int v = vertexBase + f * 9;
                    WriteStrandFace(v, b0, b1, tip, outward, ref strandBounds);
                    WriteStrandFace(v + 3, b1, b2, tip, outward, ref strandBounds);
                    WriteStrandFace(v + 6, b2, b0, tip, outward, ref strandBounds);
                }
            }
            if (writeIndices)
            {
                for (int q = 0; q < fibreCount * 9; q++) indices[burrCursor++] = vertexBase + q;
            }
            else
            {
                burrCursor += fibreCount * 9;
            }
            vertexBase += fibreCount * 9;
        }

        private static Float3 Corner(Float3 nrm, Float3 bin, float angle) => nrm * MathF.Cos(angle) + bin * MathF.Sin(angle);

        private void WriteStrandFace(int v, Float3 p0, Float3 p1, Float3 tip, Float3 fallback, ref Bounds bounds)
        {
            Float3 edge = p1 - p0;
            Float3 normal = Float3.Cross(edge, tip - p0).NormalizedOr(fallback);
            Float3 tangent = edge.NormalizedOr(FrameTransport.Perpendicular(fallback, normal));
            SetVertex(v, p0, normal, tangent, 0f, 1f);
            SetVertex(v + 1, p1, normal, tangent, 1f, 1f);
            SetVertex(v + 2, tip, normal, tangent, 0.5f, 0f);
            bounds.Add(p0);
            bounds.Add(tip);
        }

        /// <summary>Writes vertex <paramref name="index"/> at <paramref name="p"/> (relative to the first particle: the frame origin is added).</summary>
        private void SetVertex(int index, Float3 p, Float3 normal, Float3 tangent, float u, float v) =>
            SetVertexInFrame(index, p.X + frameOrigin.X, p.Y + frameOrigin.Y, p.Z + frameOrigin.Z, normal, tangent, u, v);

        /// <summary>
        /// Writes vertex <paramref name="index"/> of the build's buffer at (<paramref name="px"/>, <paramref name="py"/>,
        /// <paramref name="pz"/>), a position in the frame of the input positions (the frame origin already added; the
        /// tangent only where the buffer has one). Inlined: a cap rim writes
        /// 16 of them a ring, where a call with its Float3 arguments cost 37 instructions each.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private void SetVertexInFrame(int index, float px, float py, float pz, Float3 normal, Float3 tangent, float u, float v)
        {
            if (leanOut != null)
            {
                ref LeanTubeVertex lean = ref leanOut[index];
                lean.PX = px; lean.PY = py; lean.PZ = pz;
                lean.NX = normal.X; lean.NY = normal.Y; lean.NZ = normal.Z;
                lean.U = u; lean.V = v;
                return;
            }
            ref TubeVertex vertex = ref fullOut[index];
            vertex.PX = px; vertex.PY = py; vertex.PZ = pz;
            vertex.NX = normal.X; vertex.NY = normal.Y; vertex.NZ = normal.Z;
            vertex.TX = tangent.X; vertex.TY = tangent.Y; vertex.TZ = tangent.Z; vertex.TW = 1f;
            vertex.U = u; vertex.V = v;
        }

        private static bool Same(ReadOnlySpan<float> now, ReadOnlySpan<float> before) => RopePieces.SameBits(now, before);

        /// <summary>The burr values read at every build (the rest of <see cref="BurrSettings"/> is topology).</summary>
        private readonly struct BurrKey : IEquatable<BurrKey>
        {
            private readonly uint seed;
            private readonly float length, spread, splay;

            public BurrKey(BurrSettings burr)
            {
                seed = burr.Seed;
                length = burr.FibreLength;
                spread = burr.FibreLengthSpread;
                splay = burr.Spread;
            }

            public bool Equals(BurrKey other) => seed == other.seed && length.Equals(other.length) && spread.Equals(other.spread) && splay.Equals(other.splay);

            public override bool Equals(object obj) => obj is BurrKey other && Equals(other);

            public override int GetHashCode() => (int)seed;
        }

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
                // plain comparisons (MathF.Min/Max order NaN and signed zeros, which finite geometry never needs)
                Min = new Float3(p.X < Min.X ? p.X : Min.X, p.Y < Min.Y ? p.Y : Min.Y, p.Z < Min.Z ? p.Z : Min.Z);
                Max = new Float3(p.X > Max.X ? p.X : Max.X, p.Y > Max.Y ? p.Y : Max.Y, p.Z > Max.Z ? p.Z : Max.Z);
            }

            /// <summary>Adds the box lo … hi (lo ≤ hi per axis, or NaN): the same result as Add(lo) then Add(hi), with half the comparisons.</summary>
            [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
            public void AddBox(float lx, float ly, float lz, float hx, float hy, float hz)
            {
                Min = new Float3(lx < Min.X ? lx : Min.X, ly < Min.Y ? ly : Min.Y, lz < Min.Z ? lz : Min.Z);
                Max = new Float3(hx > Max.X ? hx : Max.X, hy > Max.Y ? hy : Max.Y, hz > Max.Z ? hz : Max.Z);
            }

            public void Add(Bounds other)
            {
                if (other.Min.X > other.Max.X) return;
                Add(other.Min);
                Add(other.Max);
            }
        }
    }
}
