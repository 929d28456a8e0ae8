namespace HookeRope.Solver
{
    /// <summary>Shape of a <see cref="ColliderShape"/>.</summary>
    public enum ColliderKind
    {
        /// <summary>Infinite plane through the pose position; solid below, normal = rotation applied to +Y.</summary>
        Plane,
        /// <summary>Sphere of <see cref="ColliderShape.Radius"/> about the pose position.</summary>
        Sphere,
        /// <summary>Capsule: segment of half length <see cref="ColliderShape.HalfHeight"/> along local Y, swept by <see cref="ColliderShape.Radius"/>.</summary>
        Capsule,
        /// <summary>Oriented box of <see cref="ColliderShape.HalfExtents"/> about the pose position.</summary>
        Box,
    }
}
