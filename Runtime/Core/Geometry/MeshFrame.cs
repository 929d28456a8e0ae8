using System;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Where the frame of the positions given to
    /// <see cref="RopeSimulation.FillMesh(ReadOnlySpan{float}, ReadOnlySpan{float}, ReadOnlySpan{float}, TubeVertex[], int[], float, MeshFrame)"/>
    /// (e.g. a renderer's local space) sits in the rope's world frame, the frame of <see cref="Solver.Rope.Origin"/> and of
    /// the rope's colliders: a point p of that frame is at <see cref="Origin"/> + <see cref="Rotation"/> · (<see cref="Scale"/> · p).
    /// A similarity (rotation, uniform scale, translation), so the mesh can keep the drawn tube out of the colliders in
    /// any such frame.
    /// </summary>
    public readonly struct MeshFrame
    {
        /// <summary>Position (m, rope world frame) of the caller frame's origin.</summary>
        public readonly Float3 Origin;

        /// <summary>Rotation of the caller frame's axes in the rope world frame (unit quaternion).</summary>
        public readonly Quat Rotation;

        /// <summary>Metres in the rope world frame per unit of the caller frame (finite, non-zero; negative mirrors through the origin).</summary>
        public readonly float Scale;

        /// <summary>
        /// The frame at <paramref name="origin"/> (m) rotated by <paramref name="rotation"/> (normalised here) and scaled
        /// by <paramref name="scale"/> (m per caller unit). Throws ArgumentException when a value is not finite, the
        /// rotation is zero or the scale is zero.
        /// </summary>
        public MeshFrame(Float3 origin, Quat rotation, float scale)
        {
            if (!origin.IsFinite) throw new ArgumentException("origin must be finite.", nameof(origin));
            if (!rotation.IsFinite || !(rotation.LengthSquared > 1e-12f))
                throw new ArgumentException("rotation must be a finite, non-zero quaternion.", nameof(rotation));
            if (!float.IsFinite(scale) || scale == 0f)
                throw new ArgumentOutOfRangeException(nameof(scale), scale, "scale must be finite and non-zero: (-inf, 0) or (0, +inf).");
            Origin = origin;
            Rotation = rotation.Normalized();
            Scale = scale;
        }

        /// <summary>A frame only shifted by <paramref name="origin"/> (m): no rotation, scale 1.</summary>
        public static MeshFrame Shifted(Float3 origin) => new MeshFrame(origin, Quat.Identity, 1f);

        /// <summary>The rope-world position (m) of point <paramref name="p"/> given in the caller frame.</summary>
        internal Float3 ToWorld(Float3 p) => Origin + DisplacementToWorld(p);

        /// <summary>A caller-frame displacement <paramref name="v"/> expressed in the rope world frame (m).</summary>
        internal Float3 DisplacementToWorld(Float3 v) => Rotation.Rotate(v * Scale);

        /// <summary>A rope-world displacement <paramref name="v"/> (m) expressed in the caller frame.</summary>
        internal Float3 DisplacementFromWorld(Float3 v) => Rotation.Conjugate.Rotate(v) * (1f / Scale);
    }
}
