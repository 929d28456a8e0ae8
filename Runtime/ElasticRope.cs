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
    /// An elastic rope with real physics in SI units: thin glue over the engine-free core. It builds the core
    /// simulation from its settings (ElasticRope.Settings.cs: the serialized fields with ranges, defaults and
    /// tooltips from <see cref="RopeParameters"/>), copies anchor, hand and collider poses in every FixedUpdate
    /// (<see cref="RopeAttachmentBinding"/>, <see cref="RopeColliderBinding"/>), steps it (substeps inside),
    /// exchanges forces with attached Rigidbodies (two-way) and forwards the core's read-outs
    /// (<see cref="RopeSimulation.Readouts"/>). Rendering lives in <see cref="RopeMeshRenderer"/>. Every
    /// serialized field changed in Play (inspector or code) applies at the next step: in place where the core allows,
    /// else by a rebuild at that step (Documentation~/index.md, "Live edits").
    /// </summary>
    [AddComponentMenu("HookeRope/Elastic Rope")]
    [DefaultExecutionOrder(-100)] // steps before default-order scripts (samples) that read it
    [HelpURL(DocumentationUrl)]
    [DisallowMultipleComponent]
    public sealed partial class ElasticRope : MonoBehaviour
    {
        /// <summary>The package manual.</summary>
        public const string DocumentationUrl = "https://github.com/hookerope/com.hookerope.elastic-rope/blob/main/Documentation~/index.md";

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
        RopeInputGuard _guard;
        Vector3 _origin;
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
        public bool MeetsEn355 => Readouts?.MeetsEn355 ?? true;

        /// <summary>True while <see cref="PeakArrestForce"/> is within ANSI Z359.13's 8 kN.</summary>
        public bool MeetsAnsiZ359_13 => Readouts?.MeetsAnsiZ359_13 ?? true;

        /// <summary>Constraint residual of the last step: largest strain error against the compliance-consistent target (dimensionless).</summary>
        public float Residual => Readouts?.Residual ?? 0f;

        /// <summary>Wall-clock time of the last solver step (ms), for trading substeps/iterations against accuracy.</summary>
        public float StepMilliseconds { get; private set; }

        RopeReadouts Readouts => _simulation?.Readouts;

        /// <summary>Particles in the built rope (segments + 1), or 0 before the build.</summary>
        public int ParticleCount => _rope?.ParticleCount ?? 0;

        // ---- Unity messages -------------------------------------------------------------------------------
        void Awake()
        {
            if (!Application.isPlaying) return;
            WireOnDrop();
            Rebuild();
        }

        // With two or more ropes enabled in Play, the first rope to run in a physics step steps all of them on the
        // shared world (RopeWorldScheduler); one rope alone steps inline, here. The key names the physics step.
        void FixedUpdate()
        {
            if (Physics.simulationMode == SimulationMode.FixedUpdate) RopeWorldScheduler.OnPhysicsStep(this, Time.fixedDeltaTime, Time.fixedTimeAsDouble);
        }

        void Update()
        {
            if (Physics.simulationMode == SimulationMode.Update && Time.deltaTime > 0f) RopeWorldScheduler.OnPhysicsStep(this, Time.deltaTime, -1.0 - Time.frameCount);
        }

        // ---- Public API -----------------------------------------------------------------------------------
        /// <summary>
        /// (Re)creates the core rope from the current settings: particles evenly from the start attachment to
        /// the end attachment (or straight down from this object by the rest length), pins, loads and colliders.
        /// Called in Awake during Play; call it yourself in edit-mode code and tests.
        /// </summary>
        public void Rebuild()
        {
            ClampSerializedFields();   // a scene or prefab saved out of range (OnValidate does not run in players)
            _settings = new RopeSettings();
            WriteRadiusSettings(_radiusSettings);
            _simulation = BuildSimulation(_settings, _attachments, RadiusFeaturesOn ? _radiusSettings : null, out _origin);
            _rope = _simulation.Rope;
            _colliderBinding.Bind(_rope, m_CollisionMode, m_Colliders, m_CollisionLayers, m_Planes, m_Friction, _origin, m_Start, m_End, Reach, this);
            _simulation.Readouts.ArrestLoad = _attachments.EndLoad;

            RecordBuiltTopology();
            Guard.RecordAttachments(m_Start, m_End);
            _breakRaised = false;
            RopeWorldScheduler.Built(this);
        }

        /// <summary>
        /// Advances the rope by <paramref name="deltaTime"/> seconds: copies attachment and collider poses in,
        /// steps the core simulation (substeps inside; it updates the read-outs), applies the rope's forces to attached
        /// Rigidbodies, records where rigs without a Rigidbody must move, raises <see cref="OnBreak"/> on the first break
        /// and <see cref="OnStepped"/> after every step. FixedUpdate calls it with Time.fixedDeltaTime when Physics.simulationMode
        /// is FixedUpdate, Update with Time.deltaTime in Update mode (with two or more ropes enabled, the shared world does
        /// the same for all of them at once: <see cref="ElasticRopeWorld"/>); in Script mode and edit-mode code call it yourself.
        /// </summary>
        public void Simulate(float deltaTime)
        {
            if (!(deltaTime > 0f) || float.IsInfinity(deltaTime))
                throw new ArgumentOutOfRangeException(nameof(deltaTime), deltaTime, "deltaTime must be in (0, +inf) seconds");
            BeginStep(deltaTime);
            _stopwatch.Restart();
            _simulation.Step(deltaTime);
            _stopwatch.Stop();
            EndStep(deltaTime, _stopwatch.Elapsed.TotalMilliseconds);
        }

        /// <summary>The main-thread half before the core step (copy-in): rebuild if needed, attachment and collider poses.</summary>
        internal void BeginStep(float deltaTime)
        {
            if (_rope == null || TopologyChanged()) Rebuild();
            if (_attachments.CopyIn(_rope, _origin, deltaTime)) _simulation.Readouts.ArrestLoad = _attachments.EndLoad;
            _colliderBinding.BeforeStep(_rope, _origin, Reach);
        }

        /// <summary>
        /// The main-thread half after the core step of <paramref name="deltaTime"/> s that took
        /// <paramref name="stepMilliseconds"/> ms (copy-out): forces to the bodies, rig displacements, the break and
        /// stepped events.
        /// </summary>
        internal void EndStep(float deltaTime, double stepMilliseconds)
        {
            StepMilliseconds = (float)stepMilliseconds;
            Guard.WatchStepCost(StepMilliseconds, deltaTime, m_SegmentCount, m_Substeps, m_Iterations);

            _attachments.ApplyForces(_rope);

            var firstBreak = _simulation.Readouts.FirstBreak;
            if (!_breakRaised && firstBreak.HasValue)
            {
                _breakRaised = true;
                m_OnBreak?.Invoke(_origin + firstBreak.Value.Position.ToVector3(), firstBreak.Value.Tension);
            }
            m_OnStepped?.Invoke(_attachments.StartForce, _attachments.EndForce);
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
            // a non-finite attachment pose is reported and replaced: the start by this object, the end by the hanging fallback
            Vector3 start = m_Start.WorldPosition(transform.position);
            if (!Guard.AcceptPose(RopeInputGuard.Start, m_Start, start)) start = transform.position;
            Vector3 hanging = new Vector3(start.x, start.y - m_RestLength, start.z);
            Vector3 end = m_End.WorldPosition(hanging);
            if (!Guard.AcceptPose(RopeInputGuard.End, m_End, end)) end = hanging;
            origin = start;
            var rope = new Rope(settings, (start - origin).ToFloat3(), (end - origin).ToFloat3());
            attachments.Attach(rope, m_Start, m_End, origin, m_AttachmentCompliance, Guard);
            return new RopeSimulation(rope, radiusSettings);
        }

        /// <summary>Checks and reports what reaches this rope from the scene (see <see cref="RopeInputGuard"/>).</summary>
        RopeInputGuard Guard => _guard ??= new RopeInputGuard(this, nameof(ElasticRope));

        /// <summary>
        /// A simulation of the current settings and attachment poses that this component does not own or step
        /// (no radius model, no colliders): the editor's static-sag preview relaxes it. <paramref name="origin"/> is
        /// the world position (m) of its frame's origin.
        /// </summary>
        internal RopeSimulation CreateDetachedSimulation(out Vector3 origin) =>
            BuildSimulation(new RopeSettings(), new RopeAttachmentBinding(), radiusSettings: null, out origin);
    }
}
