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
        /// <summary>Position of the rope's first particle in metres: vertex positions are relative to it.</summary>
        public readonly Float3 Origin;
        /// <summary>Lower corner in metres (relative to <see cref="Origin"/>) of a box holding every vertex (tight to within the ring polygons' circumcircles).</summary>
        public readonly Float3 BoundsMin;
        /// <summary>Upper corner in metres (relative to <see cref="Origin"/>) of a box holding every vertex.</summary>
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
