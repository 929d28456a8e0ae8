using System;
using HookeRope.Radius;
using HookeRope.Solver;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// The settings of <see cref="ElasticRope"/>: the serialized fields (ranges, defaults and tooltips from the
    /// parameter table <see cref="RopeParameters"/>), their validated properties, OnValidate's clamp and the copy
    /// into the core settings. Field names are those of 0.1.0 (the prefab and user scenes store them).
    /// </summary>
    public sealed partial class ElasticRope
    {
        // ---- Material -------------------------------------------------------------------------------------
        [SerializeField, Tooltip(RopeParameters.StiffnessInput.Tooltip)]
        RopeStiffnessInput m_StiffnessInput = (RopeStiffnessInput)RopeParameters.StiffnessInput.Default;

        [SerializeField, Min(RopeParameters.YoungsModulus.Min), Tooltip(RopeParameters.YoungsModulus.Tooltip)]
        float m_YoungsModulus = RopeParameters.YoungsModulus.Default;

        [SerializeField, Min(RopeParameters.AxialStiffness.Min), Tooltip(RopeParameters.AxialStiffness.Tooltip)]
        float m_AxialStiffness = RopeParameters.AxialStiffness.Default;

        [SerializeField, Min(RopeParameters.Density.Min), Tooltip(RopeParameters.Density.Tooltip)]
        float m_Density = RopeParameters.Density.Default;

        [SerializeField, Range(RopeParameters.PoissonRatio.Min, RopeParameters.PoissonRatio.Max), Tooltip(RopeParameters.PoissonRatio.Tooltip)]
        float m_PoissonRatio = RopeParameters.PoissonRatio.Default;

        [SerializeField, Min(RopeParameters.Damping.Min), Tooltip(RopeParameters.Damping.Tooltip)]
        float m_Damping = RopeParameters.Damping.Default;

        // ---- Geometry -------------------------------------------------------------------------------------
        [SerializeField, Min(RopeParameters.RestLength.Min), Tooltip(RopeParameters.RestLength.Tooltip)]
        float m_RestLength = RopeParameters.RestLength.Default;

        [SerializeField, Min(RopeParameters.Radius.Min), Tooltip(RopeParameters.Radius.Tooltip)]
        float m_Radius = RopeParameters.Radius.Default;

        [SerializeField, Min(RopeParameters.SegmentCount.Min), Tooltip(RopeParameters.SegmentCount.Tooltip)]
        int m_SegmentCount = RopeParameters.SegmentCount.Default;

        // ---- Solver ---------------------------------------------------------------------------------------
        [SerializeField, Tooltip(RopeParameters.Solver.Tooltip)]
        ConstraintSolverKind m_Solver = RopeParameters.Solver.Default;

        [SerializeField, Min(RopeParameters.Substeps.Min), Tooltip(RopeParameters.Substeps.Tooltip)]
        int m_Substeps = RopeParameters.Substeps.Default;

        [SerializeField, Min(RopeParameters.Iterations.Min), Tooltip(RopeParameters.Iterations.Tooltip)]
        int m_Iterations = RopeParameters.Iterations.Default;

        [SerializeField, Tooltip(RopeParameters.TensionModel.Tooltip)]
        TensionModel m_TensionModel = RopeParameters.TensionModel.Default;

        [SerializeField, Tooltip(RopeParameters.Integrator.Tooltip)]
        TimeIntegrator m_Integrator = RopeParameters.Integrator.Default;

        [SerializeField, Tooltip(RopeParameters.GaussSeidelKernel.Tooltip)]
        GaussSeidelKernel m_GaussSeidelKernel = RopeParameters.GaussSeidelKernel.Default;

        [SerializeField, Min(RopeParameters.Gravity.Min), Tooltip(RopeParameters.Gravity.Tooltip)]
        Vector3 m_Gravity = new Vector3(RopeParameters.Gravity.DefaultX, RopeParameters.Gravity.DefaultY, RopeParameters.Gravity.DefaultZ);

        // ---- Attachments ----------------------------------------------------------------------------------
        [SerializeField, Tooltip("Start of the rope (first particle): a Transform to follow, a Rigidbody to pull two-way, or nothing.")]
        RopeEnd m_Start = new RopeEnd();

        [SerializeField, Tooltip("End of the rope (last particle): a Transform to follow, a Rigidbody to pull two-way (e.g. a harness D-ring), or nothing.")]
        RopeEnd m_End = new RopeEnd();

        [SerializeField, Min(RopeParameters.AttachmentCompliance.Min), Tooltip(RopeParameters.AttachmentCompliance.Tooltip)]
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

        [SerializeField, Min(RopeParameters.Friction.Min), Tooltip(RopeParameters.Friction.Tooltip)]
        float m_Friction = RopeParameters.Friction.Default;

        // ---- Drag -----------------------------------------------------------------------------------------
        [SerializeField, Min(RopeParameters.ViscousDrag.Min), Tooltip(RopeParameters.ViscousDrag.Tooltip)]
        float m_ViscousDrag = RopeParameters.ViscousDrag.Default;

        [SerializeField, Min(RopeParameters.DragCoefficient.Min), Tooltip(RopeParameters.DragCoefficient.Tooltip)]
        float m_DragCoefficient = RopeParameters.DragCoefficient.Default;

        [SerializeField, Min(RopeParameters.SkinFriction.Min), Tooltip(RopeParameters.SkinFriction.Tooltip)]
        float m_SkinFriction = RopeParameters.SkinFriction.Default;

        [SerializeField, Min(RopeParameters.AirDensity.Min), Tooltip(RopeParameters.AirDensity.Tooltip)]
        float m_AirDensity = RopeParameters.AirDensity.Default;

        [SerializeField, Min(RopeParameters.Wind.Min), Tooltip(RopeParameters.Wind.Tooltip)]
        Vector3 m_Wind = new Vector3(RopeParameters.Wind.DefaultX, RopeParameters.Wind.DefaultY, RopeParameters.Wind.DefaultZ);

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

        [SerializeField, Min(RopeParameters.BreakStrain.Min), Tooltip(RopeParameters.BreakStrain.Tooltip)]
        float m_BreakStrain = RopeParameters.BreakStrain.Default;

        [SerializeField, Range(RopeParameters.BreakRadiusFraction.Min, RopeParameters.BreakRadiusFraction.Max), Tooltip(RopeParameters.BreakRadiusFraction.Tooltip)]
        float m_BreakRadiusFraction = RopeParameters.BreakRadiusFraction.Default;

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
        public float Density { get => m_Density; set => SetLive(ref m_Density, value, RopeParameters.Density.Row); }

        /// <summary>Rope mass per metre ρ·πR² (kg/m).</summary>
        public float LinearDensity => m_Density * Area(m_Radius);

        /// <summary>Poisson ratio ν (dimensionless), range <see cref="RopeParameters.PoissonRatio"/>.</summary>
        public float PoissonRatio { get => m_PoissonRatio; set => SetLive(ref m_PoissonRatio, value, RopeParameters.PoissonRatio.Row); }

        /// <summary>XPBD damping coefficient β (s), range <see cref="RopeParameters.Damping"/>.</summary>
        public float Damping { get => m_Damping; set => SetLive(ref m_Damping, value, RopeParameters.Damping.Row); }

        /// <summary>Rest length L (m), range <see cref="RopeParameters.RestLength"/>.</summary>
        public float RestLength { get => m_RestLength; set => SetLive(ref m_RestLength, value, RopeParameters.RestLength.Row); }

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
            }
        }

        /// <summary>Constraint solver: exact chain solve or Gauss–Seidel.</summary>
        public ConstraintSolverKind Solver
        {
            get => m_Solver;
            set { m_Solver = value; ApplySettings(); }
        }

        /// <summary>Substeps per physics step, range <see cref="RopeParameters.Substeps"/>.</summary>
        public int Substeps { get => m_Substeps; set => SetLive(ref m_Substeps, value, RopeParameters.Substeps.Row); }

        /// <summary>Iterations per substep, range <see cref="RopeParameters.Iterations"/>.</summary>
        public int Iterations { get => m_Iterations; set => SetLive(ref m_Iterations, value, RopeParameters.Iterations.Row); }

        /// <summary>Rope (pulls only) or rod (also pushes).</summary>
        public TensionModel TensionModel
        {
            get => m_TensionModel;
            set { m_TensionModel = value; ApplySettings(); }
        }

        /// <summary>Time integrator of each substep: backward Euler (most robust, dissipative) or BDF2 (second order, low dissipation).</summary>
        public TimeIntegrator Integrator
        {
            get => m_Integrator;
            set { m_Integrator = value; ApplySettings(); }
        }

        /// <summary>
        /// The Gauss–Seidel kernel (Gauss–Seidel solver only; <see cref="RopeParameters.GaussSeidelKernel"/>): Precise
        /// (default) or the opt-in Fused Single, one single-precision pass per substep for a backward-Euler rope without
        /// colliders, drag, compliant pins or plastic material (any other rope runs Precise).
        /// </summary>
        public GaussSeidelKernel GaussSeidelKernel
        {
            get => m_GaussSeidelKernel;
            set { m_GaussSeidelKernel = value; ApplySettings(); }
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

        /// <summary>Viscous drag c per metre of rope (N·s/m²), range <see cref="RopeParameters.ViscousDrag"/>; 0 = off. A swing decays as exp(−c·t/(2μ)).</summary>
        public float ViscousDrag { get => m_ViscousDrag; set => SetLive(ref m_ViscousDrag, value, RopeParameters.ViscousDrag.Row); }

        /// <summary>Drag coefficient C_d of the air drag across the rope (dimensionless), range <see cref="RopeParameters.DragCoefficient"/>; 0 = off.</summary>
        public float DragCoefficient { get => m_DragCoefficient; set => SetLive(ref m_DragCoefficient, value, RopeParameters.DragCoefficient.Row); }

        /// <summary>Skin-friction coefficient C_f of the air drag along the rope (dimensionless), range <see cref="RopeParameters.SkinFriction"/>; 0 = off.</summary>
        public float SkinFriction { get => m_SkinFriction; set => SetLive(ref m_SkinFriction, value, RopeParameters.SkinFriction.Row); }

        /// <summary>Density of the air (or fluid) the rope moves through (kg/m³), range <see cref="RopeParameters.AirDensity"/>.</summary>
        public float AirDensity { get => m_AirDensity; set => SetLive(ref m_AirDensity, value, RopeParameters.AirDensity.Row); }

        /// <summary>
        /// Velocity of the air in world coordinates (m/s), each component in the range of <see cref="RopeParameters.Wind"/>. The core
        /// rope's frame is the world shifted to the start point (never rotated), so the velocity goes in unchanged, as gravity does.
        /// </summary>
        public Vector3 Wind
        {
            get => m_Wind;
            set
            {
                RopeParameters.Check(value.x, RopeParameters.Wind.Row);
                RopeParameters.Check(value.y, RopeParameters.Wind.Row);
                RopeParameters.Check(value.z, RopeParameters.Wind.Row);
                m_Wind = value;
                ApplySettings();
            }
        }

        /// <summary>Neck onset radius r_min as a fraction of R, range <see cref="RopeParameters.NeckRadiusFraction"/>.</summary>
        public float NeckRadiusFraction { get => m_NeckRadiusFraction; set => SetLive(ref m_NeckRadiusFraction, value, RopeParameters.NeckRadiusFraction.Row); }

        /// <summary>Defect position as a fraction of the rest length from the start, range <see cref="RopeParameters.DefectPosition"/>.</summary>
        public float DefectPosition { get => m_DefectPosition; set => SetLive(ref m_DefectPosition, value, RopeParameters.DefectPosition.Row); }

        /// <summary>Break strain l/L − 1 (dimensionless), range <see cref="RopeParameters.BreakStrain"/>; used when <see cref="Fracture"/> is on.</summary>
        public float BreakStrain { get => m_BreakStrain; set => SetLive(ref m_BreakStrain, value, RopeParameters.BreakStrain.Row); }

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
        public float BreakRadiusFraction { get => m_BreakRadiusFraction; set => SetLive(ref m_BreakRadiusFraction, value, RopeParameters.BreakRadiusFraction.Row); }

        /// <summary>The core radius model, or null when thinning, necking and fracture are all off. Use <c>Simulation.RadiusModel</c>.</summary>
        [Obsolete("Use Simulation.RadiusModel (the one way into the core); RadiusModelCore is removed in 0.2.")]
        public HookeRope.Radius.RadiusModel RadiusModelCore => _simulation?.RadiusModel;

        /// <summary>
        /// The core facade, or null before the first build (Awake in Play, or <see cref="Rebuild"/>): the one way into
        /// the core (solver rope, radius model, read-outs, mesh).
        /// </summary>
        public RopeSimulation Simulation => _simulation;

        /// <summary>Whether the radius thins with the Poisson ratio as the rope stretches (off: the radius stays R).</summary>
        public bool PoissonThinning { get => m_RadiusModel; set { m_RadiusModel = value; ApplySettings(); } }

        /// <summary>Whether the radius follows the Poisson ratio. Use <see cref="PoissonThinning"/>.</summary>
        [Obsolete("Use PoissonThinning; RadiusModel (a bool named like the core type) is removed in 0.2.")]
        public bool RadiusModel { get => PoissonThinning; set => PoissonThinning = value; }

        /// <summary>Whether a neck forms at the defect below r_min.</summary>
        public bool Necking { get => m_Necking; set { m_Necking = value; ApplySettings(); } }

        /// <summary>Whether the rope can break.</summary>
        public bool Fracture { get => m_Fracture; set { m_Fracture = value; ApplySettings(); } }

        /// <summary>Start attachment. Setting its Point or Body (from code or the inspector) rebuilds the rope at the next step.</summary>
        public RopeEnd StartAttachment => m_Start;

        /// <summary>End attachment. Setting its Point or Body (from code or the inspector) rebuilds the rope at the next step.</summary>
        public RopeEnd EndAttachment => m_End;

        /// <summary>How the rope collides; rebuilds the rope at the next step.</summary>
        public RopeCollisionMode CollisionMode { get => m_CollisionMode; set => m_CollisionMode = value; }

        /// <summary>Colliders used in <see cref="RopeCollisionMode.ListedColliders"/> mode; rebuilds the rope at the next step.</summary>
        public Collider[] Colliders { get => m_Colliders; set => m_Colliders = value ?? Array.Empty<Collider>(); }

        /// <summary>Coulomb friction coefficient between rope and colliders (dimensionless), range <see cref="RopeParameters.Friction"/>; rebuilds the rope at the next step.</summary>
        public float Friction { get => m_Friction; set => m_Friction = RopeParameters.Check(value, RopeParameters.Friction.Row); }

        /// <summary>Compliance of the Transform attachments (m/N), range <see cref="RopeParameters.AttachmentCompliance"/>; rebuilds the rope at the next step.</summary>
        public float AttachmentCompliance { get => m_AttachmentCompliance; set => m_AttachmentCompliance = RopeParameters.Check(value, RopeParameters.AttachmentCompliance.Row); }

        /// <summary>Plane Transforms (up axis = normal); rebuilds the rope at the next step.</summary>
        public Transform[] Planes { get => m_Planes; set => m_Planes = value ?? Array.Empty<Transform>(); }

        // ---- Validation and the copy into the core --------------------------------------------------------
        void OnValidate()
        {
            ClampSerializedFields();
            if (_rope != null) ApplySettings();   // what cannot change in place is rebuilt by the next step (TopologyChanged)
        }

        /// <summary>
        /// Clamps every serialized setting into its table range and logs one warning per changed field naming this
        /// object, the field, the range and the value kept (OnValidate, and every build: a scene saved out of range
        /// reaches players, where OnValidate never runs). Allocation-free when every value is in range.
        /// </summary>
        void ClampSerializedFields()
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
            Report(RopeParameters.Clamp(ref m_ViscousDrag, RopeParameters.ViscousDrag.Row));
            Report(RopeParameters.Clamp(ref m_DragCoefficient, RopeParameters.DragCoefficient.Row));
            Report(RopeParameters.Clamp(ref m_SkinFriction, RopeParameters.SkinFriction.Row));
            Report(RopeParameters.Clamp(ref m_AirDensity, RopeParameters.AirDensity.Row));
            Report(RopeParameters.Clamp(ref m_NeckRadiusFraction, RopeParameters.NeckRadiusFraction.Row));
            Report(RopeParameters.Clamp(ref m_DefectPosition, RopeParameters.DefectPosition.Row));
            Report(RopeParameters.Clamp(ref m_BreakStrain, RopeParameters.BreakStrain.Row));
            Report(RopeParameters.Clamp(ref m_BreakRadiusFraction, RopeParameters.BreakRadiusFraction.Row));
            ClampMaterialFields();   // the material law (ElasticRope.Material.cs)
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
            if (!m_Wind.ToFloat3().IsFinite)
            {
                m_Wind = new Vector3(RopeParameters.Wind.DefaultX, RopeParameters.Wind.DefaultY, RopeParameters.Wind.DefaultZ);
                Report("Wind was not finite; reset to (0, 0, 0) m/s.");
            }
            Report(RopeParameters.Clamp(ref m_Wind.x, RopeParameters.Wind.Row));
            Report(RopeParameters.Clamp(ref m_Wind.y, RopeParameters.Wind.Row));
            Report(RopeParameters.Clamp(ref m_Wind.z, RopeParameters.Wind.Row));
            SyncStiffness();
            if (m_Colliders == null) m_Colliders = Array.Empty<Collider>();
            if (m_Planes == null) m_Planes = Array.Empty<Transform>();
        }

        static float Area(float radius) => MathF.PI * radius * radius;

        void Report(string message)
        {
            if (message != null) Debug.LogWarning("ElasticRope '" + name + "': " + message, this);
        }

        /// <summary>Checks <paramref name="value"/> against <paramref name="row"/>, stores it and applies it at the next step.</summary>
        void SetLive(ref float field, float value, ParameterInfo row) { field = RopeParameters.Check(value, row); ApplySettings(); }

        /// <summary>Integer variant of <see cref="SetLive(ref float, float, ParameterInfo)"/>.</summary>
        void SetLive(ref int field, int value, ParameterInfo row) { field = RopeParameters.Check(value, row); ApplySettings(); }


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
            settings.Integrator = m_Integrator;
            settings.GaussSeidelKernel = m_GaussSeidelKernel;
            settings.ViscousDrag = m_ViscousDrag;
            settings.DragCoefficient = m_DragCoefficient;
            settings.SkinFriction = m_SkinFriction;
            settings.AirDensity = m_AirDensity;
            settings.Wind = m_Wind.ToFloat3();   // world = rope frame up to a shift: a velocity is the same in both
            WriteMaterialSettings(settings);   // the material law (ElasticRope.Material.cs)
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


        /// <summary>How far the Layer Mask collider query reaches: the rest length stretched to the break strain (or doubled) and the material's reach (ultimate strain, absorber), plus R.</summary>
        ColliderReach Reach => new ColliderReach(m_RestLength * (1f + (m_Fracture ? m_BreakStrain : 1f)) + MaterialReach, m_Radius);
    }
}
