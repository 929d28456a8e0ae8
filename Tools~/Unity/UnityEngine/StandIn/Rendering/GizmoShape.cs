namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: the Gizmos draw calls the stand-in records.</summary>
    internal enum GizmoShape
    {
        /// <summary>Gizmos.DrawLine.</summary>
        Line,
        /// <summary>Gizmos.DrawWireSphere.</summary>
        WireSphere,
        /// <summary>Gizmos.DrawSphere.</summary>
        Sphere,
    }
}
