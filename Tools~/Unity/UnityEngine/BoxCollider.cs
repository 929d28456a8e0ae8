namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.BoxCollider: a box-shaped primitive collider.</summary>
    public class BoxCollider : Collider
    {
        /// <summary>The center of the box, measured in the object's local space.</summary>
        public Vector3 center { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The size of the box, measured in the object's local space.</summary>
        public Vector3 size { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
