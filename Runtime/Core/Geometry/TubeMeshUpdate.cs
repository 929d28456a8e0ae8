using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>What one <see cref="TubeMeshBuilder"/> build wrote.</summary>
    public readonly struct TubeMeshUpdate
    {
        /// <summary>Vertices written (a prefix of the vertex buffer).</summary>
        public readonly int VertexCount;
        /// <summary>Indices of the topology (a prefix of the index buffer): tube and caps first, then burr strands.</summary>
        public readonly int IndexCount;
        /// <summary>Indices of the tube and caps, [0, TubeIndexCount) (first submesh).</summary>
        public readonly int TubeIndexCount;
        /// <summary>Indices of the burr strands, [TubeIndexCount, IndexCount) (second submesh, burr material).</summary>
        public readonly int BurrIndexCount;
        /// <summary>True when the index buffer was rewritten by this build (first build, break, new buffer).</summary>
        public readonly bool TopologyChanged;
        /// <summary>
        /// Offset in metres to add to the vertex positions and bounds to reach the world frame: zero from
        /// <see cref="TubeMeshBuilder"/> and the span overload of RopeSimulation.FillMesh (vertices are in the input
        /// frame), <see cref="HookeRope.Solver.Rope.Origin"/> from RopeSimulation.FillMesh(vertices, indices). Removed with
        /// the issue 12 contract step.
        /// </summary>
        public readonly Float3 Origin;
        /// <summary>Lower corner in metres (in the frame of the vertices) of a box holding every vertex (tight to within the ring polygons' circumcircles).</summary>
        public readonly Float3 BoundsMin;
        /// <summary>Upper corner in metres (in the frame of the vertices) of a box holding every vertex.</summary>
        public readonly Float3 BoundsMax;

        /// <summary>Creates the report.</summary>
        public TubeMeshUpdate(int vertexCount, int indexCount, int tubeIndexCount, bool topologyChanged, Float3 origin, Float3 boundsMin, Float3 boundsMax)
        {
            VertexCount = vertexCount;
            IndexCount = indexCount;
            TubeIndexCount = tubeIndexCount;
            BurrIndexCount = indexCount - tubeIndexCount;
            TopologyChanged = topologyChanged;
            Origin = origin;
            BoundsMin = boundsMin;
            BoundsMax = boundsMax;
        }
    }
}
