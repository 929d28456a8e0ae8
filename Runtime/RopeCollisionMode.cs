namespace HookeRope
{
    /// <summary>Which Unity colliders the rope collides with (Sphere, Capsule and Box colliders, plus planes).</summary>
    public enum RopeCollisionMode
    {
        /// <summary>No collisions: the solver skips collision work entirely.</summary>
        Off,
        /// <summary>Only the colliders and planes listed on the component.</summary>
        ListedColliders,
        /// <summary>Sphere, Capsule and Box colliders on the chosen layers within reach of the rope when it is built, plus the listed planes.</summary>
        LayerMask,
    }
}
