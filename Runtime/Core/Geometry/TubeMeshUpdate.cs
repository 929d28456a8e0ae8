using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>What one <see cref="RopeSimulation.FillMesh(System.ReadOnlySpan{float}, System.ReadOnlySpan{float}, System.ReadOnlySpan{float}, TubeVertex[], int[], float)"/> wrote; positions and bounds are in the frame of the input positions.</summary>
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
        /// <summary>Lower corner in metres (in the frame of the vertices) of a box holding every vertex (tight to within the ring polygons' circumcircles).</summary>
        public readonly Float3 BoundsMin;
        /// <summary>Upper corner in metres (in the frame of the vertices) of a box holding every vertex.</summary>
        public readonly Float3 BoundsMax;

        internal TubeMeshUpdate(int vertexCount, int indexCount, int tubeIndexCount, bool topologyChanged, Float3 boundsMin, Float3 boundsMax)
        {
            VertexCount = vertexCount;
            IndexCount = indexCount;
            TubeIndexCount = tubeIndexCount;
            BurrIndexCount = indexCount - tubeIndexCount;
            TopologyChanged = topologyChanged;
            BoundsMin = boundsMin;
            BoundsMax = boundsMax;
        }
    }
}
