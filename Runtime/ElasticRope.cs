using System;
using System.Diagnostics;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;
using UnityEngine;
using Debug = UnityEngine.Debug;

namespace HookeRope
{
    /// <summary>
    /// An elastic rope with real physics in SI units: thin glue over the engine-free core. It holds the
    /// serialized settings, builds the core rope, copies anchor and hand poses in every FixedUpdate, steps the
    /// solver (substeps inside), exchanges forces with attached Rigidbodies (two-way) and exposes read-outs.
    /// Rendering lives in <see cref="RopeMeshRenderer"/>. Inspector changes in Play apply at the next step;
    /// only a new segment count or new attachments rebuild the rope.
    /// </summary>
    [AddComponentMenu("Physics/Elastic Rope")]
    [HelpURL(DocumentationUrl)]
    [DisallowMultipleComponent]
    public sealed class ElasticRope : MonoBehaviour
    {
        /// <summary>The package manual.</summary>
        public const string DocumentationUrl = "https://github.com/hookerope/com.hookerope.elastic-rope/blob/main/Documentation~/index.md";

        // ---- Material -------------------------------------------------------------------------------------
        [SerializeField, Tooltip(RopeParameters.StiffnessInput.Tooltip)]
        RopeStiffnessInput m_StiffnessInput = (RopeStiffnessInput)RopeParameters.StiffnessInput.Default;

        [SerializeField, Tooltip(RopeParameters.YoungsModulus.Tooltip)]
        float m_YoungsModulus = RopeParameters.YoungsModulus.Default;

        [SerializeField, Tooltip(RopeParameters.AxialStiffness.Tooltip)]
        float m_AxialStiffness = RopeParameters.AxialStiffness.Default;

        [SerializeField, Tooltip(RopeParameters.Density.Tooltip)]
        float m_Density = RopeParameters.Density.Default;

        [SerializeField, Range(RopeParameters.PoissonRatio.Min, RopeParameters.PoissonRatio.Max), Tooltip(RopeParameters.PoissonRatio.Tooltip)]
        float m_PoissonRatio = RopeParameters.PoissonRatio.Default;

        [SerializeField, Tooltip(RopeParameters.Damping.Tooltip)]
        float m_Damping = RopeParameters.Damping.Default;

        // ---- Geometry -------------------------------------------------------------------------------------
        [SerializeField, Tooltip(RopeParameters.RestLength.Tooltip)]
        float m_RestLength = RopeParameters.RestLength.Default;

        [SerializeField, Tooltip(RopeParameters.Radius.Tooltip)]
        float m_Radius = RopeParameters.Radius.Default;

        [SerializeField, Tooltip(RopeParameters.SegmentCount.Tooltip)]
        int m_SegmentCount = RopeParameters.SegmentCount.Default;

        // ---- Solver ---------------------------------------------------------------------------------------
        [SerializeField, Tooltip(RopeParameters.Solver.Tooltip)]
        ConstraintSolverKind m_Solver = RopeParameters.Solver.Default;

        [SerializeField, Tooltip(RopeParameters.Substeps.Tooltip)]
        int m_Substeps = RopeParameters.Substeps.Default;

        [SerializeField, Tooltip(RopeParameters.Iterations.Tooltip)]
        int m_Iterations = RopeParameters.Iterations.Default;

        [SerializeField, Tooltip(RopeParameters.TensionModel.Tooltip)]
        TensionModel m_TensionModel = RopeParameters.TensionModel.Default;

        [SerializeField, Tooltip(RopeParameters.Gravity.Tooltip)]
        Vector3 m_Gravity = new Vector3(RopeParameters.Gravity.DefaultX, RopeParameters.Gravity.DefaultY, RopeParameters.Gravity.DefaultZ);

        // ---- Attachments ----------------------------------------------------------------------------------
        [SerializeField, Tooltip("Start of the rope (first particle): a Transform to follow, a Rigidbody to pull two-way, or nothing.")]
        RopeEnd m_Start = new RopeEnd();

        [SerializeField, Tooltip("End of the rope (last particle): a Transform to follow, a Rigidbody to pull two-way (e.g. a harness D-ring), or nothing.")]
        RopeEnd m_End = new RopeEnd();

        [SerializeField, Tooltip(RopeParameters.AttachmentCompliance.Tooltip)]
        float m_AttachmentCompliance = RopeParameters.AttachmentCompliance.Default;

        // ---- Collisions -----------------------------------------------------------------------------------
        [SerializeField, Tooltip("Off costs nothing. Listed Colliders: the colliders and planes below. Layer Mask: Sphere/Capsule/Box colliders on these layers within the rope's reach, re-queried every physics step.")]
        RopeCollisionMode m_CollisionMode = RopeCollisionMode.Off;

        [SerializeField, Tooltip("Sphere, Capsule and Box colliders the rope collides with (Listed Colliders mode).")]
        Collider[] m_Colliders = Array.Empty<Collider>();

        [SerializeField, Tooltip("Layers searched for colliders (Layer Mask mode).")]
        LayerMask m_CollisionLayers = -1;

        [SerializeField, Tooltip("Infinite planes the rope stays above: each Transform's position is a point on the plane, its up axis the normal.")]
        Transform[] m_Planes = Array.Empty<Transform>();

        [SerializeField, Tooltip(RopeParameters.Friction.Tooltip)]
        float m_Friction = RopeParameters.Friction.Default;

        // ---- Radius, necking and fracture -----------------------------------------------------------------
        [SerializeField, Tooltip(RopeParameters.PoissonThinning.Tooltip)]
        bool m_RadiusModel = RopeParameters.PoissonThinning.Default;

        [SerializeField, Tooltip(RopeParameters.Necking.Tooltip)]
        bool m_Necking = RopeParameters.Necking.Default;

        [SerializeField, Tooltip(RopeParameters.NeckMode.Tooltip)]
        NeckMode m_NeckMode = RopeParameters.NeckMode.Default;

        [SerializeField, Range(RopeParameters.NeckRadiusFraction.Min, RopeParameters.NeckRadiusFraction.Max), Tooltip(RopeParameters.NeckRadiusFraction.Tooltip)]
        float m_NeckRadiusFraction = RopeParameters.NeckRadiusFraction.Default;

        [SerializeField, Range(RopeParameters.DefectPosition.Min, RopeParameters.DefectPosition.Max), Tooltip(RopeParameters.DefectPosition.Tooltip)]
        float m_DefectPosition = RopeParameters.DefectPosition.Default;

        [SerializeField, Tooltip(RopeParameters.Fracture.Tooltip)]
        bool m_Fracture = RopeParameters.Fracture.Default;

        [SerializeField, Tooltip(RopeParameters.BreakStrain.Tooltip)]
        float m_BreakStrain = RopeParameters.BreakStrain.Default;

        [SerializeField, Range(RopeParameters.BreakRadiusFraction.Min, RopeParameters.BreakRadiusFraction.Max), Tooltip(RopeParameters.BreakRadiusFraction.Tooltip)]
        float m_BreakRadiusFraction = RopeParameters.BreakRadiusFraction.Default;

        // ---- Events ---------------------------------------------------------------------------------------
        [SerializeField, Tooltip("Raised when the rope breaks, with the break position (world, m) and the peak tension just before it (N).")]
        RopeBreakUnityEvent m_OnBreak = new RopeBreakUnityEvent();

        // ---- Runtime state (not serialized) ---------------------------------------------------------------
        Rope _rope;
        RopeSettings _settings;
        readonly RopeColliderBinding _colliderBinding = new RopeColliderBinding();
        readonly RopeAttachmentBinding _attachments = new RopeAttachmentBinding();
        readonly RadiusSettings _radiusSettings = new RadiusSettings();
        RopeSimulation _simulation;
        readonly Stopwatch _stopwatch = new Stopwatch();
        Vector3 _origin;
        bool _rebuildPending;
        bool _breakRaised;

        // ---- Read-outs ------------------------------------------------------------------------------------
        /// <summary>Raised when the rope breaks: world position (m) and peak tension just before (N).</summary>
        public RopeBreakUnityEvent OnBreak => m_OnBreak;

        /// <summary>The core rope, or null before the first build. Use <c>Simulation.Rope</c>.</summary>
        [Obsolete("Use Simulation.Rope (the one way into the core); Core is removed in 0.2.")]
        public Rope Core => _simulation?.Rope;

        /// <summary>True once the core rope exists.</summary>
        public bool IsBuilt => _rope != null;

        /// <summary>Σ over the intact segments of (current length − rest length) (m); 0 before the build.</summary>
        public float Elongation => (float)(Readouts?.Elongation ?? 0.0);

        /// <summary><see cref="Elongation"/> over the rest length of the intact segments (dimensionless); 0 before the build.</summary>
        public float Strain => (float)(Readouts?.Strain ?? 0.0);

        /// <summary>Tension in the first segment (N); 0 once it is broken.</summary>
        public float TopTension => Readouts?.TopTension ?? 0f;

        /// <summary>Tension in the last segment (N); 0 once it is broken.</summary>
        public float BottomTension => Readouts?.BottomTension ?? 0f;

        /// <summary>Largest intact-segment tension since the build or <see cref="ResetPeaks"/> (N).</summary>
        public float PeakTension => Readouts?.PeakTension ?? 0f;

        /// <summary>Smallest radius along the rope now, neck included (m).</summary>
        public float MinRadius => Readouts?.MinRadius ?? 0f;

        /// <summary>Radius at the defect (m): the neck radius once necking has started, else the local Poisson radius.</summary>
        public float NeckRadius => Readouts?.NeckRadius ?? 0f;

        /// <summary>True once any segment has broken.</summary>
        public bool IsBroken => Readouts?.IsBroken ?? false;

        /// <summary>
        /// Force the rope exerts on the end load now (N): on the end Rigidbody when there is one, else the bottom
        /// tension. This is the arrest force of a fall-arrest lanyard.
        /// </summary>
        public float ArrestForce => Readouts?.ArrestForce ?? 0f;

        /// <summary>Largest <see cref="ArrestForce"/> since the build or <see cref="ResetPeaks"/> (N).</summary>
        public float PeakArrestForce => Readouts?.PeakArrestForce ?? 0f;

        /// <summary>True while <see cref="PeakArrestForce"/> is within EN 355's 6 kN.</summary>
        public bool MeetsEn355 => FallArrestLimits.MeetsEn355(PeakArrestForce);

        /// <summary>True while <see cref="PeakArrestForce"/> is within ANSI Z359.13's 8 kN.</summary>
        public bool MeetsAnsiZ359_13 => FallArrestLimits.MeetsAnsiZ359_13(PeakArrestForce);

        /// <summary>Constraint residual of the last step: largest strain error against the compliance-consistent target (dimensionless).</summary>
        public float Residual => Readouts?.Residual ?? 0f;

        /// <summary>Wall-clock time of the last solver step (ms), for trading substeps/iterations against accuracy.</summary>
        public float StepMilliseconds { get; private set; }

        RopeReadouts Readouts => _simulation?.Readouts;

        /// <summary>Particles in the built rope (segments + 1), or 0 before the build.</summary>
        public int ParticleCount => _rope?.ParticleCount ?? 0;

        // ---- Settings properties (validated; changes apply at the next step) ------------------------------
        /// <summary>Young's modulus E (Pa), range <see cref="RopeParameters.YoungsModulus"/>. Setting it switches the stiffness input to E.</summary>
        public float YoungsModulus
        {
            get => m_StiffnessInput == RopeStiffnessInput.YoungsModulus ? m_YoungsModulus : m_AxialStiffness / Area(m_Radius);
            set
            {
                m_YoungsModulus = RopeParameters.Check(value, RopeParameters.YoungsModulus.Row);
                m_StiffnessInput = RopeStiffnessInput.YoungsModulus;
                m_AxialStiffness = m_YoungsModulus * Area(m_Radius);
                ApplySettings();
            }
        }

        /// <summary>Axial stiffness E·A (N), range <see cref="RopeParameters.AxialStiffness"/>. Setting it switches the stiffness input to E·A.</summary>
        public float AxialStiffness
        {
            get => m_StiffnessInput == RopeStiffnessInput.AxialStiffness ? m_AxialStiffness : m_YoungsModulus * Area(m_Radius);
            set
            {
                m_AxialStiffness = RopeParameters.Check(value, RopeParameters.AxialStiffness.Row);
                m_StiffnessInput = RopeStiffnessInput.AxialStiffness;
                m_YoungsModulus = m_AxialStiffness / Area(m_Radius);
                ApplySettings();
            }
        }

        /// <summary>Material density ρ (kg/m³), range <see cref="RopeParameters.Density"/>.</summary>
        public float Density
        {
            get => m_Density;
            set { m_Density = RopeParameters.Check(value, RopeParameters.Density.Row); ApplySettings(); }
        }

        /// <summary>Rope mass per metre ρ·πR² (kg/m).</summary>
        public float LinearDensity => m_Density * Area(m_Radius);

        /// <summary>Poisson ratio ν (dimensionless), range <see cref="RopeParameters.PoissonRatio"/>.</summary>
        public float PoissonRatio
        {
            get => m_PoissonRatio;
            set { m_PoissonRatio = RopeParameters.Check(value, RopeParameters.PoissonRatio.Row); ApplySettings(); }
        }

        /// <summary>XPBD damping coefficient β (s), range <see cref="RopeParameters.Damping"/>.</summary>
        public float Damping
        {
            get => m_Damping;
            set { m_Damping = RopeParameters.Check(value, RopeParameters.Damping.Row); ApplySettings(); }
        }

        /// <summary>Rest length L (m), range <see cref="RopeParameters.RestLength"/>.</summary>
        public float RestLength
        {
            get => m_RestLength;
            set { m_RestLength = RopeParameters.Check(value, RopeParameters.RestLength.Row); ApplySettings(); }
        }

        /// <summary>Rest radius R (m), range <see cref="RopeParameters.Radius"/>. With E·A as the stiffness input, E·A is kept and E follows.</summary>
        public float Radius
        {
            get => m_Radius;
            set
            {
                m_Radius = RopeParameters.Check(value, RopeParameters.Radius.Row);
                SyncStiffness();
                ApplySettings();
            }
        }

        /// <summary>Segment count, range <see cref="RopeParameters.SegmentCount"/>. A new value rebuilds the rope at the next step.</summary>
        public int SegmentCount
        {
            get => m_SegmentCount;
            set
            {
                m_SegmentCount = RopeParameters.Check(value, RopeParameters.SegmentCount.Row);
                if (_rope != null && _rope.SegmentCount != m_SegmentCount) _rebuildPending = true;
            }
        }

        /// <summary>Constraint solver: exact chain solve or Gauss–Seidel.</summary>
        public ConstraintSolverKind Solver
        {
            get => m_Solver;
            set { m_Solver = value; ApplySettings(); }
        }

        /// <summary>Substeps per physics step, range <see cref="RopeParameters.Substeps"/>.</summary>
        public int Substeps
        {
            get => m_Substeps;
            set { m_Substeps = RopeParameters.Check(value, RopeParameters.Substeps.Row); ApplySettings(); }
        }

        /// <summary>Iterations per substep, range <see cref="RopeParameters.Iterations"/>.</summary>
        public int Iterations
        {
            get => m_Iterations;
            set { m_Iterations = RopeParameters.Check(value, RopeParameters.Iterations.Row); ApplySettings(); }
        }

        /// <summary>Rope (pulls only) or rod (also pushes).</summary>
        public TensionModel TensionModel
        {
            get => m_TensionModel;
            set { m_TensionModel = value; ApplySettings(); }
        }

        /// <summary>Gravity on the rope (m/s²).</summary>
        public Vector3 Gravity
        {
            get => m_Gravity;
            set
            {
                RopeParameters.Check(value.x, RopeParameters.Gravity.Row);
                RopeParameters.Check(value.y, RopeParameters.Gravity.Row);
                RopeParameters.Check(value.z, RopeParameters.Gravity.Row);
                m_Gravity = value;
                ApplySettings();
            }
        }

        /// <summary>Neck onset radius r_min as a fraction of R, range <see cref="RopeParameters.NeckRadiusFraction"/>.</summary>
        public float NeckRadiusFraction
        {
            get => m_NeckRadiusFraction;
            set { m_NeckRadiusFraction = RopeParameters.Check(value, RopeParameters.NeckRadiusFraction.Row); ApplySettings(); }
        }

        /// <summary>Defect position as a fraction of the rest length from the start, range <see cref="RopeParameters.DefectPosition"/>.</summary>
        public float DefectPosition
        {
            get => m_DefectPosition;
            set { m_DefectPosition = RopeParameters.Check(value, RopeParameters.DefectPosition.Row); ApplySettings(); }
        }

        /// <summary>Break strain l/L − 1 (dimensionless), range <see cref="RopeParameters.BreakStrain"/>; used when <see cref="Fracture"/> is on.</summary>
        public float BreakStrain
        {
            get => m_BreakStrain;
            set { m_BreakStrain = RopeParameters.Check(value, RopeParameters.BreakStrain.Row); ApplySettings(); }
        }

        /// <summary>Neck model used when <see cref="Necking"/> is on (Zone or Paper).</summary>
        public NeckMode NeckMode
        {
            get => m_NeckMode;
            set
            {
                if (!RopeParameters.Contains(RopeParameters.NeckMode.Row, (int)value)) throw new ArgumentOutOfRangeException(nameof(NeckMode), value, "NeckMode must be Zone or Paper (turn necking off with Necking = false)");
                m_NeckMode = value;
                ApplySettings();
            }
        }

        /// <summary>Neck radius below which the rope breaks, as a fraction of R, range <see cref="RopeParameters.BreakRadiusFraction"/> (0 = off).</summary>
        public float BreakRadiusFraction
        {
            get => m_BreakRadiusFraction;
            set { m_BreakRadiusFraction = RopeParameters.Check(value, RopeParameters.BreakRadiusFraction.Row); ApplySettings(); }
        }

        /// <summary>The core radius model, or null when thinning, necking and fracture are all off. Use <c>Simulation.RadiusModel</c>.</summary>
        [Obsolete("Use Simulation.RadiusModel (the one way into the core); RadiusModelCore is removed in 0.2.")]
        public HookeRope.Radius.RadiusModel RadiusModelCore => _simulation?.RadiusModel;

        /// <summary>
        /// The core facade, or null before the first build (Awake in Play, or <see cref="Rebuild"/>): the one way into
        /// the core (solver rope, radius model, read-outs, mesh).
        /// </summary>
        public RopeSimulation Simulation => _simulation;

        /// <summary>Whether the radius thins with the Poisson ratio as the rope stretches (off: the radius stays R).</summary>
        public bool PoissonThinning { get => m_RadiusModel; set { m_RadiusModel = value; ApplyFeatureToggles(); } }

        /// <summary>Whether the radius follows the Poisson ratio. Use <see cref="PoissonThinning"/>.</summary>
        [Obsolete("Use PoissonThinning; RadiusModel (a bool named like the core type) is removed in 0.2.")]
        public bool RadiusModel { get => PoissonThinning; set => PoissonThinning = value; }

        /// <summary>Whether a neck forms at the defect below r_min.</summary>
        public bool Necking { get => m_Necking; set { m_Necking = value; ApplyFeatureToggles(); } }

        /// <summary>Whether the rope can break.</summary>
        public bool Fracture { get => m_Fracture; set { m_Fracture = value; ApplyFeatureToggles(); } }

        /// <summary>Start attachment. Changing what it points to takes effect at the next <see cref="Rebuild"/>.</summary>
        public RopeEnd StartAttachment => m_Start;

        /// <summary>End attachment. Changing what it points to takes effect at the next <see cref="Rebuild"/>.</summary>
        public RopeEnd EndAttachment => m_End;

        /// <summary>How the rope collides; takes effect at the next <see cref="Rebuild"/>.</summary>
        public RopeCollisionMode CollisionMode { get => m_CollisionMode; set { m_CollisionMode = value; _rebuildPending |= _rope != null; } }

        /// <summary>Colliders used in <see cref="RopeCollisionMode.ListedColliders"/> mode; takes effect at the next <see cref="Rebuild"/>.</summary>
        public Collider[] Colliders { get => m_Colliders; set { m_Colliders = value ?? Array.Empty<Collider>(); _rebuildPending |= _rope != null; } }

        /// <summary>Coulomb friction coefficient between rope and colliders (dimensionless), range <see cref="RopeParameters.Friction"/>; takes effect at the next <see cref="Rebuild"/>.</summary>
        public float Friction
        {
            get => m_Friction;
            set { m_Friction = RopeParameters.Check(value, RopeParameters.Friction.Row); _rebuildPending |= _rope != null; }
        }

        /// <summary>Compliance of the Transform attachments (m/N), range <see cref="RopeParameters.AttachmentCompliance"/>; takes effect at the next <see cref="Rebuild"/>.</summary>
        public float AttachmentCompliance
        {
            get => m_AttachmentCompliance;
            set { m_AttachmentCompliance = RopeParameters.Check(value, RopeParameters.AttachmentCompliance.Row); _rebuildPending |= _rope != null; }
        }

        /// <summary>Plane Transforms (up axis = normal); takes effect at the next <see cref="Rebuild"/>.</summary>
        public Transform[] Planes { get => m_Planes; set { m_Planes = value ?? Array.Empty<Transform>(); _rebuildPending |= _rope != null; } }

        // ---- Unity messages -------------------------------------------------------------------------------
        void Awake()
        {
            if (Application.isPlaying) Rebuild();
        }

        void FixedUpdate()
        {
            Simulate(Time.fixedDeltaTime);
        }

        void OnValidate()
        {
            Report(RopeParameters.Clamp(ref m_RestLength, RopeParameters.RestLength.Row));
            Report(RopeParameters.Clamp(ref m_Radius, RopeParameters.Radius.Row));
            Report(RopeParameters.Clamp(ref m_SegmentCount, RopeParameters.SegmentCount.Row));
            Report(RopeParameters.Clamp(ref m_YoungsModulus, RopeParameters.YoungsModulus.Row));
            Report(RopeParameters.Clamp(ref m_AxialStiffness, RopeParameters.AxialStiffness.Row));
            Report(RopeParameters.Clamp(ref m_Density, RopeParameters.Density.Row));
            Report(RopeParameters.Clamp(ref m_PoissonRatio, RopeParameters.PoissonRatio.Row));
            Report(RopeParameters.Clamp(ref m_Damping, RopeParameters.Damping.Row));
            Report(RopeParameters.Clamp(ref m_Substeps, RopeParameters.Substeps.Row));
            Report(RopeParameters.Clamp(ref m_Iterations, RopeParameters.Iterations.Row));
            Report(RopeParameters.Clamp(ref m_Friction, RopeParameters.Friction.Row));
            Report(RopeParameters.Clamp(ref m_AttachmentCompliance, RopeParameters.AttachmentCompliance.Row));
            Report(RopeParameters.Clamp(ref m_NeckRadiusFraction, RopeParameters.NeckRadiusFraction.Row));
            Report(RopeParameters.Clamp(ref m_DefectPosition, RopeParameters.DefectPosition.Row));
            Report(RopeParameters.Clamp(ref m_BreakStrain, RopeParameters.BreakStrain.Row));
            Report(RopeParameters.Clamp(ref m_BreakRadiusFraction, RopeParameters.BreakRadiusFraction.Row));
            if (!RopeParameters.Contains(RopeParameters.NeckMode.Row, (int)m_NeckMode))
            {
                m_NeckMode = RopeParameters.NeckMode.Default;
                Report("Neck mode must be Zone or Paper; set to Zone (use the Necking toggle to turn necking off).");
            }
            if (!m_Gravity.ToFloat3().IsFinite)
            {
                m_Gravity = new Vector3(RopeParameters.Gravity.DefaultX, RopeParameters.Gravity.DefaultY, RopeParameters.Gravity.DefaultZ);
                Report("Gravity was not finite; reset to (0, -9.81, 0) m/s².");
            }
            Report(RopeParameters.Clamp(ref m_Gravity.x, RopeParameters.Gravity.Row));
            Report(RopeParameters.Clamp(ref m_Gravity.y, RopeParameters.Gravity.Row));
            Report(RopeParameters.Clamp(ref m_Gravity.z, RopeParameters.Gravity.Row));
            SyncStiffness();
            if (m_Colliders == null) m_Colliders = Array.Empty<Collider>();
            if (m_Planes == null) m_Planes = Array.Empty<Transform>();
            if (_rope == null) return;
            if (_rope.SegmentCount != m_SegmentCount || (_simulation.RadiusSettings != null) != RadiusFeaturesOn) _rebuildPending = true;
            else ApplySettings();
        }

        // ---- Public API -----------------------------------------------------------------------------------
        /// <summary>
        /// (Re)creates the core rope from the current settings: particles evenly from the start attachment to
        /// the end attachment (or straight down from this object by the rest length), pins, loads and colliders.
        /// Called in Awake during Play; call it yourself in edit-mode code and tests.
        /// </summary>
        public void Rebuild()
        {
            _settings = new RopeSettings();
            WriteRadiusSettings(_radiusSettings);
            _simulation = BuildSimulation(_settings, _attachments, RadiusFeaturesOn ? _radiusSettings : null, out _origin);
            _rope = _simulation.Rope;
            _colliderBinding.Bind(_rope, m_CollisionMode, m_Colliders, m_CollisionLayers, m_Planes, m_Friction, _origin, m_Start, m_End, Reach, this);
            _simulation.Readouts.ArrestLoad = _attachments.EndLoad;

            _breakRaised = false;
            _rebuildPending = false;
        }

        /// <summary>
        /// Advances the rope by <paramref name="deltaTime"/> seconds: copies attachment and collider poses in,
        /// steps the solver (substeps inside), applies the rope's forces to attached Rigidbodies and updates
        /// the read-outs. FixedUpdate calls it with Time.fixedDeltaTime; call it yourself in edit-mode code.
        /// </summary>
        public void Simulate(float deltaTime)
        {
            if (!(deltaTime > 0f) || float.IsInfinity(deltaTime))
                throw new ArgumentOutOfRangeException(nameof(deltaTime), deltaTime, "deltaTime must be in (0, +inf) seconds");
            if (_rope == null || _rebuildPending) Rebuild();

            _attachments.CopyIn(_rope, _origin);
            _colliderBinding.BeforeStep(_rope, _origin, Reach);

            _stopwatch.Restart();
            _simulation.Step(deltaTime);
            _stopwatch.Stop();
            StepMilliseconds = (float)_stopwatch.Elapsed.TotalMilliseconds;

            _attachments.ApplyForces(_rope);

            var firstBreak = _simulation.Readouts.FirstBreak;
            if (!_breakRaised && firstBreak.HasValue)
            {
                _breakRaised = true;
                m_OnBreak?.Invoke(_origin + firstBreak.Value.Position.ToVector3(), firstBreak.Value.Tension);
            }
        }

        /// <summary>Clears <see cref="PeakTension"/> and <see cref="PeakArrestForce"/>.</summary>
        public void ResetPeaks() => Readouts?.ResetPeaks();

        /// <summary>
        /// Writes the particle positions interpolated between the last two steps into <paramref name="destination"/>
        /// as x, y, z triples in world space (m). <paramref name="alpha"/> is 0 at the previous step and 1 at the latest.
        /// Returns the particle count written (0 before the build). Allocation-free.
        /// </summary>
        public int GetInterpolatedPositions(float alpha, float[] destination)
        {
            if (_rope == null) return 0;
            int particles = _rope.ParticleCount;
            if (destination == null || destination.Length < particles * 3)
                throw new ArgumentException("destination must hold 3 × ParticleCount floats", nameof(destination));
            for (int i = 0, j = 0; i < particles; i++, j += 3)
            {
                Vector3 p = _origin + _rope.GetInterpolatedPosition(i, alpha).ToVector3();
                destination[j] = p.x;
                destination[j + 1] = p.y;
                destination[j + 2] = p.z;
            }
            return particles;
        }

        /// <summary>World position (m) of the origin of the core rope's frame: world = origin + <see cref="Rope.GetPosition"/>.</summary>
        internal Vector3 SimulationOrigin => _origin;

        /// <summary>World position of particle <paramref name="particle"/> after the last step (m).</summary>
        public Vector3 GetParticlePosition(int particle)
        {
            if (_rope == null) throw new InvalidOperationException("The rope is not built yet; call Rebuild() or enter Play.");
            return _origin + _rope.GetPosition(particle).ToVector3();
        }

        /// <summary>Tension of segment <paramref name="segment"/> after the last step (N, ≥ 0 = pulling).</summary>
        public float GetSegmentTension(int segment)
        {
            if (_rope == null) throw new InvalidOperationException("The rope is not built yet; call Rebuild() or enter Play.");
            return _rope.Tensions[segment];
        }

        /// <summary>Radius of particle <paramref name="particle"/> (m): the Poisson/neck radius when the radius model is on, else R.</summary>
        public float GetParticleRadius(int particle)
        {
            if (_rope == null) return m_Radius;
            return _rope.ParticleRadius[particle];
        }

        /// <summary>True when segment <paramref name="segment"/> has broken.</summary>
        public bool IsSegmentBroken(int segment) => _rope != null && _rope.IsSegmentBroken(segment);

        // ---- Internals ------------------------------------------------------------------------------------
        static float Area(float radius) => MathF.PI * radius * radius;

        void Report(string message)
        {
            if (message != null) Debug.LogWarning("ElasticRope '" + name + "': " + message, this);
        }

        void SyncStiffness()
        {
            if (m_StiffnessInput == RopeStiffnessInput.YoungsModulus) m_AxialStiffness = m_YoungsModulus * Area(m_Radius);
            else m_YoungsModulus = m_AxialStiffness / Area(m_Radius);
        }

        /// <summary>Writes every live setting (all but the segment count) into a core settings object.</summary>
        void WriteSettings(RopeSettings settings)
        {
            settings.RestLength = m_RestLength;
            settings.Radius = m_Radius;
            if (m_StiffnessInput == RopeStiffnessInput.AxialStiffness) settings.AxialStiffness = m_AxialStiffness;
            else settings.YoungsModulus = m_YoungsModulus;
            settings.Density = m_Density;
            settings.Damping = m_Damping;
            settings.Gravity = m_Gravity.ToFloat3();
            settings.Substeps = m_Substeps;
            settings.Iterations = m_Iterations;
            settings.Solver = m_Solver;
            settings.Tension = m_TensionModel;
        }

        /// <summary>True when any radius-model feature (thinning, necking, fracture) is on; all off costs nothing per step.</summary>
        bool RadiusFeaturesOn => m_RadiusModel || m_Necking || m_Fracture;

        /// <summary>Writes the thinning, necking and break settings into the core radius settings.</summary>
        void WriteRadiusSettings(RadiusSettings settings)
        {
            settings.PoissonThinning = m_RadiusModel;
            settings.PoissonRatio = m_PoissonRatio;
            settings.NeckMode = m_NeckMode;
            settings.Necking = m_Necking;
            settings.NeckRadiusFraction = m_NeckRadiusFraction;
            settings.DefectPosition = m_DefectPosition;
            settings.Fracture = m_Fracture;
            settings.BreakStrain = m_BreakStrain;
            settings.BreakRadiusFraction = m_BreakRadiusFraction;
        }

        void ApplySettings()
        {
            if (_settings != null) WriteSettings(_settings);
            if (_rope != null) WriteRadiusSettings(_radiusSettings);
        }

        void ApplyFeatureToggles()
        {
            if (_rope != null && (_simulation.RadiusSettings != null) != RadiusFeaturesOn) _rebuildPending = true;
            ApplySettings();
        }

        /// <summary>
        /// Writes every live setting and the segment count into <paramref name="settings"/> and builds a core
        /// simulation from them: particles evenly from the start attachment to the end attachment (or straight down
        /// from this object by the rest length), the ends attached through <paramref name="attachments"/>, and a
        /// radius model when <paramref name="radiusSettings"/> is not null. <paramref name="origin"/> is the start in
        /// world space (m): the origin of the rope's frame.
        /// </summary>
        RopeSimulation BuildSimulation(RopeSettings settings, RopeAttachmentBinding attachments, RadiusSettings radiusSettings, out Vector3 origin)
        {
            WriteSettings(settings);
            settings.SegmentCount = m_SegmentCount;
            Vector3 start = m_Start.WorldPosition(transform.position);
            Vector3 end = m_End.WorldPosition(new Vector3(start.x, start.y - m_RestLength, start.z));
            origin = start;
            var rope = new Rope(settings, (start - origin).ToFloat3(), (end - origin).ToFloat3());
            attachments.Attach(rope, m_Start, m_End, origin, m_AttachmentCompliance);
            return new RopeSimulation(rope, radiusSettings);
        }

        /// <summary>
        /// A simulation of the current settings and attachment poses that this component does not own or step
        /// (no radius model, no colliders): the editor's static-sag preview relaxes it. <paramref name="origin"/> is
        /// the world position (m) of its frame's origin.
        /// </summary>
        internal RopeSimulation CreateDetachedSimulation(out Vector3 origin) =>
            BuildSimulation(new RopeSettings(), new RopeAttachmentBinding(), radiusSettings: null, out origin);

        /// <summary>How far the Layer Mask collider query reaches: the rest length stretched to the break strain (or doubled), plus R.</summary>
        ColliderReach Reach => new ColliderReach(m_RestLength * (1f + (m_Fracture ? m_BreakStrain : 1f)), m_Radius);
    }
}
