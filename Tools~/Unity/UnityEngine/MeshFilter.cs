namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.MeshFilter.</summary>
    public sealed class MeshFilter : Component
    {
        /// <summary>Returns the shared mesh of the mesh filter.</summary>
        public Mesh sharedMesh { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
