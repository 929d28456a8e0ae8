namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.RigidbodyConstraints: which degrees of freedom of a Rigidbody are simulated (values as Unity 2022.3, Modules/Physics/Managed/Dynamics.cs; not a [Flags] enum there either).</summary>
    public enum RigidbodyConstraints
    {
        /// <summary>No constraints.</summary>
        None = 0,
        /// <summary>Freeze motion along the X-axis.</summary>
        FreezePositionX = 2,
        /// <summary>Freeze motion along the Y-axis.</summary>
        FreezePositionY = 4,
        /// <summary>Freeze motion along the Z-axis.</summary>
        FreezePositionZ = 8,
        /// <summary>Freeze rotation along the X-axis.</summary>
        FreezeRotationX = 16,
        /// <summary>Freeze rotation along the Y-axis.</summary>
        FreezeRotationY = 32,
        /// <summary>Freeze rotation along the Z-axis.</summary>
        FreezeRotationZ = 64,
        /// <summary>Freeze motion along all axes.</summary>
        FreezePosition = 14,
        /// <summary>Freeze rotation along all axes.</summary>
        FreezeRotation = 112,
        /// <summary>Freeze rotation and motion along all axes.</summary>
        FreezeAll = 126,
    }
}
