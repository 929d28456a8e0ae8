namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.MeshFilter: holds the Mesh its MeshRenderer draws.</summary>
    public sealed class MeshFilter : Component
    {
        Mesh m_Mesh;

        /// <summary>Returns the shared mesh of the mesh filter.</summary>
        public Mesh sharedMesh
        {
            get { EnsureAlive(); return m_Mesh; }
            set { EnsureAlive(); m_Mesh = value; }
        }
    }
}
