namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.SphereCollider: a sphere-shaped primitive collider.</summary>
    public class SphereCollider : Collider
    {
        /// <summary>The center of the sphere in the object's local space.</summary>
        public Vector3 center { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The radius of the sphere measured in the object's local space.</summary>
        public float radius { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
