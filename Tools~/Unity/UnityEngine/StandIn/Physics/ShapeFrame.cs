using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: where the physics engine has a collider's Transform: position, rotation and lossy scale.
    /// A collider's shape (center, size, radius…) is laid out in this frame: center at Position + Rotation·(Scale ∘ center).
    /// </summary>
    internal readonly struct ShapeFrame
    {
        internal readonly Vector3 Position;
        internal readonly Quaternion Rotation;
        internal readonly Vector3 Scale;

        internal ShapeFrame(Vector3 position, Quaternion rotation, Vector3 scale)
        {
            Position = position;
            Rotation = rotation;
            Scale = scale;
        }

        /// <summary>The frame of <paramref name="t"/> now (Transform.position, rotation, lossyScale).</summary>
        internal static ShapeFrame Of(Transform t) => new ShapeFrame(t.position, t.rotation, t.lossyScale);

        /// <summary>A point given in the collider's local space (scaled, rotated, moved).</summary>
        internal Vector3 Point(Vector3 local) => Position + Rotation * Vector3.Scale(Scale, local);

        internal float AbsScale(int axis) => System.Math.Abs(axis == 0 ? Scale.x : axis == 1 ? Scale.y : Scale.z);
    }
}
