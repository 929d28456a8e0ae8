using System;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;

namespace HookeRope
{
    /// <summary>
    /// The facade the Unity layer and the headless lab use: a <see cref="Solver.Rope"/> plus an optional
    /// <see cref="Radius.RadiusModel"/>, the read-outs and the tube mesh. <see cref="Step"/> steps the solver,
    /// updates the radii, writes them into the rope's particle radii (colliders see the thinning rope), breaks the
    /// rope at the defect when the model's fracture decision says so, and updates <see cref="Readouts"/>.
    /// <see cref="FillMesh(ReadOnlySpan{float}, ReadOnlySpan{float}, ReadOnlySpan{float}, TubeVertex[], int[], float)"/>
    /// is the one mesh path. Allocation-free per step and per mesh fill after warm-up (a change of rest length, rest
    /// radius or mesh topology settings reallocates once).
    /// </summary>
    public sealed class RopeSimulation
    {
        private readonly RopeMesh mesh;
        private RadiusModel radiusModel;
        private int settingsVersion;
        private float modelRestRadius;
        private float modelRestLength;
        private float[] radiusLengths;

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
            mesh = new RopeMesh(this, meshSettings ?? new TubeMeshSettings());
            Readouts = new RopeReadouts(this);
            rope.Broken += OnRopeBroken;
            RebuildModel();
            UpdateRadii();
            Readouts.Update(0f);
        }

        /// <summary>The solver rope (positions in its rope-local frame, world = Rope.Origin + local).</summary>
        public Rope Rope { get; }

        /// <summary>Radius settings, or null when the rope has no radius model.</summary>
        public RadiusSettings RadiusSettings { get; }

        /// <summary>Mesh settings (topology values are picked up at the next mesh fill or count).</summary>
        public TubeMeshSettings MeshSettings => mesh.Settings;

        /// <summary>The read-outs (tensions, elongation, strain, arrest force, radii, residual, first break), updated by <see cref="Step"/>.</summary>
        public RopeReadouts Readouts { get; }

        /// <summary>The radius model, or null when <see cref="RadiusSettings"/> is null.</summary>
        public RadiusModel RadiusModel => radiusModel;

        /// <summary>Rest radius R in metres (from the rope settings).</summary>
        public float RestRadius => Rope.Settings.Radius;

        /// <summary>Smallest radius along the rope in metres (R without a radius model).</summary>
        public float MinRadius => IsModelActive ? radiusModel.MinRadius : RestRadius;

        /// <summary>Radius at the defect in metres, neck included (R without a radius model).</summary>
        public float NeckRadius => IsModelActive ? radiusModel.NeckRadius : RestRadius;

        /// <summary>True once any segment has broken (by the radius model's fracture decision, a cut or a pin).</summary>
        public bool IsBroken => Rope.BrokenSegmentCount > 0;

        /// <summary>Radius at each particle in metres, neck included: what the colliders use (the rope's own array).</summary>
        public ReadOnlySpan<float> ParticleRadii => Rope.ParticleRadius;

        /// <summary>Incremented whenever the mesh topology changes (a break, new mesh settings): re-query the buffer sizes and re-upload the indices.</summary>
        public int MeshTopologyVersion => mesh.TopologyVersion;

        /// <summary>The mesh (layout, builder, ring radii), for the package's own assemblies.</summary>
        internal RopeMesh Mesh => mesh;

        private bool IsModelActive => radiusModel != null && radiusModel.IsActive;

        /// <summary>
        /// Steps the solver by <paramref name="hostDeltaTime"/> seconds, then (when the radius model is on) updates
        /// the radii, writes the particle radii into the rope and breaks it at the defect when the model asks; last,
        /// updates <see cref="Readouts"/>.
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
            Readouts.Update(report.Residual);
            return report;
        }

        /// <summary>
        /// Updates the radii from the rope's current segment lengths, writes them into the rope's collision radii and
        /// breaks the rope at the defect when the model's fracture decision says so (the only fracture path).
        /// <see cref="Step"/> calls it; call it yourself after moving particles by hand (the constructor calls it
        /// once). Does nothing without an active radius model.
        /// </summary>
        public void UpdateRadii()
        {
            if (!IsModelActive) return;
            // the elastic–plastic material drives the neck (onset, waist, break at the ultimate strain)
            radiusModel.FollowMaterial(Rope.IsRopePlastic, Rope.NeckSoftening, Rope.Settings.UltimateStrain);
            radiusModel.Update(RadiusLengths(), Rope.BrokenSegments);
            if (Rope.IsRopePlastic && Rope.NeckSegment != radiusModel.DefectSegment) Rope.SetNeckSegment(radiusModel.DefectSegment);
            if (RadiusSettings.PoissonThinning || RadiusSettings.Necking)
                Rope.SetParticleRadii(radiusModel.ParticleRadii);
            if (radiusModel.ShouldBreak)
            {
                int defect = radiusModel.DefectSegment;
                radiusModel.MarkBroken();
                Rope.BreakSegment(defect);
            }
        }

        /// <summary>
        /// The segment lengths the radius model thins the rope by: the rope's, except the energy absorber's segment, whose
        /// deployed webbing unfolds without stretching (its length less the deployment). Allocation-free.
        /// </summary>
        private ReadOnlySpan<float> RadiusLengths()
        {
            ReadOnlySpan<float> lengths = Rope.SegmentLengths;
            int absorber = Rope.AbsorberSegment;
            if (absorber < 0) return lengths;
            if (radiusLengths == null || radiusLengths.Length != lengths.Length) radiusLengths = new float[lengths.Length];
            lengths.CopyTo(radiusLengths);
            radiusLengths[absorber] = Math.Max(lengths[absorber] - (float)Rope.AbsorberDeployment, 0f);
            return radiusLengths;
        }

        /// <summary>Vertices the mesh needs now (the broken segments change it).</summary>
        public int GetVertexCount() => mesh.GetVertexCount();

        /// <summary>Indices the mesh needs now (the broken segments change it).</summary>
        public int GetIndexCount() => mesh.GetIndexCount();

        /// <summary>
        /// Most vertices the mesh can need until a segment breaks or the mesh topology settings change: with adaptive rings,
        /// every piece at its ring budget's cap (<c>MaxMeanRingsPerSegment</c> = 8 rings per segment on average, plus a Zone
        /// neck's stations; Documentation~/radius-and-mesh.md, "Ring budget"), else <see cref="GetVertexCount"/>. Buffers
        /// of this size, made once, take every ring budget the rope's motion asks for: no fill reallocates them.
        /// </summary>
        public int GetVertexCapacity() => mesh.GetVertexCapacity();

        /// <summary>Most indices the mesh can need until a segment breaks or the mesh topology settings change (see <see cref="GetVertexCapacity"/>).</summary>
        public int GetIndexCapacity() => mesh.GetIndexCapacity();

        /// <summary>
        /// The one mesh path. Fills caller-owned buffers (at least <see cref="GetVertexCount"/> and
        /// <see cref="GetIndexCount"/> long) with the tube mesh through the particle positions
        /// <paramref name="x"/>, <paramref name="y"/>, <paramref name="z"/> (m, ParticleCount each) given in the
        /// caller's frame (e.g. renderer-local); vertices and bounds are written in that same frame. Ring radii come
        /// from the radius model (R without one) times <paramref name="radiusScale"/> (e.g. 1/|lossyScale.x|); broken
        /// segments come from the rope. Indices are rewritten only when the topology changed
        /// (<see cref="TubeMeshUpdate.TopologyChanged"/>). Allocation-free after warm-up.
        /// </summary>
        public TubeMeshUpdate FillMesh(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            TubeVertex[] vertices, int[] indices, float radiusScale = 1f) =>
            FillMesh(x, y, z, vertices, null, indices, radiusScale, null);

        /// <summary>
        /// <see cref="FillMesh(ReadOnlySpan{float}, ReadOnlySpan{float}, ReadOnlySpan{float}, TubeVertex[], int[], float)"/>
        /// for positions in a caller frame placed in the rope's world frame by <paramref name="frame"/> (e.g. a
        /// renderer's local space: its pose relative to the frame of <see cref="Solver.Rope.Origin"/>): ring centres
        /// closer to one of the rope's colliders than their drawn radius (ring radius × |frame.Scale|, m) are pushed out
        /// along its normal, so the drawn tube does not sink into a collider it wraps. Allocation-free after warm-up.
        /// </summary>
        public TubeMeshUpdate FillMesh(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            TubeVertex[] vertices, int[] indices, float radiusScale, MeshFrame frame) =>
            FillMesh(x, y, z, vertices, null, indices, radiusScale, frame);

        /// <summary>
        /// <see cref="FillMesh(ReadOnlySpan{float}, ReadOnlySpan{float}, ReadOnlySpan{float}, TubeVertex[], int[], float, MeshFrame)"/>
        /// through the rope's own positions: vertices in the rope-local frame (world = <see cref="Solver.Rope.Origin"/> + v).
        /// </summary>
        public TubeMeshUpdate FillMesh(TubeVertex[] vertices, int[] indices) => FillMesh(vertices, null, indices);

        /// <summary>
        /// <see cref="FillMesh(ReadOnlySpan{float}, ReadOnlySpan{float}, ReadOnlySpan{float}, TubeVertex[], int[], float)"/>
        /// into vertices without tangents (<see cref="LeanTubeVertex"/>, 32 bytes instead of 48: for materials without a
        /// normal map). Every written field has the bits of the same field of a <see cref="TubeVertex"/> fill.
        /// </summary>
        public TubeMeshUpdate FillMesh(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            LeanTubeVertex[] vertices, int[] indices, float radiusScale = 1f) =>
            FillMesh(x, y, z, null, vertices, indices, radiusScale, null);

        /// <summary>
        /// <see cref="FillMesh(ReadOnlySpan{float}, ReadOnlySpan{float}, ReadOnlySpan{float}, TubeVertex[], int[], float, MeshFrame)"/>
        /// into vertices without tangents (<see cref="LeanTubeVertex"/>).
        /// </summary>
        public TubeMeshUpdate FillMesh(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            LeanTubeVertex[] vertices, int[] indices, float radiusScale, MeshFrame frame) =>
            FillMesh(x, y, z, null, vertices, indices, radiusScale, frame);

        /// <summary><see cref="FillMesh(TubeVertex[], int[])"/> into vertices without tangents (<see cref="LeanTubeVertex"/>).</summary>
        public TubeMeshUpdate FillMesh(LeanTubeVertex[] vertices, int[] indices) => FillMesh(null, vertices, indices);

        /// <summary>
        /// The fill every overload above calls: into <paramref name="vertices"/> or, when it is null,
        /// <paramref name="leanVertices"/> (the host's choice of layout, e.g. <see cref="World.RopeMeshSlot.Tangents"/>), from
        /// caller positions with an optional <paramref name="frame"/>.
        /// </summary>
        internal TubeMeshUpdate FillMesh(ReadOnlySpan<float> x, ReadOnlySpan<float> y, ReadOnlySpan<float> z,
            TubeVertex[] vertices, LeanTubeVertex[] leanVertices, int[] indices, float radiusScale, MeshFrame? frame) =>
            mesh.Fill(x, y, z, vertices, leanVertices, indices, CheckedRadiusScale(radiusScale), frame);

        /// <summary>The fill through the rope's own positions (rope-local frame), into either kind of buffer.</summary>
        internal TubeMeshUpdate FillMesh(TubeVertex[] vertices, LeanTubeVertex[] leanVertices, int[] indices) =>
            mesh.Fill(Rope.PositionX, Rope.PositionY, Rope.PositionZ, vertices, leanVertices, indices, 1f, MeshFrame.Shifted(Rope.Origin));

        private static float CheckedRadiusScale(float radiusScale)
        {
            if (!float.IsFinite(radiusScale) || !(radiusScale > 0f))
                throw new ArgumentOutOfRangeException(nameof(radiusScale), radiusScale, "radiusScale must be finite and in (0, +inf).");
            return radiusScale;
        }

        private void OnRopeBroken(RopeBreakEvent e)
        {
            mesh.TopologyChanged();
            if (radiusModel != null && !radiusModel.IsBroken) radiusModel.MarkBroken();
            Readouts.RecordBreak(e);
        }

        private void RebuildModel()
        {
            RopeSettings settings = Rope.Settings;
            settingsVersion = settings.Version;
            modelRestRadius = settings.Radius;
            modelRestLength = settings.RestLength;
            if (RadiusSettings != null)
            {
                bool wasBroken = radiusModel != null && radiusModel.IsBroken;
                radiusModel = new RadiusModel(RadiusSettings, settings.Radius, Rope.RestLengths);
                if (wasBroken || Rope.BrokenSegmentCount > 0) radiusModel.MarkBroken();
                Rope.SetNeckSegment(radiusModel.DefectSegment);   // the plastic material necks at the model's defect
                if (settings.EnergyAbsorber) radiusLengths = new float[Rope.SegmentCount];
            }
            mesh.Invalidate();
        }
    }
}
