using HookeRope.Mathematics;
using UnityEngine;

namespace HookeRope
{
    /// <summary>Field-by-field conversions between Unity's vector types and the engine-free core's.</summary>
    internal static class UnityConversions
    {
        /// <summary>Unity vector to core vector (same units).</summary>
        public static Float3 ToFloat3(this Vector3 v) => new Float3(v.x, v.y, v.z);

        /// <summary>Core vector to Unity vector (same units).</summary>
        public static Vector3 ToVector3(this Float3 v) => new Vector3(v.X, v.Y, v.Z);

        /// <summary>World point (m) to a core vector in the frame whose origin is <paramref name="origin"/> (world axes, m).</summary>
        public static Float3 RelativeTo(this Vector3 world, Vector3 origin) =>
            new Float3(world.x - origin.x, world.y - origin.y, world.z - origin.z);

        /// <summary>Unity rotation to core rotation.</summary>
        public static Quat ToQuat(this Quaternion q) => new Quat(q.x, q.y, q.z, q.w);
    }
}
