using System;
using System.Numerics;
using System.Runtime.InteropServices;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// The builds into vertices without tangents (<see cref="LeanTubeVertex"/>, 32 bytes): where the ring writers go by
    /// the kind of buffer the build was given, and the ring kernel of that kind. Every float is computed by the same
    /// operations on the same numbers as the field of the same name of the <see cref="TubeVertex"/> kernels
    /// (<see cref="WriteRing"/>), so the two kinds of build agree bit for bit but for the tangent, which is not written.
    /// </summary>
    internal sealed partial class TubeMeshBuilder
    {
        // per side (the seam too): (−0, −0, u, 0), the addend per side of the 4-float kernel's second vector (see WriteLeanRings)
        private Vector4[] leanSideU;
        // per side (the seam too), where Vector<float> has 8 lanes: cos in every lane but u's, which holds u; sin in every lane
        private LeanLanes[] leanLanes;
        // the wide kernel's coefficient vectors B, C, A, O of the ring in hand (no allocation per build)
        private readonly Vector<float>[] leanCoefficients = new Vector<float>[4];

        /// <summary>Ring <paramref name="k"/>'s radial + 1 vertices into the build's buffer from vertex <paramref name="at"/>.</summary>
        private void WriteRingAt(int k, int at) => WriteRingsAt(k, k, at);

        /// <summary>Rings <paramref name="first"/> … <paramref name="last"/>, radial + 1 vertices each, into the build's buffer from vertex <paramref name="at"/>.</summary>
        private void WriteRingsAt(int first, int last, int at)
        {
            int length = (last - first + 1) * (radial + 1);
            if (leanOut != null) WriteLeanRings(first, last, new Span<LeanTubeVertex>(leanOut, at, length));
            else WriteRings(first, last, new Span<TubeVertex>(fullOut, at, length));
        }

        /// <summary><see cref="WriteRingOnStrips"/> of ring <paramref name="k"/> into the build's buffer from vertex <paramref name="at"/>.</summary>
        private void WriteRingOnStripsAt(int k, int first, int last, in Neighbour beforeFirst, in Neighbour afterLast, int at)
        {
            if (leanOut == null)
            {
                WriteRingOnStrips(k, first, last, beforeFirst, afterLast, new Span<TubeVertex>(fullOut, at, radial + 1));
                return;
            }
            // the ring in the full layout first, in the cap rims' scratch ring (WriteCap uses it only within itself)
            WriteRingOnStrips(k, first, last, beforeFirst, afterLast, capRim);
            Span<LeanTubeVertex> ring = new Span<LeanTubeVertex>(leanOut, at, radial + 1);
            ReadOnlySpan<TubeVertex> written = capRim;
            written = written.Slice(0, ring.Length);
            for (int i = 0; i < ring.Length; i++)
            {
                ref readonly TubeVertex from = ref written[i];
                ref LeanTubeVertex to = ref ring[i];
                to.PX = from.PX; to.PY = from.PY; to.PZ = from.PZ;
                to.NX = from.NX; to.NY = from.NY; to.NZ = from.NZ;
                to.U = from.U; to.V = from.V;
            }
        }

        /// <summary>The tables of the lean kernel, made with the builder's other side tables (at construction).</summary>
        private void MakeLeanTables()
        {
            ReadOnlySpan<SideLanes> sides = sideLanes;
            leanSideU = new Vector4[sides.Length];
            for (int i = 0; i < sides.Length; i++) leanSideU[i] = new Vector4(-0f, -0f, sides[i].U.Z, 0f);
            if (Vector<float>.Count != 8) return;
            leanLanes = new LeanLanes[sides.Length];
            Span<float> cos = stackalloc float[8];
            for (int i = 0; i < sides.Length; i++)
            {
                cos.Fill(sides[i].Cos.X);
                cos[6] = sides[i].U.Z;
                leanLanes[i] = new LeanLanes(new Vector<float>(cos), new Vector<float>(sides[i].Sin.X));
            }
            leanSixteenSided = sides.Length == SixteenSidedVertices;
            if (leanSixteenSided) leanSixteen = MemoryMarshal.Cast<LeanLanes, LeanSixteenLanes>(new Span<LeanLanes>(leanLanes))[0];
        }

        /// <summary>
        /// The ring kernel of lean vertices, for rings <paramref name="first"/> … <paramref name="last"/>, each into the
        /// next radial + 1 vertices of <paramref name="rings"/>. With 8-float vectors (and the vector paths on) a vertex is
        /// one vector, ((B·cos + C·sin) + A) + O, B, C, A, O per ring in the vertex's lane pattern (position, normal, u, v;
        /// O the frame origin on the position lanes, +0 on the normal's x as in the full kernel, −0 elsewhere) and cos, sin
        /// per side from <see cref="leanLanes"/> (u in the cos lane under u, whose coefficient is 1): 2 multiplications, 3
        /// additions and one store a vertex, against 3 vector stores per 2 vertices of 48 bytes. Otherwise two 4-float
        /// vectors: the full kernel's first, and (normal.yz, u, v) from the full kernel's coefficients of those floats.
        /// </summary>
        private void WriteLeanRings(int first, int last, Span<LeanTubeVertex> rings)
        {
            bool wide = Vector<float>.Count == 8 && VectorPath.Enabled;
            int stride = radial + 1;
            var o0 = new Vector4(frameOrigin.X, frameOrigin.Y, frameOrigin.Z, 0f);
            // the scratch's views of constant length: their constant indices need no range check (the 8 halves only
            // where the 4 vectors have 8 lanes: with 4 lanes they are 4 halves, and the 4-float kernel needs none)
            Span<Vector<float>> q = new Span<Vector<float>>(leanCoefficients, 0, 4);
            Span<Vector4> half = wide ? MemoryMarshal.Cast<Vector<float>, Vector4>(q).Slice(0, 8) : default;
            bool sixteen = wide && leanSixteenSided;
            if (wide)
            {
                half[6] = o0;
                half[7] = new Vector4(-0f);
            }
            ReadOnlySpan<SideLanes> sides = new ReadOnlySpan<SideLanes>(sideLanes, 0, stride);
            ReadOnlySpan<Vector4> sideU = new ReadOnlySpan<Vector4>(leanSideU, 0, stride);
            int count = last - first + 1;
            ReadOnlySpan<Float3> centre = new ReadOnlySpan<Float3>(centers, first, count);
            ReadOnlySpan<Float3> tangent = new ReadOnlySpan<Float3>(tangents, first, count).Slice(0, centre.Length);
            ReadOnlySpan<Float3> normal = new ReadOnlySpan<Float3>(normals, first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> radius = new ReadOnlySpan<float>(ringRadii, first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> slopeOf = new ReadOnlySpan<float>(slopes, first, count).Slice(0, centre.Length);
            ReadOnlySpan<float> vOf = new ReadOnlySpan<float>(ringV, first, count).Slice(0, centre.Length);
            for (int k = 0, at = 0; k < centre.Length; k++, at += stride)
            {
                RingCoefficients(centre[k], tangent[k], normal[k], radius[k], slopeOf[k],
                    out Vector4 a0, out Vector4 b0, out Vector4 c0, out Vector4 a1, out Vector4 b1, out Vector4 c1, out _, out _);
                float v = vOf[k];
                Span<LeanTubeVertex> ring = rings.Slice(at, stride);
                if (wide)
                {
                    half[0] = b0; half[1] = new Vector4(b1.X, b1.Y, 1f, 0f);
                    half[2] = c0; half[3] = new Vector4(c1.X, c1.Y, 0f, 0f);
                    half[4] = a0; half[5] = new Vector4(a1.X, a1.Y, -0f, v + 0f);
                    if (sixteen) WriteLeanSixteen(ref MemoryMarshal.Cast<LeanTubeVertex, LeanSixteenSidedRing>(ring)[0], in leanSixteen, q[0], q[1], q[2], q[3]);
                    else WriteLeanLanes(MemoryMarshal.Cast<LeanTubeVertex, Vector<float>>(ring), leanLanes, q);
                    continue;
                }
                var bL = new Vector4(b1.X, b1.Y, 0f, 0f);
                var cL = new Vector4(c1.X, c1.Y, 0f, 0f);
                var aL = new Vector4(a1.X, a1.Y, 0f, v);
                Span<VertexLeanLanes> vertices = MemoryMarshal.Cast<LeanTubeVertex, VertexLeanLanes>(ring);
                for (int i = 0; i < vertices.Length; i++)
                {
                    ref readonly SideLanes side = ref sides[i];
                    ref VertexLeanLanes vertex = ref vertices[i];
                    Vector4 ci = side.Cos, si = side.Sin;
                    vertex.First = ((b0 * ci + c0 * si) + a0) + o0;
                    vertex.Second = (bL * ci + cL * si) + (aL + sideU[i]);
                }
            }
        }

        /// <summary>
        /// The wide lean loop of <see cref="WriteLeanRings"/>: one vertex per side, the ring's coefficient vectors from
        /// <paramref name="q"/> (B, C, A, O) in registers through the loop.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static void WriteLeanLanes(Span<Vector<float>> vertices, ReadOnlySpan<LeanLanes> sides, Span<Vector<float>> q)
        {
            Vector<float> b = q[0], c = q[1], a = q[2], o = q[3];
            sides = sides.Slice(0, vertices.Length);
            for (int i = 0; i < sides.Length; i++)
            {
                ref readonly LeanLanes side = ref sides[i];
                vertices[i] = ((b * side.Cos + c * side.Sin) + a) + o;
            }
        }

        /// <summary>
        /// <see cref="WriteLeanLanes"/> of 16 sides (the default), written out: the 17 vertices (the seam computed from its
        /// own table entry, cos 1, sin 0, u 1, like every other) at constant offsets from the ring and the table, no loop
        /// counter and no range check.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static void WriteLeanSixteen(ref LeanSixteenSidedRing ring, in LeanSixteenLanes t, Vector<float> b, Vector<float> c, Vector<float> a, Vector<float> o)
        {
            ring.V0 = ((b * t.S0.Cos + c * t.S0.Sin) + a) + o;
            ring.V1 = ((b * t.S1.Cos + c * t.S1.Sin) + a) + o;
            ring.V2 = ((b * t.S2.Cos + c * t.S2.Sin) + a) + o;
            ring.V3 = ((b * t.S3.Cos + c * t.S3.Sin) + a) + o;
            ring.V4 = ((b * t.S4.Cos + c * t.S4.Sin) + a) + o;
            ring.V5 = ((b * t.S5.Cos + c * t.S5.Sin) + a) + o;
            ring.V6 = ((b * t.S6.Cos + c * t.S6.Sin) + a) + o;
            ring.V7 = ((b * t.S7.Cos + c * t.S7.Sin) + a) + o;
            ring.V8 = ((b * t.S8.Cos + c * t.S8.Sin) + a) + o;
            ring.V9 = ((b * t.S9.Cos + c * t.S9.Sin) + a) + o;
            ring.V10 = ((b * t.S10.Cos + c * t.S10.Sin) + a) + o;
            ring.V11 = ((b * t.S11.Cos + c * t.S11.Sin) + a) + o;
            ring.V12 = ((b * t.S12.Cos + c * t.S12.Sin) + a) + o;
            ring.V13 = ((b * t.S13.Cos + c * t.S13.Sin) + a) + o;
            ring.V14 = ((b * t.S14.Cos + c * t.S14.Sin) + a) + o;
            ring.V15 = ((b * t.S15.Cos + c * t.S15.Sin) + a) + o;
            ring.V16 = ((b * t.S16.Cos + c * t.S16.Sin) + a) + o;
        }

        /// <summary>Vertices of a 16-sided ring (the seam duplicated).</summary>
        private const int SixteenSidedVertices = 17;

        // the wide lean kernel's table of 16 sides (WriteLeanSixteen), set with leanLanes where it applies
        private LeanSixteenLanes leanSixteen;
        private bool leanSixteenSided;

        /// <summary>The 17 lean vertices of a 16-sided ring as the wide lean kernel writes them.</summary>
        [StructLayout(LayoutKind.Sequential)]
        private struct LeanSixteenSidedRing
        {
            public Vector<float> V0, V1, V2, V3, V4, V5, V6, V7, V8, V9, V10, V11, V12, V13, V14, V15, V16;
        }

        /// <summary>The 17 entries of the lean table of 16 sides (<see cref="leanLanes"/>), read at constant offsets.</summary>
        [StructLayout(LayoutKind.Sequential)]
        private struct LeanSixteenLanes
        {
            public LeanLanes S0, S1, S2, S3, S4, S5, S6, S7, S8, S9, S10, S11, S12, S13, S14, S15, S16;
        }

        /// <summary>The wide lean kernel's table entry of one side: cos (u in the lane under u) and sin.</summary>
        private readonly struct LeanLanes
        {
            public readonly Vector<float> Cos, Sin;

            public LeanLanes(Vector<float> cos, Vector<float> sin)
            {
                Cos = cos;
                Sin = sin;
            }
        }

        /// <summary>A <see cref="LeanTubeVertex"/> as the 4-float kernel writes it: position.xyz normal.x | normal.yz u v.</summary>
        [StructLayout(LayoutKind.Sequential)]
        private struct VertexLeanLanes
        {
            public Vector4 First, Second;
        }
    }
}
