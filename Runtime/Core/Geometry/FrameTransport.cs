using System;
using HookeRope.Mathematics;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Parallel transport of a ring frame: the normal is rotated by the smallest rotation that takes the old
    /// tangent to the new one, so the tube does not twist; a half-turn reversal keeps the normal. The scalar forms
    /// are what the mesh's per-ring loop calls (no vector temporaries, the same operations in the same order as the
    /// <see cref="Float3"/> forms, which wrap them).
    /// </summary>
    internal static class FrameTransport
    {
        /// <summary>
        /// Transports unit <paramref name="normal"/> (perpendicular to unit <paramref name="fromTangent"/>) to a unit
        /// normal perpendicular to unit <paramref name="toTangent"/>. Never returns NaN for unit inputs.
        /// </summary>
        public static Float3 Transport(Float3 normal, Float3 fromTangent, Float3 toTangent)
        {
            return Transported(normal.X, normal.Y, normal.Z, fromTangent.X, fromTangent.Y, fromTangent.Z, toTangent.X, toTangent.Y, toTangent.Z);
        }

        /// <summary>
        /// <paramref name="candidate"/> made perpendicular to unit <paramref name="tangent"/> and unit length; when
        /// that degenerates, a unit vector perpendicular to the tangent built from the least-aligned axis.
        /// </summary>
        public static Float3 Perpendicular(Float3 candidate, Float3 tangent)
        {
            return Perpendicular(candidate.X, candidate.Y, candidate.Z, tangent.X, tangent.Y, tangent.Z);
        }

        /// <summary>Scalar <see cref="Transport(Float3, Float3, Float3)"/>: (nx, ny, nz) is transported in place from tangent f to tangent t.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        public static void Transport(ref float nx, ref float ny, ref float nz, float fx, float fy, float fz, float tx, float ty, float tz)
        {
            Float3 m = Transported(nx, ny, nz, fx, fy, fz, tx, ty, tz);
            nx = m.X; ny = m.Y; nz = m.Z;
        }

        /// <summary>
        /// <see cref="Transport(ref float, ref float, ref float, float, float, float, float, float, float)"/> by value: normal
        /// (nx, ny, nz) transported from tangent f to tangent t. A loop that carries the normal in locals calls this form,
        /// whose arguments are values (a local passed by reference lives on the stack, not in a register).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        public static Float3 Transported(float nx, float ny, float nz, float fx, float fy, float fz, float tx, float ty, float tz)
        {
            float c = fx * tx + fy * ty + fz * tz;
            if (c > -0.9999f)
            {
                // k = f × t
                Float3 m = Rotated(nx, ny, nz, c, fy * tz - fz * ty, fz * tx - fx * tz, fx * ty - fy * tx);
                nx = m.X; ny = m.Y; nz = m.Z;
            }
            return Perpendicular(nx, ny, nz, tx, ty, tz);
        }

        /// <summary>
        /// Normal n = (<paramref name="nx"/>, <paramref name="ny"/>, <paramref name="nz"/>) turned by the rotation that takes
        /// one unit tangent to the next, given by their cosine <paramref name="c"/> (&gt; −0.9999: the caller tests it) and
        /// their cross product k = (<paramref name="kx"/>, <paramref name="ky"/>, <paramref name="kz"/>):
        /// n·c + k × n + k·(k·n)/(1 + c). Returned by value, so a loop that carries n keeps it in registers.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static Float3 Rotated(float nx, float ny, float nz, float c, float kx, float ky, float kz)
        {
            float s = (kx * nx + ky * ny + kz * nz) / (1f + c);
            return new Float3(nx * c + (ky * nz - kz * ny) + kx * s, ny * c + (kz * nx - kx * nz) + ky * s, nz * c + (kx * ny - ky * nx) + kz * s);
        }

        /// <summary>The part of (<paramref name="x"/>, <paramref name="y"/>, <paramref name="z"/>) across unit tangent t: p = n − t·(n·t), not yet unit.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static Float3 Across(float x, float y, float z, float tx, float ty, float tz)
        {
            float d = x * tx + y * ty + z * tz;
            return new Float3(x - tx * d, y - ty * d, z - tz * d);
        }

        /// <summary>
        /// Whether a part across the tangent of squared length <paramref name="lengthSquared"/> can be made unit: above 1e-8
        /// and finite (a NaN fails both comparisons); else <see cref="AxisPerpendicular"/> replaces it.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static bool Usable(float lengthSquared) => lengthSquared > 1e-8f && lengthSquared < float.PositiveInfinity;

        /// <summary>
        /// Carries <paramref name="normal"/>[from − 1] (from ≥ 1) along <paramref name="tangent"/> (the same length) ring by ring:
        /// normal[i] = <see cref="Transported"/>(normal[i − 1], tangent[i − 1], tangent[i]) for i = from, from + 1, … with
        /// that method's operations in its order, as long as the re-normalisation does not degenerate. Returns the first i
        /// it did not write (tangent.Length when it wrote all): there <see cref="Perpendicular(float, float, float, float, float, float)"/>
        /// needs its out-of-line fallback, which the caller applies by <see cref="Transported"/> from that ring on. With no
        /// call in it, the loop keeps the normal and the tangent before in registers.
        /// </summary>
        public static int TransportRun(ReadOnlySpan<Float3> tangent, Span<Float3> normal, int from)
        {
            if (from >= tangent.Length) return tangent.Length;
            normal = normal.Slice(0, tangent.Length);
            Float3 n = normal[from - 1], f = tangent[from - 1];
            float nx = n.X, ny = n.Y, nz = n.Z, fx = f.X, fy = f.Y, fz = f.Z;
            int i = from;
            for (; i < tangent.Length; i++)
            {
                Float3 t = tangent[i];
                float tx = t.X, ty = t.Y, tz = t.Z;
                float c = fx * tx + fy * ty + fz * tz;
                if (c > -0.9999f)
                {
                    Float3 m = Rotated(nx, ny, nz, c, fy * tz - fz * ty, fz * tx - fx * tz, fx * ty - fy * tx);
                    nx = m.X; ny = m.Y; nz = m.Z;
                }
                // Perpendicular without its out-of-line fallback, which ends the run
                Float3 p = Across(nx, ny, nz, tx, ty, tz);
                float lengthSquared = p.LengthSquared;
                if (!Usable(lengthSquared)) break;
                float inverse = 1f / MathF.Sqrt(lengthSquared);
                nx = p.X * inverse; ny = p.Y * inverse; nz = p.Z * inverse;
                normal[i] = new Float3(nx, ny, nz);
                fx = tx; fy = ty; fz = tz;
            }
            return i;
        }

        /// <summary>
        /// <see cref="TransportRun(ReadOnlySpan{Float3}, Span{Float3}, int)"/> with what depends on the tangents alone
        /// formed before, per ring i (the pair i − 1, i): <paramref name="cosine"/>[i] = t_{i−1}·t_i and k = t_{i−1} × t_i in
        /// <paramref name="kx"/>, <paramref name="ky"/>, <paramref name="kz"/> (each by <see cref="Transported"/>'s operations
        /// in its order, so the same bits); the loop then carries only the normal. Returns as that method does.
        /// </summary>
        public static int TransportRun(ReadOnlySpan<Float3> tangent, Span<Float3> normal, int from,
            ReadOnlySpan<float> cosine, ReadOnlySpan<float> kx, ReadOnlySpan<float> ky, ReadOnlySpan<float> kz)
        {
            if (from >= tangent.Length) return tangent.Length;
            int count = tangent.Length - from;
            // the rings from `from` on, indexed from 0 (spans of one length: no range checks in the loop)
            ReadOnlySpan<Float3> t = tangent.Slice(from, count);
            Span<Float3> written = normal.Slice(from, count).Slice(0, t.Length);
            ReadOnlySpan<float> cs = cosine.Slice(from, count).Slice(0, t.Length);
            ReadOnlySpan<float> ax = kx.Slice(from, count).Slice(0, t.Length), ay = ky.Slice(from, count).Slice(0, t.Length), az = kz.Slice(from, count).Slice(0, t.Length);
            Float3 n = normal[from - 1];
            float nx = n.X, ny = n.Y, nz = n.Z;
            int i = 0;
            for (; i < t.Length; i++)
            {
                float c = cs[i];
                if (c > -0.9999f)
                {
                    Float3 m = Rotated(nx, ny, nz, c, ax[i], ay[i], az[i]);
                    nx = m.X; ny = m.Y; nz = m.Z;
                }
                Float3 ti = t[i];
                Float3 p = Across(nx, ny, nz, ti.X, ti.Y, ti.Z);
                float lengthSquared = p.LengthSquared;
                if (!Usable(lengthSquared)) break;
                float inverse = 1f / MathF.Sqrt(lengthSquared);
                nx = p.X * inverse; ny = p.Y * inverse; nz = p.Z * inverse;
                written[i] = new Float3(nx, ny, nz);
            }
            return from + i;
        }

        /// <summary>Scalar <see cref="Perpendicular(Float3, Float3)"/>: (x, y, z) made unit and perpendicular to unit tangent t in place.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        public static void Perpendicular(ref float x, ref float y, ref float z, float tx, float ty, float tz)
        {
            Float3 p = Perpendicular(x, y, z, tx, ty, tz);
            x = p.X; y = p.Y; z = p.Z;
        }

        /// <summary>The value form of <see cref="Perpendicular(ref float, ref float, ref float, float, float, float)"/>: (x, y, z) made unit and perpendicular to unit tangent t.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        public static Float3 Perpendicular(float x, float y, float z, float tx, float ty, float tz)
        {
            Float3 p = Across(x, y, z, tx, ty, tz);
            float lengthSquared = p.LengthSquared;
            if (Usable(lengthSquared))
            {
                float inverse = 1f / System.MathF.Sqrt(lengthSquared);
                return new Float3(p.X * inverse, p.Y * inverse, p.Z * inverse);
            }
            return AxisPerpendicular(tx, ty, tz);
        }

        /// <summary><see cref="Perpendicular(float, float, float, float, float, float)"/>'s fallback, out of line (the callers' loops rarely need it): the least-aligned axis made perpendicular to t.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        private static Float3 AxisPerpendicular(float tx, float ty, float tz)
        {
            float ax = System.MathF.Abs(tx), ay = System.MathF.Abs(ty), az = System.MathF.Abs(tz);
            float qx = 0f, qy = 0f, qz = 0f;
            if (ax <= ay && ax <= az) qx = 1f; else if (ay <= az) qy = 1f; else qz = 1f;
            float e = qx * tx + qy * ty + qz * tz;
            qx -= tx * e; qy -= ty * e; qz -= tz * e;
            float q2 = qx * qx + qy * qy + qz * qz;
            if (q2 > 1e-20f)
            {
                float inverse = 1f / System.MathF.Sqrt(q2);
                return new Float3(qx * inverse, qy * inverse, qz * inverse);
            }
            return new Float3(1f, 0f, 0f);
        }
    }
}
