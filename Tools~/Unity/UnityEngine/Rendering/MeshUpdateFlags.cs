namespace UnityEngine.Rendering
{
    /// <summary>Stand-in of UnityEngine.Rendering.MeshUpdateFlags: flags that control how Mesh data is updated.</summary>
    [System.Flags]
    public enum MeshUpdateFlags
    {
        /// <summary>Indicates that Unity should perform the default checks and validation when you update a Mesh's data.</summary>
        Default = 0,
        /// <summary>Indicates that Unity should not check index values when you use Mesh.SetIndexBufferData to modify a Mesh's data.</summary>
        DontValidateIndices = 1,
        /// <summary>Indicates that Unity should not reset skinned mesh bone bounds when you modify Mesh data using Mesh.SetVertexBufferData or Mesh.SetIndexBufferData.</summary>
        DontResetBoneBounds = 2,
        /// <summary>Indicates that Unity should not notify Renderer components about a possible Mesh bounds change.</summary>
        DontNotifyMeshUsers = 4,
        /// <summary>Indicates that Unity should not recalculate the bounds when you set Mesh data using Mesh.SetSubMesh.</summary>
        DontRecalculateBounds = 8,
    }
}
