using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>
    /// The inspector's static-sag preview of an <see cref="ElasticRope"/>, computed in edit mode without entering
    /// Play: a detached core simulation of the rope's current settings and attachment poses (the same build path as
    /// <see cref="ElasticRope.Rebuild"/>) relaxes with its velocities damped, and the settled particle positions are
    /// kept for the scene gizmo and
    /// <see cref="RopeMeshRenderer"/>'s edit-mode mesh (runtime side: RopeStaticSag), recomputed when an end moves.
    /// </summary>
    public static class StaticSagPreview
    {
        /// <summary>
        /// Computes the static sag of <paramref name="rope"/>'s current settings between its current attachment
        /// positions: a separate core rope relaxes for <paramref name="seconds"/> of simulated time (s) with its
        /// velocities scaled by 0.85 every 1/60 s step (a near-critical damping of the swing of a metre-scale rope),
        /// so it settles into the static shape; long ropes swing slowly and need more seconds. Returns the particle
        /// positions in world space (m), also kept for <see cref="Get"/> and drawn by <see cref="RopeMeshRenderer"/>
        /// in edit mode. The component itself is not built.
        /// </summary>
        public static Vector3[] Compute(ElasticRope rope, float seconds = 6f) => RopeStaticSag.Compute(rope, seconds);

        /// <summary>
        /// The last preview computed for <paramref name="rope"/> (world, m), or an empty array. When an end moved or
        /// the segment count changed since, the preview is first recomputed (same relaxation time), so it follows
        /// dragged ends.
        /// </summary>
        public static Vector3[] Get(ElasticRope rope) => RopeStaticSag.GetFollowing(rope);
    }
}
