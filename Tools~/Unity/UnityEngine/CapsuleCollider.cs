namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.CapsuleCollider: a capsule-shaped primitive collider.</summary>
    public class CapsuleCollider : Collider
    {
        /// <summary>The center of the capsule, measured in the object's local space.</summary>
        public Vector3 center { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The radius of the sphere, measured in the object's local space.</summary>
        public float radius { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The height of the capsule measured in the object's local space.</summary>
        public float height { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The direction of the capsule (0, 1, 2 = X, Y, Z axis).</summary>
        public int direction { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
