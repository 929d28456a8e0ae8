using System;
using UnityEngine.Rendering;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: a Mesh's raw index buffer (UInt16 or UInt32 little-endian indices), as set by
    /// Mesh.SetIndexBufferParams / SetIndexBufferData.
    /// </summary>
    internal sealed class IndexBuffer
    {
        byte[] _bytes = Array.Empty<byte>();

        /// <summary>Format of the indices.</summary>
        internal IndexFormat Format { get; private set; } = IndexFormat.UInt16;

        /// <summary>Number of indices.</summary>
        internal int Count { get; private set; }

        /// <summary>Bytes per index of <paramref name="format"/>.</summary>
        internal static int IndexSize(IndexFormat format) => format == IndexFormat.UInt32 ? 4 : 2;

        /// <summary>The raw bytes (length Count × index size).</summary>
        internal byte[] Bytes => _bytes;

        /// <summary>Resizes to <paramref name="count"/> indices of <paramref name="format"/>; keeps the existing indices that fit when the format is unchanged.</summary>
        internal void Resize(int count, IndexFormat format)
        {
            var bytes = new byte[count * IndexSize(format)];
            if (format == Format) Buffer.BlockCopy(_bytes, 0, bytes, 0, Math.Min(_bytes.Length, bytes.Length));
            _bytes = bytes;
            Format = format;
            Count = count;
        }

        /// <summary>Truncates to the first <paramref name="count"/> indices (Mesh.subMeshCount shrinking).</summary>
        internal void Truncate(int count)
        {
            if (count >= Count) return;
            Array.Resize(ref _bytes, count * IndexSize(Format));
            Count = count;
        }

        /// <summary>Index number <paramref name="i"/>.</summary>
        internal int this[int i] =>
            Format == IndexFormat.UInt32 ? (int)BitConverter.ToUInt32(_bytes, 4 * i) : BitConverter.ToUInt16(_bytes, 2 * i);
    }
}
