using System;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: byte views of caller arrays for the buffer uploads (Mesh.SetVertexBufferData /
    /// SetIndexBufferData, Texture2D.SetPixelData). Copies without allocating; element sizes are cached per type.
    /// </summary>
    internal static class RawBytes
    {
        /// <summary>True when <typeparamref name="T"/> holds no references (Unity's "blittable" check of the upload APIs).</summary>
        internal static bool IsBlittable<T>() where T : struct => !RuntimeHelpers.IsReferenceOrContainsReferences<T>();

        /// <summary>Size in bytes of one <typeparamref name="T"/> as laid out in an array.</summary>
        internal static int SizeOf<T>() where T : struct => Size<T>.Value;

        /// <summary>The bytes of <paramref name="count"/> elements of <paramref name="data"/> from <paramref name="start"/>.</summary>
        internal static ReadOnlySpan<byte> Of<T>(T[] data, int start, int count) where T : struct =>
            MemoryMarshal.AsBytes(new ReadOnlySpan<T>(data, start, count));

        /// <summary>Copies the bytes of an array of unconstrained element type (Texture2D.SetPixelData's T[] overload) into <paramref name="destination"/>.</summary>
        internal static void CopyUnconstrained(Array source, int sourceByteOffset, byte[] destination, int destinationOffset, int byteCount)
        {
            var handle = GCHandle.Alloc(source, GCHandleType.Pinned);
            try
            {
                Marshal.Copy(handle.AddrOfPinnedObject() + sourceByteOffset, destination, destinationOffset, byteCount);
            }
            finally
            {
                handle.Free();
            }
        }

        static class Size<T> where T : struct
        {
            internal static readonly int Value = MemoryMarshal.AsBytes(new ReadOnlySpan<T>(new T[1])).Length;
        }
    }
}
