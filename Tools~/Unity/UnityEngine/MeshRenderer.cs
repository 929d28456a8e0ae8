namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.MeshRenderer: renders meshes inserted by the MeshFilter.</summary>
    public class MeshRenderer : Renderer
    {
    }
}
