using System;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the float components of Unity's built-in value types as the serializer names them
    /// (YAML keys and SerializedProperty children): Vector3 x y z, Quaternion x y z w, Color r g b a. LayerMask is
    /// stored as m_Bits (an unsigned 32-bit mask), Bounds as m_Center and m_Extent (half the size).
    /// </summary>
    internal static class UnityStructs
    {
        static readonly string[] VectorNames = { "x", "y", "z" };
        static readonly string[] QuaternionNames = { "x", "y", "z", "w" };
        static readonly string[] ColorNames = { "r", "g", "b", "a" };

        /// <summary>Names of the float components of <paramref name="type"/>, or null when it has none.</summary>
        internal static string[] FloatComponents(Type type)
        {
            if (type == typeof(Vector3)) return VectorNames;
            if (type == typeof(Quaternion)) return QuaternionNames;
            if (type == typeof(Color)) return ColorNames;
            return null;
        }

        /// <summary>Component <paramref name="index"/> of a boxed Vector3, Quaternion or Color.</summary>
        internal static float Get(object boxed, int index)
        {
            switch (boxed)
            {
                case Vector3 v: return index == 0 ? v.x : index == 1 ? v.y : v.z;
                case Quaternion q: return index == 0 ? q.x : index == 1 ? q.y : index == 2 ? q.z : q.w;
                case Color c: return index == 0 ? c.r : index == 1 ? c.g : index == 2 ? c.b : c.a;
                default: throw new ArgumentException("not a Vector3, Quaternion or Color: " + boxed);
            }
        }

        /// <summary>A copy of a boxed Vector3, Quaternion or Color with component <paramref name="index"/> set.</summary>
        internal static object With(object boxed, int index, float value)
        {
            switch (boxed)
            {
                case Vector3 v:
                    if (index == 0) v.x = value; else if (index == 1) v.y = value; else v.z = value;
                    return v;
                case Quaternion q:
                    if (index == 0) q.x = value; else if (index == 1) q.y = value; else if (index == 2) q.z = value; else q.w = value;
                    return q;
                case Color c:
                    if (index == 0) c.r = value; else if (index == 1) c.g = value; else if (index == 2) c.b = value; else c.a = value;
                    return c;
                default: throw new ArgumentException("not a Vector3, Quaternion or Color: " + boxed);
            }
        }

        /// <summary>A boxed value of <paramref name="type"/> from its float components.</summary>
        internal static object FromFloats(Type type, float[] values)
        {
            if (type == typeof(Vector3)) return new Vector3(values[0], values[1], values[2]);
            if (type == typeof(Quaternion)) return new Quaternion(values[0], values[1], values[2], values[3]);
            if (type == typeof(Color)) return new Color(values[0], values[1], values[2], values[3]);
            throw new ArgumentException("not a Vector3, Quaternion or Color: " + type);
        }

        /// <summary>LayerMask from its serialized bits.</summary>
        internal static LayerMask Mask(uint bits) => unchecked((int)bits);

        /// <summary>Bounds from its serialized center and extent (half size).</summary>
        internal static Bounds BoundsOf(Vector3 center, Vector3 extent) => new Bounds(center, extent * 2f);
    }
}
