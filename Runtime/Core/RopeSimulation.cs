using System;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;

namespace HookeRope
{
    /// <summary>
    /// The facade the Unity layer and the headless lab use: a <see cref="Solver.Rope"/> plus an optional
    /// <see cref="Radius.RadiusModel"/> and the tube mesh. <see cref="Step"/> steps the solver, updates the radii,
    /// writes them into <see cref="Rope.ParticleRadius"/> (colliders see the thinning rope) and breaks the rope at
    /// the defect when the radius model says so. Allocation-free per step and per mesh fill after warm-up (a break
    /// or a change of rest length, rest radius or mesh topology settings reallocates once).
    /// </summary>
    public sealed class RopeSimulation
    {
        /// <summary>Rings placed inside the Zone-mode neck zone (the ring layout is refined there).</summary>
        public const int RingsInNeckZone = 16;

        private readonly bool[] brokenFlags;
        private readonly float[] restRadiusSegments;
        private readonly float[] restRadiusParticles;
        private RadiusModel radiusModel;
        private TubeMeshBuilder meshBuilder;
        private float[] ringRadii;
        private int settingsVersion;
        private float modelRestRadius;
        private float modelRestLength;
        private int topologyVersion;
        private int brokenCount;
        private int meshSettingsRings;
        private bool meshCaps;
        private bool meshBurr;
        private NeckMode meshNeckMode;
        private float meshDefect;
        private float meshZone;

        /// <summary>
        /// Builds a rope from <paramref name="ropeSettings"/> between world points <paramref name="start"/> and
        /// <paramref name="end"/> (m). <paramref name="radiusSettings"/> null = no radius model (the rope keeps its
        /// rest radius and no per-step radius work is done); <paramref name="meshSettings"/> null = defaults.
        /// </summary>
        public RopeSimulation(RopeSettings ropeSettings, Float3 start, Float3 end, RadiusSettings radiusSettings = null, TubeMeshSettings meshSettings = null)
            : this(new Rope(ropeSettings, start, end), radiusSettings, meshSettings)
        {
        }

        /// <summary>Wraps an existing rope (pins, loads and colliders may be added to it before or after).</summary>
        public RopeSimulation(Rope rope, RadiusSettings radiusSettings = null, TubeMeshSettings meshSettings = null)
        {
            Rope = rope ?? throw new ArgumentNullException(nameof(rope));
            RadiusSettings = radiusSettings;
            MeshSettings = meshSettings ?? new TubeMeshSettings();
            int n = rope.SegmentCount;
            brokenFlags = new bool[n];
            restRadiusSegments = new float[n];
            restRadiusParticles = new float[n + 1];
            for (int j = 0; j < n; j++)
            {
                brokenFlags[j] = rope.IsSegmentBroken(j);
                if (brokenFlags[j]) brokenCount++;
            }
            rope.Broken += OnRopeBroken;
            RebuildModel();
            UpdateRadii();
        }

        /// <summary>The solver rope (positions in its rope-local frame, world = Rope.Origin + local).</summary>
        public Rope Rope { get; }

        /// <summary>Radius settings, or null when the rope has no radius model.</summary>
        public RadiusSettings RadiusSettings { get; }

        /// <summary>Mesh settings (topology values are picked up at the next mesh fill).</summary>
        public TubeMeshSettings MeshSettings { get; }

        /// <summary>The radius model, or null when <see cref="RadiusSettings"/> is null.</summary>
        public RadiusModel RadiusModel => radiusModel;

        /// <summary>Rest radius R in metres (from the rope settings).</summary>
        public float RestRadius => Rope.Settings.Radius;

        /// <summary>Smallest radius along the rope in metres (R without a radius model).</summary>
        public float MinRadius => IsModelActive ? radiusModel.MinRadius : RestRadius;

        /// <summary>Radius at the defect in metres, neck included (R without a radius model).</summary>
        public float NeckRadius => IsModelActive ? radiusModel.NeckRadius : RestRadius;

        /// <summary>True once any segment has broken (by the radius model, the solver's strain limit or a pin).</summary>
        public bool IsBroken => brokenCount > 0;

        /// <summary>Per-segment broken flags, as the mesh sees them.</summary>
        public ReadOnlySpan<bool> BrokenSegments => brokenFlags;

        /// <summary>Radius of each segment in metres (Poisson; R without a radius model).</summary>
        public ReadOnlySpan<float> SegmentRadii => IsModelActive ? radiusModel.SegmentRadii : restRadiusSegments;

        /// <summary>Radius at each particle in metres, neck included: what the colliders use.</summary>
        public ReadOnlySpan<float> ParticleRadii => IsModelActive ? radiusModel.ParticleRadii : restRadiusParticles;

        /// <summary>Incremented whenever the mesh topology changes (a break, new mesh settings): re-query the buffer sizes.</summary>
        public int TopologyVersion => topologyVersion;

        /// <summary>Ring layout of the mesh (refined around the neck zone in Zone mode).</summary>
        public RingLayout RingLayout => EnsureMesh().Layout;

        /// <summary>Radius at each mesh ring in metres (after the last <see cref="FillMesh"/> or <see cref="FillRingRadii"/>).</summary>
        public ReadOnlySpan<float> RingRadii { get { EnsureMesh(); return ringRadii; } }

        private bool IsModelActive => radiusModel != null && radiusModel.IsActive;

        /// <summary>
        /// Steps the solver by <paramref name="hostDeltaTime"/> seconds, then (when the radius model is on) updates
        /// the radii, writes the particle radii into the rope and breaks it at the defect when the model asks.
        /// </summary>
        public StepReport Step(float hostDeltaTime)
        {
            StepReport report = Rope.Step(hostDeltaTime);
            RopeSettings settings = Rope.Settings;
            if (settings.Version != settingsVersion)
            {
                settingsVersion = settings.Version;
                if (settings.Radius != modelRestRadius || settings.RestLength != modelRestLength) RebuildModel();
            }
            UpdateRadii();
            return report;
        }

        /// <summary>
        /// Updates the radii from the rope's current segment lengths, writes them into the rope's collision radii and
        /// breaks the rope at the defect when the model asks. <see cref="Step"/> calls it; call it yourself after
        /// moving particles by hand (the constructor calls it once). Does nothing without an active radius model.
        /// </summary>
        public void UpdateRadii()
        {
            if (!IsModelActive) return;
            radiusModel.Update(Rope.SegmentLengths, brokenFlags);
            if (RadiusSettings.PoissonEnabled || RadiusSettings.NeckMode != NeckMode.Off)
                radiusModel.ParticleRadii.CopyTo(Rope.ParticleRadius);
            if (radiusModel.ShouldBreak)
            {
                int defect = radiusModel.DefectSegment;
                radiusModel.MarkBroken();
                Rope.BreakSegment(defect);
            }
        }

        /// <summary>Vertices the mesh needs now.</summary>
        public int GetVertexCount() => EnsureMesh().GetVertexCount(brokenFlags);

        /// <summary>Indices the mesh needs now.</summary>
        public int GetIndexCount() => EnsureMesh().GetIndexCount(brokenFlags);

        /// <summary>Computes the radius of every mesh ring (m) into <see cref="RingRadii"/>.</summary>
        public void FillRingRadii() => ComputeRingRadii(EnsureMesh());

        private void ComputeRingRadii(TubeMeshBuilder builder)
        {
            if (IsModelActive)
            {
                RingLayout layout = builder.Layout;
                radiusModel.FillRingRadii(layout.RingSegments, layout.RingFractions, ringRadii);
            }
            else
            {
                Array.Fill(ringRadii, Rope.Settings.Radius);
            }
        }

        /// <summary>
        /// Fills caller-owned buffers (at least <see cref="GetVertexCount"/> and <see cref="GetIndexCount"/> long)
        /// with the tube mesh. Vertex positions are relative to the first particle; the returned
        /// <see cref="TubeMeshUpdate.Origin"/> is that particle's world position (m). Indices are rewritten only
        /// when the topology changed (see <see cref="TubeMeshUpdate.TopologyChanged"/>).
        /// </summary>
        public TubeMeshUpdate FillMesh(TubeVertex[] vertices, int[] indices)
        {
            TubeMeshBuilder builder = EnsureMesh();
            ComputeRingRadii(builder);
            TubeMeshUpdate u = builder.BuildWithRingRadii(Rope.PositionX, Rope.PositionY, Rope.PositionZ, Rope.RestLengths,
                ringRadii, brokenFlags, vertices, indices);
            return new TubeMeshUpdate(u.VertexCount, u.IndexCount, u.TubeIndexCount, u.TopologyChanged,
                Rope.Origin + u.Origin, u.BoundsMin, u.BoundsMax);
        }

        private void OnRopeBroken(RopeBreakEvent e)
        {
            if (e.Segment < 0 || e.Segment >= brokenFlags.Length || brokenFlags[e.Segment]) return;
            brokenFlags[e.Segment] = true;
            brokenCount++;
            topologyVersion++;
            if (radiusModel != null && !radiusModel.IsBroken) radiusModel.MarkBroken();
        }

        private void RebuildModel()
        {
            RopeSettings settings = Rope.Settings;
            settingsVersion = settings.Version;
            modelRestRadius = settings.Radius;
            modelRestLength = settings.RestLength;
            Array.Fill(restRadiusSegments, settings.Radius);
            Array.Fill(restRadiusParticles, settings.Radius);
            if (RadiusSettings != null)
            {
                bool wasBroken = radiusModel != null && radiusModel.IsBroken;
                radiusModel = new RadiusModel(RadiusSettings, settings.Radius, Rope.RestLengths);
                if (wasBroken || brokenCount > 0) radiusModel.MarkBroken();
            }
            meshBuilder = null;
        }

        private TubeMeshBuilder EnsureMesh()
        {
            TubeMeshSettings s = MeshSettings;
            RadiusSettings r = RadiusSettings;
            NeckMode neckMode = r == null ? NeckMode.Off : r.NeckMode;
            float defect = r == null ? 0f : r.DefectPosition;
            float zone = r == null ? 0f : r.NeckZoneDiameters;
            if (meshBuilder != null
                && meshBuilder.RadialSegments == s.RadialSegments
                && meshSettingsRings == s.RingsPerSegment
                && meshCaps == s.CapEnds
                && meshBurr == s.Burr.Enabled
                && meshNeckMode == neckMode
                && meshDefect == defect
                && meshZone == zone)
                return meshBuilder;
            meshSettingsRings = s.RingsPerSegment;
            meshCaps = s.CapEnds;
            meshBurr = s.Burr.Enabled;
            meshNeckMode = neckMode;
            meshDefect = defect;
            meshZone = zone;
            RingLayout layout = meshNeckMode == NeckMode.Zone && radiusModel != null
                ? RingLayout.Refined(Rope.RestLengths, s.RingsPerSegment, radiusModel.DefectRestArc, radiusModel.NeckZoneRestLength, RingsInNeckZone)
                : new RingLayout(Rope.SegmentCount, s.RingsPerSegment);
            meshBuilder = new TubeMeshBuilder(s, layout);
            ringRadii = new float[layout.RingCount];
            topologyVersion++;
            return meshBuilder;
        }
    }
}
