using System;
using HookeRope.Geometry;
using HookeRope.Solver;
using HookeRope.World;
using UnityEngine;
using UnityEngine.Rendering;

namespace HookeRope
{
    /// <summary>
    /// Renders the <see cref="ElasticRope"/> on the same GameObject as a procedural tube whose radius follows the
    /// rope's radius model (Poisson thinning, neck) with burred ends where it broke. Submesh 0 is the tube and
    /// its caps (material 0), submesh 1 the burr strands (material 1): opaque triangles, by default drawn with a copy of
    /// the tube material carrying the burr texture (<see cref="RopeDefaultMaterial.CreateBurr"/>; no alpha test, no
    /// keyword a player build could strip). When no shader is available for a generated material (a player build
    /// without one), the slots stay empty and one console error per component names the renderer and the fix. Every LateUpdate
    /// it interpolates the rope between the last two physics steps (<see cref="Rope.Interpolate"/>, so 90/120 Hz
    /// headsets see smooth motion at any physics rate) into its one position buffer, in this GameObject's local
    /// space, lets the core build the tube (<see cref="RopeSimulation.FillMesh(System.ReadOnlySpan{float}, System.ReadOnlySpan{float}, System.ReadOnlySpan{float}, TubeVertex[], int[], float, MeshFrame)"/>,
    /// told where that space sits relative to the rope's colliders, so the tube is drawn outside a collider it wraps)
    /// and only uploads it. The mesh is dynamic (MarkDynamic); its vertex and index buffers are sized once for the most
    /// the tube can need (<see cref="RopeSimulation.GetVertexCapacity"/>, <see cref="RopeSimulation.GetIndexCapacity"/>:
    /// the adaptive rings' ring budget) and again only when that changes (new segment count or sides, a break), so
    /// <see cref="UnityEngine.Mesh.vertexCount"/> is that capacity and the sub-meshes name the vertices in use
    /// (firstVertex 0, vertexCount = the tube's). Vertices are uploaded with SetVertexBufferData from a preallocated
    /// array of that capacity (no GC per frame), indices and sub-meshes only when the topology changes (also a new ring
    /// budget of the adaptive rings, which steps within the buffers), and the bounds are set explicitly before each vertex upload.
    /// One mesh per frame serves both eyes in single-pass instanced stereo. Keep this GameObject's scale uniform.
    /// <para>
    /// Edit mode ([ExecuteAlways]): without entering Play, every editor update draws the rope without simulating it,
    /// through the same core mesh path: a detached simulation of the rope's current settings
    /// (<see cref="ElasticRope.CreateDetachedSimulation"/>, the Rebuild path) straight between the ends, or laid
    /// along the static-sag preview once one was computed (the inspector's button; it is recomputed when an end moves).
    /// The MeshRenderer then has a mesh, so the rope is pickable in the Scene view. The generated mesh, materials and
    /// burr texture are created once per enable with DontSave hide flags (the texture HideAndDontSave), so Unity never
    /// writes them into the scene (a saved slot that references one is saved empty), and OnDisable destroys them
    /// (DestroyImmediate in edit mode, Destroy in Play) and empties the slots they occupied. Generated materials only
    /// fill material slots the user left empty.
    /// </para>
    /// </summary>
    [ExecuteAlways]
    [AddComponentMenu("HookeRope/Elastic Rope Mesh")]
    [HelpURL(ElasticRope.DocumentationUrl)]
    [DisallowMultipleComponent]
    [RequireComponent(typeof(MeshFilter), typeof(MeshRenderer))]
    [RequireComponent(typeof(ElasticRope))]
    public sealed class RopeMeshRenderer : MonoBehaviour
    {
        /// <summary>Position, normal, tangent (xyzw) and uv, all float32: the layout of <see cref="TubeVertex"/>.</summary>
        static readonly VertexAttributeDescriptor[] s_Layout =
        {
            new VertexAttributeDescriptor(VertexAttribute.Position, VertexAttributeFormat.Float32, 3),
            new VertexAttributeDescriptor(VertexAttribute.Normal, VertexAttributeFormat.Float32, 3),
            new VertexAttributeDescriptor(VertexAttribute.Tangent, VertexAttributeFormat.Float32, 4),
            new VertexAttributeDescriptor(VertexAttribute.TexCoord0, VertexAttributeFormat.Float32, 2),
        };

        /// <summary>Position, normal and uv, all float32: the layout of <see cref="LeanTubeVertex"/> (<see cref="Tangents"/> off).</summary>
        static readonly VertexAttributeDescriptor[] s_LeanLayout =
        {
            new VertexAttributeDescriptor(VertexAttribute.Position, VertexAttributeFormat.Float32, 3),
            new VertexAttributeDescriptor(VertexAttribute.Normal, VertexAttributeFormat.Float32, 3),
            new VertexAttributeDescriptor(VertexAttribute.TexCoord0, VertexAttributeFormat.Float32, 2),
        };

        /// <summary>
        /// Upload flags: no index validation and no bounds recalculation (the bounds come from the tube builder and
        /// are set before the vertex upload). Renderers are still notified (no DontNotifyMeshUsers): that flag
        /// would require a later Mesh.MarkModified call, or the MeshRenderer keeps culling with stale bounds.
        /// </summary>
        const MeshUpdateFlags FrameFlags = MeshUpdateFlags.DontValidateIndices | MeshUpdateFlags.DontRecalculateBounds |
                                           MeshUpdateFlags.DontResetBoneBounds;

        [SerializeField, Range(RopeParameters.RadialSegments.Min, RopeParameters.RadialSegments.Max), Tooltip(RopeParameters.RadialSegments.Tooltip)]
        int m_RadialSegments = RopeParameters.RadialSegments.Default;

        [SerializeField, Range(RopeParameters.RingTolerance.Min, RopeParameters.RingTolerance.Max), Tooltip(RopeParameters.RingTolerance.Tooltip)]
        float m_RingTolerance = RopeParameters.RingTolerance.Default;

        [SerializeField, Tooltip("The viewer whose distance sets the rope's detail beyond Detail Distance, e.g. the XR camera's Transform. None: the main camera (the enabled Camera tagged MainCamera), or full detail without one.")]
        Transform m_ViewPoint;

        [SerializeField, Min(RopeParameters.DetailDistance.Min), Tooltip(RopeParameters.DetailDistance.Tooltip)]
        float m_DetailDistance = RopeParameters.DetailDistance.Default;

        [SerializeField, Tooltip(RopeParameters.BurrTexture.Tooltip)]
        bool m_BurrTexture = RopeParameters.BurrTexture.Default;

        [SerializeField, Tooltip(RopeParameters.Tangents.Tooltip)]
        bool m_Tangents = RopeParameters.Tangents.Default;

        [SerializeField, Tooltip(RopeParameters.Color.Tooltip)]
        Color m_Color = new Color(RopeParameters.Color.DefaultR, RopeParameters.Color.DefaultG, RopeParameters.Color.DefaultB, RopeParameters.Color.DefaultA);

        ElasticRope _rope;
        MeshFilter _filter;
        MeshRenderer _renderer;
        Mesh _mesh;
        float[] _x = Array.Empty<float>(), _y = Array.Empty<float>(), _z = Array.Empty<float>();
        TubeVertex[] _vertices = Array.Empty<TubeVertex>();
        LeanTubeVertex[] _leanVertices = Array.Empty<LeanTubeVertex>();
        int[] _indices = Array.Empty<int>();
        RopeSimulation _uploaded;
        int _uploadedTopology = -1, _vertexCount, _indexCount, _vertexCapacity = -1, _indexCapacity = -1;
        bool _uploadedTangents;
        Material _generatedMaterial;
        Material _generatedBurrMaterial;
        Texture2D _generatedTexture;
        bool _reportedMissingShader;
        RopeInputGuard _guard;
        float _viewDistance = float.NaN;

        /// <summary>Vertices around the tube, range <see cref="RopeParameters.RadialSegments"/>. A new value rebuilds the tube topology at the next frame.</summary>
        public int RadialSegments
        {
            get => m_RadialSegments;
            set
            {
                m_RadialSegments = RopeParameters.Check(value, RopeParameters.RadialSegments.Row);
            }
        }

        /// <summary>
        /// How far the drawn surface may leave the smooth tube along the rope, as a multiple of the polygon's own depth
        /// around it (<see cref="HookeRope.Geometry.TubeMeshSettings.RingTolerance"/>, range
        /// <see cref="RopeParameters.RingTolerance"/>, default 1): 2 draws about 30 % fewer rings on a bent rope. A new
        /// value applies at the next frame without new buffers or garbage (a script may set it each frame, e.g. from the
        /// rope's distance to the camera); rings it no longer needs go after the ring budget's calm spell.
        /// </summary>
        public float RingTolerance
        {
            get => m_RingTolerance;
            set => m_RingTolerance = RopeParameters.Check(value, RopeParameters.RingTolerance.Row);
        }

        /// <summary>
        /// The viewer (e.g. the XR camera's Transform) whose distance to the rope sets its ring tolerance and side count
        /// beyond <see cref="DetailDistance"/> (<see cref="ViewDetail"/>); null: Camera.main's (the first enabled Camera tagged
        /// "MainCamera", as an XR rig's camera is), or, without one, <see cref="RingTolerance"/> at any distance. A prefab
        /// cannot name a scene object, so a rope prefab with a Detail Distance relies on the main camera.
        /// </summary>
        public Transform ViewPoint
        {
            get => m_ViewPoint;
            set => m_ViewPoint = value;
        }

        /// <summary>
        /// Distance from <see cref="ViewPoint"/> (m, range <see cref="RopeParameters.DetailDistance"/>, default 0 = off) up
        /// to which the rope draws at <see cref="RingTolerance"/>; beyond it the tolerance grows in proportion to the
        /// distance (to the box around the rope's particles), up to 16, and from 4.4 times this distance an unbroken rope
        /// draws half its sides (<see cref="DrawnRadialSegments"/>), so the detail seen from the viewer stays what it is at
        /// this distance (<see cref="ViewDetail"/>). Read every frame; allocation-free once the rope has drawn at both side
        /// counts (the first switch makes the other count's builder and keeps it).
        /// </summary>
        public float DetailDistance
        {
            get => m_DetailDistance;
            set => m_DetailDistance = RopeParameters.Check(value, RopeParameters.DetailDistance.Row);
        }

        /// <summary>
        /// Whether the mesh has vertex tangents (default true): 48-byte vertices (position, normal, tangent, uv). Only
        /// normal-mapped materials read tangents; without (false) the vertices are 32 bytes (position, normal, uv;
        /// <see cref="LeanTubeVertex"/>), a third less to write and upload every frame, with the same positions, normals
        /// and uv bit for bit. A new value re-lays the vertex buffer at the next frame (once; no garbage after it).
        /// </summary>
        public bool Tangents
        {
            get => m_Tangents;
            set => m_Tangents = value;
        }

        /// <summary>The ring tolerance the last drawn frame used: <see cref="RingTolerance"/>, scaled by the view distance where <see cref="DetailDistance"/> is on (1 before the first frame).</summary>
        public float DrawnRingTolerance { get; private set; } = RopeParameters.RingTolerance.Default;

        /// <summary>
        /// The side count the last drawn frame used: <see cref="RadialSegments"/>, or half of it (rounded up, at least 3) on
        /// an unbroken rope from 4.4 detail distances away until it comes within 4 again (<see cref="ViewDetail.RadialSegments"/>);
        /// 0 before the first frame.
        /// </summary>
        public int DrawnRadialSegments { get; private set; }

        /// <summary>The generated mesh, or null before the first <see cref="Render"/>.</summary>
        public Mesh Mesh => _mesh;

        void OnValidate()
        {
            string message = RopeParameters.Clamp(ref m_RadialSegments, RopeParameters.RadialSegments.Row);
            if (message != null) Debug.LogWarning("RopeMeshRenderer '" + name + "': " + message, this);
            message = RopeParameters.Clamp(ref m_RingTolerance, RopeParameters.RingTolerance.Row);
            if (message != null) Debug.LogWarning("RopeMeshRenderer '" + name + "': " + message, this);
            message = RopeParameters.Clamp(ref m_DetailDistance, RopeParameters.DetailDistance.Row);
            if (message != null) Debug.LogWarning("RopeMeshRenderer '" + name + "': " + message, this);
        }

        void LateUpdate()
        {
            if (!Application.isPlaying)
            {
                Render(1f);
                return;
            }
            float alpha = Time.fixedDeltaTime > 0f ? (Time.time - Time.fixedTime) / Time.fixedDeltaTime : 1f;
            // with two or more ropes in the shared world, the first renderer of the frame draws all of them (ElasticRopeWorld)
            if (!RopeWorldScheduler.OnLateUpdate(this, _rope, alpha, Time.frameCount)) Render(alpha);
        }

        void OnEnable()
        {
            if (_rope != null || TryGetComponent(out _rope)) _rope.Drawer = this;
        }

        void OnDisable()
        {
            if (_rope is object && ReferenceEquals(_rope.Drawer, this)) _rope.Drawer = null;
            ReleaseGenerated();
        }

        void OnDestroy() => ReleaseGenerated();

        /// <summary>Takes the generated mesh and materials out of the MeshFilter and MeshRenderer and destroys everything generated.</summary>
        void ReleaseGenerated()
        {
            if (_mesh != null && _filter != null && _filter.sharedMesh == _mesh) _filter.sharedMesh = null;
            if (_renderer != null && (_generatedMaterial != null || _generatedBurrMaterial != null))
            {
                var materials = _renderer.sharedMaterials;
                bool changed = false;
                for (int i = 0; i < materials.Length; i++)
                {
                    if (materials[i] == null || (materials[i] != _generatedMaterial && materials[i] != _generatedBurrMaterial)) continue;
                    materials[i] = null;
                    changed = true;
                }
                if (changed) _renderer.sharedMaterials = materials;
            }
            DestroyOwned(_mesh);
            DestroyOwned(_generatedMaterial);
            DestroyOwned(_generatedBurrMaterial);
            DestroyOwned(_generatedTexture);
            _mesh = null;
            _generatedMaterial = null;
            _generatedBurrMaterial = null;
            _generatedTexture = null;
            _uploaded = null;
            _uploadedTopology = -1;
            _vertexCapacity = -1;
            _indexCapacity = -1;
        }

        /// <summary>
        /// Rebuilds the tube from the rope's positions interpolated by <paramref name="alpha"/> (0 = previous physics
        /// step, 1 = latest) and uploads it. LateUpdate calls it; call it yourself in edit-mode code and tests.
        /// In edit mode, before the rope is built, it draws the edit-mode shape instead (straight between the ends,
        /// or the static-sag preview; see the class remarks; this path allocates a detached core simulation).
        /// Returns false when nothing was drawn (no rope, or in Play before the build) or when the mesh kept its last
        /// frame because this object's scale cannot be inverted or a position was not finite (one warning per cause,
        /// Documentation~/index.md, "Bad input"). Allocation-free after the first frame, whatever ring budget the adaptive
        /// rings choose; a break, a new segment count or a new side count sizes the buffers again, once (for one
        /// simulation they only grow, so a far rope switching between its two side counts keeps the larger).
        /// </summary>
        public bool Render(float alpha)
        {
            if (!Prepare(alpha, out var simulation, out var origin)) return false;
            // made once for the ring budget's most (constant until a break): the adaptive budgets step within it
            int vertexCapacity = simulation.GetVertexCapacity(), indexCapacity = simulation.GetIndexCapacity();
            if (_indices.Length < indexCapacity) _indices = new int[indexCapacity];
            if (m_Tangents && _vertices.Length < vertexCapacity) _vertices = new TubeVertex[vertexCapacity];
            if (!m_Tangents && _leanVertices.Length < vertexCapacity) _leanVertices = new LeanTubeVertex[vertexCapacity];
            TubeVertex[] full = m_Tangents ? _vertices : null;
            LeanTubeVertex[] lean = m_Tangents ? null : _leanVertices;
            var update = simulation.FillMesh(_x, _y, _z, full, lean, _indices, RadiusScale(), LocalFrameInRope(origin));
            Upload(simulation, update, full, lean, _indices);
            return true;
        }

        /// <summary>The frame this renderer was last drawn in by the shared world's pass (−1: never).</summary>
        internal int DrawnFrame { get; set; } = -1;

        /// <summary>
        /// The main-thread half of a world draw: what <see cref="Render"/> does before the fill, then names this
        /// renderer's position arrays and frame to <paramref name="slot"/> (turned off when there is nothing to draw).
        /// </summary>
        internal bool PrepareWorldFill(float alpha, RopeMeshSlot slot)
        {
            bool ready = Prepare(alpha, out _, out var origin);
            if (ready) slot.UseCallerPositions(_x, _y, _z, RadiusScale(), LocalFrameInRope(origin));
            slot.Tangents = m_Tangents;
            slot.Enabled = ready;
            return ready;
        }

        /// <summary>Uploads what the world filled into <paramref name="slot"/> after <see cref="PrepareWorldFill"/>.</summary>
        internal void UploadWorldFill(RopeMeshSlot slot) =>
            Upload(_rope.Simulation, slot.Update, slot.Tangents ? slot.Vertices : null, slot.Tangents ? null : slot.LeanVertices, slot.Indices);

        /// <summary>
        /// Everything <see cref="Render"/> does before the fill: picks the simulation (the rope's, or the edit-mode
        /// shape), checks the drawing frame, makes the mesh and interpolates the positions into this GameObject's local
        /// space; false when there is nothing to draw (see <see cref="Render"/>).
        /// </summary>
        bool Prepare(float alpha, out RopeSimulation simulation, out Vector3 origin)
        {
            simulation = null;
            origin = default;
            if (_rope == null && !TryGetComponent(out _rope)) return false;
            bool alignEnds = true;
            if (_rope.IsBuilt)
            {
                simulation = _rope.Simulation;
                origin = _rope.SimulationOrigin;
            }
            else if (!Application.isPlaying)
            {
                simulation = CreateEditModeShape(out origin);
                alignEnds = false;
                alpha = 1f;
            }
            else return false;
            // a transform that cannot be inverted (scale 0) or non-finite positions: keep the last uploaded mesh
            _guard ??= new RopeInputGuard(this, nameof(RopeMeshRenderer));
            if (!_guard.AcceptDrawingFrame(transform)) return false;
            EnsureMesh();

            InterpolateIntoLocalSpace(simulation.Rope, alpha, origin, alignEnds);
            if (!_guard.AcceptMeshPositions(_x, _y, _z, simulation.Rope.ParticleCount)) return false;
            // this frame's side count and ring tolerance: the settings', or those the view distance asks for (ViewDetail;
            // NaN when off or without a viewer, which it reads as full detail); a broken rope keeps its sides
            ViewDetail.Choose(m_RadialSegments, m_RingTolerance, m_DetailDistance, _viewDistance, DrawnRadialSegments,
                simulation.Rope.BrokenSegmentCount > 0, out int sides, out float tolerance);
            if (simulation.MeshSettings.RadialSegments != sides) simulation.MeshSettings.RadialSegments = sides;
            if (!simulation.MeshSettings.RingTolerance.Equals(tolerance)) simulation.MeshSettings.RingTolerance = tolerance;
            DrawnRadialSegments = sides;
            DrawnRingTolerance = tolerance;
            return true;
        }

        /// <summary>
        /// Distance (m) from <see cref="ViewPoint"/> (or the main camera) to the box around the first
        /// <paramref name="particles"/> positions, which are world offsets from <paramref name="origin"/>; NaN when
        /// <see cref="DetailDistance"/> is off or there is no viewer.
        /// </summary>
        float ViewDistance(Vector3 origin, int particles)
        {
            if (!(m_DetailDistance > 0f)) return float.NaN;
            Transform viewPoint = m_ViewPoint;
            if (viewPoint == null)
            {
                Camera main = Camera.main;
                if (main == null) return float.NaN;
                viewPoint = main.transform;
            }
            return ViewDetail.DistanceToBox(_x, _y, _z, particles, (viewPoint.position - origin).ToFloat3());
        }

        /// <summary>
        /// Uploads a filled tube (<paramref name="update"/> over <paramref name="vertices"/>, or, when it is null, over
        /// <paramref name="leanVertices"/>, and <paramref name="indices"/>, from this renderer's buffers or its world mesh
        /// slot): the buffer sizes only when the capacity or the vertex layout changed, the indices and sub-meshes only
        /// when the topology or the source changed, then the bounds, then the vertices in use.
        /// </summary>
        void Upload(RopeSimulation simulation, TubeMeshUpdate update, TubeVertex[] vertices, LeanTubeVertex[] leanVertices, int[] indices)
        {
            bool tangents = vertices != null;
            bool sameSimulation = ReferenceEquals(_uploaded, simulation);
            // another vertex layout: the buffer is laid out again (at the capacity it would keep anyway)
            bool relayout = tangents != _uploadedTangents || _vertexCapacity < 0;
            if (update.TopologyChanged || !sameSimulation || _uploadedTopology != simulation.MeshTopologyVersion ||
                _vertexCount != update.VertexCount || _indexCount != update.IndexCount || relayout)
            {
                _uploaded = simulation;
                _uploadedTopology = simulation.MeshTopologyVersion;
                _vertexCount = update.VertexCount;
                _indexCount = update.IndexCount;
                // the buffers hold the most the tube can need: a new ring budget steps within them (no reallocation);
                // for the same simulation they only grow, so a far rope switching between its two side counts
                // (DetailDistance) keeps the larger buffers
                int vertexCapacity = Math.Max(simulation.GetVertexCapacity(), update.VertexCount);
                int indexCapacity = Math.Max(simulation.GetIndexCapacity(), update.IndexCount);
                if (sameSimulation)
                {
                    vertexCapacity = Math.Max(vertexCapacity, _vertexCapacity);
                    indexCapacity = Math.Max(indexCapacity, _indexCapacity);
                }
                if (vertexCapacity != _vertexCapacity || relayout)
                {
                    _vertexCapacity = vertexCapacity;
                    _uploadedTangents = tangents;
                    _mesh.SetVertexBufferParams(vertexCapacity, tangents ? s_Layout : s_LeanLayout);
                }
                if (indexCapacity != _indexCapacity)
                {
                    _indexCapacity = indexCapacity;
                    _mesh.SetIndexBufferParams(indexCapacity, IndexFormat.UInt32);
                }
                _mesh.SetIndexBufferData(indices, 0, 0, update.IndexCount, FrameFlags);
                _mesh.subMeshCount = 2;
                _mesh.SetSubMesh(0, InUse(0, update.TubeIndexCount, update.VertexCount), FrameFlags);
                _mesh.SetSubMesh(1, InUse(update.TubeIndexCount, update.IndexCount - update.TubeIndexCount, update.VertexCount), FrameFlags);
            }
            // Bounds first, so the renderer notification of the vertex upload already sees this frame's bounds.
            Vector3 min = update.BoundsMin.ToVector3(), max = update.BoundsMax.ToVector3();
            _mesh.bounds = new Bounds((min + max) * 0.5f, max - min);
            if (tangents) _mesh.SetVertexBufferData(vertices, 0, 0, update.VertexCount, 0, FrameFlags);
            else _mesh.SetVertexBufferData(leanVertices, 0, 0, update.VertexCount, 0, FrameFlags);
        }

        /// <summary>A triangle sub-mesh of <paramref name="indexCount"/> indices from <paramref name="indexStart"/> over the first <paramref name="vertexCount"/> vertices (the rest of the buffer is spare capacity).</summary>
        static SubMeshDescriptor InUse(int indexStart, int indexCount, int vertexCount) =>
            new SubMeshDescriptor(indexStart, indexCount, MeshTopology.Triangles) { firstVertex = 0, vertexCount = vertexCount };

        /// <summary>The rope's interpolated particle positions in this GameObject's local space (m), into the one position buffer.</summary>
        void InterpolateIntoLocalSpace(Rope rope, float alpha, Vector3 simulationOrigin, bool alignEnds)
        {
            int particles = rope.ParticleCount;
            if (_x.Length != particles)
            {
                _x = new float[particles];
                _y = new float[particles];
                _z = new float[particles];
            }
            rope.Interpolate(alpha, _x, _y, _z);
            Vector3 origin = simulationOrigin + rope.Origin.ToVector3();
            // the attachments are drawn at their live poses: put the rope's ends on them (the interior follows smoothly)
            var start = _rope.StartAttachment;
            var end = _rope.EndAttachment;
            bool startHeld = alignEnds && start.Kind != RopeEndKind.Free, endHeld = alignEnds && end.Kind != RopeEndKind.Free;
            int last = particles - 1;
            var startOffset = startHeld ? (start.DrawnPosition() - origin - new Vector3(_x[0], _y[0], _z[0])).ToFloat3() : default;
            var endOffset = endHeld ? (end.DrawnPosition() - origin - new Vector3(_x[last], _y[last], _z[last])).ToFloat3() : default;
            startHeld &= startOffset.IsFinite;   // an attachment at a non-finite pose (reported by the rope) is not followed
            endHeld &= endOffset.IsFinite;
            if (startHeld || endHeld) EndAlignment.Apply(_x, _y, _z, rope.BrokenSegments, startHeld, startOffset, endHeld, endOffset);
            // the view distance in world space (m), while the positions are still world offsets from origin: exact under
            // any scale, skew included, of this GameObject's hierarchy
            _viewDistance = ViewDistance(origin, particles);
            var frame = transform;
            for (int i = 0; i < particles; i++)
            {
                var local = frame.InverseTransformPoint(new Vector3(origin.x + _x[i], origin.y + _y[i], origin.z + _z[i]));
                _x[i] = local.x;
                _y[i] = local.y;
                _z[i] = local.z;
            }
        }

        /// <summary>
        /// The edit-mode shape: a detached core simulation of the rope's current settings (built straight between the
        /// ends), its particles moved onto the static-sag preview when one exists for the current segment count.
        /// <paramref name="origin"/> is the world position (m) of its frame's origin.
        /// </summary>
        RopeSimulation CreateEditModeShape(out Vector3 origin)
        {
            var simulation = _rope.CreateDetachedSimulation(out origin);
            var core = simulation.Rope;
            var preview = RopeStaticSag.GetFollowing(_rope);
            if (preview.Length == core.ParticleCount)
                for (int i = 0; i < preview.Length; i++) core.SetPosition(i, (preview[i] - origin).ToFloat3());
            return simulation;
        }

        /// <summary>
        /// This GameObject's local space in the simulation's frame (whose origin is at world <paramref name="simulationOrigin"/>, m,
        /// the frame of the rope's colliders): its pose and (uniform) scale, so the core keeps the drawn tube out of them.
        /// </summary>
        MeshFrame LocalFrameInRope(Vector3 simulationOrigin)
        {
            var frame = transform;
            return new MeshFrame((frame.position - simulationOrigin).ToFloat3(), frame.rotation.ToQuat(), frame.lossyScale.x);
        }

        /// <summary>Ring radii are in world metres; the mesh is in local space, so they shrink by the (uniform) scale.</summary>
        float RadiusScale()
        {
            float scale = Math.Abs(transform.lossyScale.x);
            return scale != 0f && float.IsFinite(scale) ? 1f / scale : 1f;
        }

        void EnsureMesh()
        {
            if (_mesh != null) return;
            _mesh = new Mesh { name = "Elastic Rope (generated)", hideFlags = HideFlags.DontSave };
            _mesh.MarkDynamic();
            if (_filter == null) _filter = GetComponent<MeshFilter>();
            if (_renderer == null) _renderer = GetComponent<MeshRenderer>();
            _filter.sharedMesh = _mesh;
            var materials = _renderer.sharedMaterials;
            Material tube = materials.Length > 0 ? materials[0] : null;
            Material burr = materials.Length > 1 ? materials[1] : null;
            if (tube == null)
            {
                _generatedMaterial = RopeDefaultMaterial.Create(null);
                RopeDefaultMaterial.SetBaseColor(_generatedMaterial, m_Color);
                tube = _generatedMaterial;
            }
            if (burr == null && tube != null)
            {
                if (m_BurrTexture && _generatedTexture == null) _generatedTexture = RopeDefaultMaterial.CreateBurrTexture();
                _generatedBurrMaterial = m_BurrTexture ? RopeDefaultMaterial.CreateBurr(tube, _generatedTexture) : null;
                burr = _generatedBurrMaterial != null ? _generatedBurrMaterial : tube;
            }
            if (tube == null && !_reportedMissingShader)
            {
                _reportedMissingShader = true;
                Debug.LogError("RopeMeshRenderer '" + name + "': " + RopeDefaultMaterial.MissingShaderAdvice(GraphicsSettings.currentRenderPipeline), this);
            }
            _renderer.sharedMaterials = new[] { tube, burr };
        }

        static void DestroyOwned(UnityEngine.Object owned)
        {
            if (owned == null) return;
            if (Application.isPlaying) Destroy(owned);
            else DestroyImmediate(owned);
        }
    }
}
