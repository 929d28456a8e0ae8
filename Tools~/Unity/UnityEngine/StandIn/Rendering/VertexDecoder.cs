using System;
using UnityEngine;
using UnityEngine.Rendering;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: reads one attribute of a raw vertex stream back as floats, for Mesh.vertices / normals.
    /// Float32 and Float16 components are decoded (Float16 by IEEE 754 binary16, as Mathf.HalfToFloat); the
    /// normalized and integer formats are outside the stand-in's subset.
    /// </summary>
    internal static class VertexDecoder
    {
        /// <summary>Component <paramref name="component"/> (0 = x) of the attribute starting at byte <paramref name="offset"/>; 0 beyond its dimension.</summary>
        internal static float Read(byte[] stream, int offset, VertexAttributeDescriptor attribute, int component)
        {
            if (component >= attribute.dimension) return 0f;
            switch (attribute.format)
            {
                case VertexAttributeFormat.Float32:
                    return BitConverter.ToSingle(stream, offset + 4 * component);
                case VertexAttributeFormat.Float16:
                    return HalfToFloat(BitConverter.ToUInt16(stream, offset + 2 * component));
                default:
                    throw StandInError.Unsupported("Mesh vertex readback of " + attribute.format + " attributes");
            }
        }

        /// <summary>Reads the first three components as a Vector3.</summary>
        internal static Vector3 ReadVector3(byte[] stream, int offset, VertexAttributeDescriptor attribute) =>
            new Vector3(Read(stream, offset, attribute, 0), Read(stream, offset, attribute, 1), Read(stream, offset, attribute, 2));

        /// <summary>IEEE 754 binary16 to binary32 (subnormals, infinities and NaN included).</summary>
        internal static float HalfToFloat(ushort half)
        {
            int sign = (half >> 15) & 1, exponent = (half >> 10) & 0x1F, mantissa = half & 0x3FF;
            float magnitude;
            if (exponent == 0) magnitude = mantissa * (1f / 16777216f); // 2^-24
            else if (exponent == 31) magnitude = mantissa == 0 ? float.PositiveInfinity : float.NaN;
            else magnitude = (1f + mantissa / 1024f) * (float)Math.Pow(2, exponent - 15);
            return sign == 1 ? -magnitude : magnitude;
        }
    }
}
