using System;
using HookeRope.Geometry;

namespace HookeRope.World
{
    /// <summary>
    /// The tube-mesh buffers of one rope in a <see cref="RopeWorld"/>: the world fills them on a worker thread
    /// (<see cref="RopeWorld.FillMeshes"/>, <see cref="RopeWorld.StepAndFillMeshes"/>) and the host uploads them
    /// afterwards on its own thread (copy-out). Positions come either from the rope itself (rope-local frame, the
    /// default) or from caller-owned arrays written before the pass (copy-in, e.g. interpolated and in a renderer's
    /// local frame, see <see cref="UseCallerPositions(float[], float[], float[], float)"/>). The buffers are made at the
    /// first fill for the most the mesh can need (<see cref="RopeSimulation.GetVertexCapacity"/>,
    /// <see cref="RopeSimulation.GetIndexCapacity"/>: the adaptive rings' ring budget), so no later pass allocates
    /// whatever ring budget the rope's motion asks for; only a break (or new mesh topology settings) makes them again, once.
    /// </summary>
    public sealed class RopeMeshSlot
    {
        private float[] callerX, callerY, callerZ;
        private float radiusScale = 1f;
        private MeshFrame frame;
        private bool hasFrame;

        internal RopeMeshSlot()
        {
        }

        /// <summary>Vertices of the last fill (the first <see cref="TubeMeshUpdate.VertexCount"/> of <see cref="Update"/> are valid).</summary>
        public TubeVertex[] Vertices { get; private set; } = Array.Empty<TubeVertex>();

        /// <summary>
        /// Vertices of the last fill when <see cref="Tangents"/> is off (then <see cref="Vertices"/> stays as it was; the
        /// first <see cref="TubeMeshUpdate.VertexCount"/> of <see cref="Update"/> are valid).
        /// </summary>
        public LeanTubeVertex[] LeanVertices { get; private set; } = Array.Empty<LeanTubeVertex>();

        /// <summary>
        /// Whether the fills write tangents (default true): into <see cref="Vertices"/> (48 bytes each) when on, else into
        /// <see cref="LeanVertices"/> (32 bytes: for materials without a normal map). Set it between passes.
        /// </summary>
        public bool Tangents { get; set; } = true;

        /// <summary>Indices of the last fill (rewritten only when <see cref="TubeMeshUpdate.TopologyChanged"/>; the first <see cref="TubeMeshUpdate.IndexCount"/> are valid).</summary>
        public int[] Indices { get; private set; } = Array.Empty<int>();

        /// <summary>Result of the last fill: counts, topology flag, bounds (m, in the positions' frame).</summary>
        public TubeMeshUpdate Update { get; private set; }

        /// <summary>Fills served so far (0 before the first pass).</summary>
        public int FillCount { get; private set; }

        /// <summary>
        /// Whether the world's mesh passes fill this slot (default true). A host that has nothing to draw for the rope
        /// this frame (or whose caller arrays are stale) turns it off: the buffers keep the last fill.
        /// </summary>
        public bool Enabled { get; set; } = true;

        /// <summary>True when the positions come from <see cref="UseCallerPositions(float[], float[], float[], float)"/> rather than the rope.</summary>
        public bool UsesCallerPositions => callerX != null;

        /// <summary>
        /// From the next fill on, builds the tube through <paramref name="x"/>, <paramref name="y"/>, <paramref name="z"/>
        /// (m, at least ParticleCount each, written by the caller before every pass, in the frame the vertices should
        /// be in) with ring radii times <paramref name="radiusScaleFactor"/> (&gt; 0, e.g. 1/|lossyScale.x|). The arrays
        /// are read, not copied: do not write them while a pass runs.
        /// </summary>
        public void UseCallerPositions(float[] x, float[] y, float[] z, float radiusScaleFactor)
        {
            if (x == null) throw new ArgumentNullException(nameof(x));
            if (y == null) throw new ArgumentNullException(nameof(y));
            if (z == null) throw new ArgumentNullException(nameof(z));
            if (!float.IsFinite(radiusScaleFactor) || !(radiusScaleFactor > 0f))
                throw new ArgumentOutOfRangeException(nameof(radiusScaleFactor), radiusScaleFactor, "radiusScaleFactor must be finite and in (0, +inf).");
            callerX = x;
            callerY = y;
            callerZ = z;
            radiusScale = radiusScaleFactor;
            hasFrame = false;
        }

        /// <summary>
        /// <see cref="UseCallerPositions(float[], float[], float[], float)"/> for positions in a caller frame that
        /// <paramref name="callerFrame"/> places in the rope's world frame (e.g. a renderer's local space): ring centres
        /// are then kept out of the rope's colliders, as with the <see cref="MeshFrame"/> overload of
        /// <see cref="RopeSimulation.FillMesh(ReadOnlySpan{float}, ReadOnlySpan{float}, ReadOnlySpan{float}, TubeVertex[], int[], float, MeshFrame)"/>.
        /// </summary>
        public void UseCallerPositions(float[] x, float[] y, float[] z, float radiusScaleFactor, MeshFrame callerFrame)
        {
            UseCallerPositions(x, y, z, radiusScaleFactor);
            frame = callerFrame;
            hasFrame = true;
        }

        /// <summary>From the next fill on, builds the tube through the rope's own positions (rope-local frame, radius scale 1).</summary>
        public void UseRopePositions()
        {
            callerX = callerY = callerZ = null;
            radiusScale = 1f;
            hasFrame = false;
        }

        /// <summary>Fills the buffers from <paramref name="simulation"/> (called by the world on a worker thread).</summary>
        internal void Fill(RopeSimulation simulation)
        {
            // made once for the ring budget's most (constant until a break): the adaptive budgets step within it
            int vertexCapacity = simulation.GetVertexCapacity(), indexCapacity = simulation.GetIndexCapacity();
            if (Indices.Length < indexCapacity) Indices = new int[indexCapacity];
            if (Tangents && Vertices.Length < vertexCapacity) Vertices = new TubeVertex[vertexCapacity];
            if (!Tangents && LeanVertices.Length < vertexCapacity) LeanVertices = new LeanTubeVertex[vertexCapacity];
            TubeVertex[] full = Tangents ? Vertices : null;
            LeanTubeVertex[] lean = Tangents ? null : LeanVertices;
            Update = callerX == null ? simulation.FillMesh(full, lean, Indices)
                : simulation.FillMesh(callerX, callerY, callerZ, full, lean, Indices, radiusScale, hasFrame ? frame : (MeshFrame?)null);
            FillCount++;
        }
    }
}
