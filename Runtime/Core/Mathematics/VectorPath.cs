using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

namespace HookeRope.Mathematics
{
    /// <summary>
    /// Whether the core's hot loops take their <see cref="Vector{T}"/> paths (issue 18: several lanes of particles,
    /// segments or rings per operation). On by default where the runtime accelerates <see cref="Vector{T}"/>
    /// (<see cref="Vector.IsHardwareAccelerated"/>); off elsewhere, where the scalar loops run instead. Every vector path
    /// gives the same bits as its scalar loop (each lane does the scalar's operations in the scalar's order), so the
    /// switch changes speed, never results: tests turn it off to compare.
    /// </summary>
    internal static class VectorPath
    {
        /// <summary>True while the vector paths run; tests may set it (restore it afterwards).</summary>
        internal static bool Enabled = Vector.IsHardwareAccelerated;

        /// <summary>Lanes of <see cref="Vector{T}"/> of <see cref="double"/> on this runtime (4 with AVX2).</summary>
        internal static int DoubleLanes => Vector<double>.Count;

        /// <summary>Lanes of <see cref="Vector{T}"/> of <see cref="float"/> on this runtime (8 with AVX2).</summary>
        internal static int FloatLanes => Vector<float>.Count;

        /// <summary>The whole runs of <see cref="Vector{T}"/> in <paramref name="values"/> (a tail shorter than a vector is left out).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static Span<Vector<float>> AsLanes(Span<float> values) => MemoryMarshal.Cast<float, Vector<float>>(values);

        /// <summary>The whole runs of <see cref="Vector{T}"/> in <paramref name="values"/> (a tail shorter than a vector is left out).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static ReadOnlySpan<Vector<float>> AsLanes(ReadOnlySpan<float> values) => MemoryMarshal.Cast<float, Vector<float>>(values);

        /// <summary>The whole runs of <see cref="Vector{T}"/> in <paramref name="values"/> (a tail shorter than a vector is left out).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static Span<Vector<double>> AsLanes(Span<double> values) => MemoryMarshal.Cast<double, Vector<double>>(values);

        /// <summary>The whole runs of <see cref="Vector{T}"/> in <paramref name="values"/> (a tail shorter than a vector is left out).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static ReadOnlySpan<Vector<double>> AsLanes(ReadOnlySpan<double> values) => MemoryMarshal.Cast<double, Vector<double>>(values);
    }
}
