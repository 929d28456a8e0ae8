namespace UnityEngine.Rendering
{
    /// <summary>Stand-in of UnityEngine.Rendering.SubMeshDescriptor: contains information about a single sub-mesh of a Mesh.</summary>
    public struct SubMeshDescriptor
    {
        /// <summary>Create a submesh descriptor (bounds, baseVertex, firstVertex and vertexCount start at zero).</summary>
        public SubMeshDescriptor(int indexStart, int indexCount, MeshTopology topology = MeshTopology.Triangles)
        {
            this.indexStart = indexStart;
            this.indexCount = indexCount;
            this.topology = topology;
            bounds = new Bounds();
            baseVertex = 0;
            firstVertex = 0;
            vertexCount = 0;
        }

        /// <summary>Bounding box of vertices in local space.</summary>
        public Bounds bounds { get; set; }

        /// <summary>Face topology of this sub-mesh.</summary>
        public MeshTopology topology { get; set; }

        /// <summary>Starting point inside the whole Mesh index buffer where the face index data is found.</summary>
        public int indexStart { get; set; }

        /// <summary>Index count for this sub-mesh face data.</summary>
        public int indexCount { get; set; }

        /// <summary>Offset that is added to each value in the index buffer, to compute the final vertex index.</summary>
        public int baseVertex { get; set; }

        /// <summary>First vertex in the index buffer for this sub-mesh.</summary>
        public int firstVertex { get; set; }

        /// <summary>Number of vertices used by the index buffer of this sub-mesh.</summary>
        public int vertexCount { get; set; }

        /// <summary>Returns "(topo=… indices=… vertices=… basevtx=… bounds=…)" as Unity does.</summary>
        public override string ToString() =>
            $"(topo={topology} indices={indexStart},{indexCount} vertices={firstVertex},{vertexCount} basevtx={baseVertex} bounds={bounds})";
    }
}
