namespace UnityEngine.Rendering
{
    /// <summary>Shim of UnityEngine.Rendering.SubMeshDescriptor: contains information about a single sub-mesh of a Mesh.</summary>
    public struct SubMeshDescriptor
    {
        /// <summary>Create a submesh descriptor.</summary>
        public SubMeshDescriptor(int indexStart, int indexCount, MeshTopology topology = MeshTopology.Triangles) => throw Shim.NotRun;
    }
}
