namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.MeshRenderer: renders meshes inserted by the MeshFilter (here: records materials and reports bounds; nothing is drawn).</summary>
    public class MeshRenderer : Renderer
    {
        internal override Bounds? LocalBoundsForCulling
        {
            get
            {
                var filter = GetComponent<MeshFilter>();
                var mesh = filter != null ? filter.sharedMesh : null;
                return mesh != null ? mesh.UpdateLog.BoundsSeenByUsers : (Bounds?)null;
            }
        }
    }
}
