using UnityEngine.Rendering;

namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Mesh (the advanced vertex/index buffer API the rope mesh uses).</summary>
    public sealed class Mesh : Object
    {
        /// <summary>Creates an empty Mesh.</summary>
        public Mesh() => throw Shim.NotRun;

        /// <summary>The bounding volume of the Mesh.</summary>
        public Bounds bounds { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The number of sub-meshes inside the Mesh object.</summary>
        public int subMeshCount { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Returns the number of vertices in the Mesh (Read Only).</summary>
        public int vertexCount => throw Shim.NotRun;

        /// <summary>Returns a copy of the vertex positions or assigns a new vertex positions array.</summary>
        public Vector3[] vertices { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>An array containing all triangles in the Mesh.</summary>
        public int[] triangles { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Optimize mesh for frequent updates.</summary>
        public void MarkDynamic() => throw Shim.NotRun;

        /// <summary>Sets the vertex buffer size and layout.</summary>
        public void SetVertexBufferParams(int vertexCount, params VertexAttributeDescriptor[] attributes) => throw Shim.NotRun;

        /// <summary>Sets the data of the vertex buffer of the Mesh.</summary>
        public void SetVertexBufferData<T>(T[] data, int dataStart, int meshBufferStart, int count, int stream = 0, MeshUpdateFlags flags = MeshUpdateFlags.Default) where T : struct => throw Shim.NotRun;

        /// <summary>Sets the index buffer size and format.</summary>
        public void SetIndexBufferParams(int indexCount, IndexFormat format) => throw Shim.NotRun;

        /// <summary>Sets the data of the index buffer of the Mesh.</summary>
        public void SetIndexBufferData<T>(T[] data, int dataStart, int meshBufferStart, int count, MeshUpdateFlags flags = MeshUpdateFlags.Default) where T : struct => throw Shim.NotRun;

        /// <summary>Sets the information about a sub-mesh of the Mesh.</summary>
        public void SetSubMesh(int index, SubMeshDescriptor desc, MeshUpdateFlags flags = MeshUpdateFlags.Default) => throw Shim.NotRun;
    }
}
