using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// The <see cref="Vector{T}"/> paths of the per-particle and per-segment passes of a substep (issue 18), taken while
    /// <see cref="VectorPath.Enabled"/>: the BDF2 prediction, the second-order velocities, the position commit, the violence
    /// test and the tensions. A block is one <see cref="Vector{T}"/> of <see cref="float"/> (8 particles with AVX2), its
    /// doubles two <see cref="Vector{T}"/> of <see cref="double"/>; floats are widened to double and doubles narrowed to
    /// float exactly as the scalar casts do (IEEE conversions, round to nearest). Each lane does its scalar loop's operations
    /// in the scalar's order (no fused multiply-add, no reassociation), so the bits are the scalar loop's. A block with a
    /// kinematic particle takes the free particles' lanes and is then set as the scalar loop sets it (its scalar branch reads
    /// nothing the lanes wrote); a block whose commit is not finite and the tail after the last full block run the scalar loop.
    /// </summary>
    public sealed partial class Rope
    {
        /// <summary>Δ's start mark 0 − (q + 0) per lane, as <see cref="StartMark"/> of (q, 0f) computes it.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<double> StartMarks(Vector<double> q) => Vector<double>.Zero + new Vector<double>(-1.0) * (q + Vector<double>.Zero);

        /// <summary>Sign-flipped lanes (−x exactly, as the scalar negation: not 0 − x, which turns −0 into +0).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<double> Negated(Vector<double> x) =>
            Vector.AsVectorDouble(Vector.Xor(Vector.AsVectorUInt64(x), new Vector<ulong>(0x8000000000000000UL)));

        /// <summary>True when every lane is finite (x − x is +0 exactly for a finite x, NaN otherwise).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool AllFinite(Vector<double> x) => Vector.EqualsAll(x - x, Vector<double>.Zero);

        /// <summary>
        /// The BDF2 prediction (<see cref="PredictSecondOrderRange{TSize}"/> with scheme BDF2) on lanes: every full block here
        /// (its kinematic particles then set as the scalar branch sets them), the tail by the scalar loop. Returns <see cref="ChainState.Size"/> when TSize is
        /// <see cref="Sized"/> (the largest magnitude is the same whatever the order the coordinates are compared in).
        /// </summary>
        private float PredictSecondOrderLanes<TSize>(double h, Float3 g, bool markSolveStart) where TSize : struct
        {
            int n = chain.ParticleCount, width = Vector<float>.Count;
            double invH = 1.0 / h, h2 = h * h, c = 4.0 * h2 / 9.0, e = 2.0 * h / 3.0;
            Vector<float> lanes = Vector<float>.Zero;
            lanes = PredictLanes<TSize>(n, chain.X, chain.PrevX, chain.VelX, chain.PrevVelX, chain.DX, chain.DLowX, chain.BaseVelX, chain.PredictedDX, invH, e, e * g.X, c * g.X, lanes);
            lanes = PredictLanes<TSize>(n, chain.Y, chain.PrevY, chain.VelY, chain.PrevVelY, chain.DY, chain.DLowY, chain.BaseVelY, chain.PredictedDY, invH, e, e * g.Y, c * g.Y, lanes);
            lanes = PredictLanes<TSize>(n, chain.Z, chain.PrevZ, chain.VelZ, chain.PrevVelZ, chain.DZ, chain.DLowZ, chain.BaseVelZ, chain.PredictedDZ, invH, e, e * g.Z, c * g.Z, lanes);
            int full = n / width * width;
            // the kinematic particles the lanes took (from the list, not a scan of the flags)
            ReadOnlySpan<int> fixedParticles = chain.KinematicIndices;
            for (int q = 0; q < fixedParticles.Length; q++)
                if (fixedParticles[q] < full) PredictKinematic(fixedParticles[q], markSolveStart);
            float size = n - full == 1 ? PredictSecondOrderParticle<TSize>(TimeIntegrator.Bdf2, h, g, markSolveStart, full)
                : full < n ? PredictSecondOrderRange<TSize>(TimeIntegrator.Bdf2, h, g, markSolveStart, full, n - full, 0f) : 0f;
            if (typeof(TSize) == typeof(Sized))
                for (int l = 0; l < width; l++) if (lanes[l] > size) size = lanes[l];
            return size;
        }

        /// <summary>
        /// One coordinate of the BDF2 prediction on the full blocks, every particle as a free one (e = 2h/3; eg = e·g and cg = 4h²/9·g of
        /// this coordinate, as the scalar loop's products): x_prev = x, v_prev = v, d = d_pred, DLow = 0, the velocity base.
        /// Returns size raised lane by lane to the coordinates' magnitudes (TSize <see cref="Sized"/>; plain compares, as <see cref="Larger"/>).
        /// </summary>
        private static Vector<float> PredictLanes<TSize>(int n, float[] x, float[] px, double[] v, double[] u, float[] d, float[] low,
            double[] b, float[] q, double invH, double e, double eg, double cg, Vector<float> size) where TSize : struct
        {
            ReadOnlySpan<Vector<float>> xs = MemoryMarshal.Cast<float, Vector<float>>(ChainState.Exactly(x, n));
            Span<Vector<float>> ps = MemoryMarshal.Cast<float, Vector<float>>(ChainState.Exactly(px, n));
            Span<Vector<float>> ds = MemoryMarshal.Cast<float, Vector<float>>(ChainState.Exactly(d, n));
            Span<Vector<float>> ls = MemoryMarshal.Cast<float, Vector<float>>(ChainState.Exactly(low, n));
            Span<Vector<float>> qs = MemoryMarshal.Cast<float, Vector<float>>(ChainState.Exactly(q, n));
            ReadOnlySpan<Vector<double>> vs = MemoryMarshal.Cast<double, Vector<double>>(ChainState.Exactly(v, n));
            Span<Vector<double>> us = MemoryMarshal.Cast<double, Vector<double>>(ChainState.Exactly(u, n));
            Span<Vector<double>> bs = MemoryMarshal.Cast<double, Vector<double>>(ChainState.Exactly(b, n));
            var four = new Vector<double>(4.0);
            var three = new Vector<double>(3.0);
            // the coordinate's factors broadcast once, not per run
            Vector<double> ev = new Vector<double>(e), egv = new Vector<double>(eg), cgv = new Vector<double>(cg), invHv = new Vector<double>(invH);
            for (int k = 0; k < xs.Length; k++)
            {
                Vector<float> xk = xs[k];
                ps[k] = xk;
                if (typeof(TSize) == typeof(Sized))
                {
                    Vector<float> magnitude = Vector.Abs(xk);
                    size = Vector.ConditionalSelect(Vector.GreaterThan(magnitude, size), magnitude, size);
                }
                int a = 2 * k, z = a + 1;
                Vector<double> w0 = vs[a], w1 = vs[z];
                // m = (4v − v_prev)/3; d_pred = (D + DLow)/3 + e·m + c·g, rounded to float; base = m + e·g − d_pred/h
                Vector<double> m0 = (four * w0 - us[a]) / three, m1 = (four * w1 - us[z]) / three;
                ChainState.Widen(ds[k], out Vector<double> d0, out Vector<double> d1);
                ChainState.Widen(ls[k], out Vector<double> l0, out Vector<double> l1);
                Vector<float> o = Vector.Narrow((d0 + l0) / three + ev * m0 + cgv, (d1 + l1) / three + ev * m1 + cgv);
                ChainState.Widen(o, out Vector<double> o0, out Vector<double> o1);
                bs[a] = m0 + egv - o0 * invHv;
                bs[z] = m1 + egv - o1 * invHv;
                ds[k] = o;
                ls[k] = Vector<float>.Zero;
                us[a] = w0; us[z] = w1;
                qs[k] = o;
            }
            return size;
        }

        /// <summary>
        /// The scalar prediction's kinematic branch for particle i after the lanes took it as a free one (they already wrote
        /// x_prev = x and v_prev = v): no displacement, no velocity base, and the Δ start mark when <paramref name="markSolveStart"/>.
        /// </summary>
        private void PredictKinematic(int i, bool markSolveStart)
        {
            chain.DX[i] = 0f; chain.DY[i] = 0f; chain.DZ[i] = 0f;
            chain.DLowX[i] = 0f; chain.DLowY[i] = 0f; chain.DLowZ[i] = 0f;
            chain.PredictedDX[i] = 0f; chain.PredictedDY[i] = 0f; chain.PredictedDZ[i] = 0f;
            chain.BaseVelX[i] = 0.0; chain.BaseVelY[i] = 0.0; chain.BaseVelZ[i] = 0.0;
            if (markSolveStart) { chain.SolveDX[i] = StartMark(0f, 0f); chain.SolveDY[i] = StartMark(0f, 0f); chain.SolveDZ[i] = StartMark(0f, 0f); }
        }

        /// <summary>
        /// <see cref="SecondOrderVelocitiesRange{TMark}"/> on lanes: every full block here as free particles, then each
        /// kinematic particle as the scalar branch sets it (<see cref="KinematicVelocity{TMark}"/>), the tail by the scalar loop.
        /// </summary>
        private void SecondOrderVelocityLanes<TMark>(TimeIntegrator scheme, double h) where TMark : struct
        {
            int n = chain.ParticleCount, width = Vector<float>.Count;
            double invH = 1.0 / h, k = scheme == TimeIntegrator.Bdf2 ? 0.5 * invH : 0.0;
            ReadOnlySpan<Vector<float>> dx = Floats(chain.DX, n), dy = Floats(chain.DY, n), dz = Floats(chain.DZ, n);
            ReadOnlySpan<Vector<float>> lx = Floats(chain.DLowX, n), ly = Floats(chain.DLowY, n), lz = Floats(chain.DLowZ, n);
            ReadOnlySpan<Vector<float>> qx = Floats(chain.PredictedDX, n), qy = Floats(chain.PredictedDY, n), qz = Floats(chain.PredictedDZ, n);
            Span<Vector<double>> wx = Doubles(chain.PrevVelX, n), wy = Doubles(chain.PrevVelY, n), wz = Doubles(chain.PrevVelZ, n);
            ReadOnlySpan<Vector<double>> sx = Doubles(chain.SolveDX, n), sy = Doubles(chain.SolveDY, n), sz = Doubles(chain.SolveDZ, n);
            ReadOnlySpan<Vector<double>> bx = Doubles(chain.BaseVelX, n), by = Doubles(chain.BaseVelY, n), bz = Doubles(chain.BaseVelZ, n);
            Span<Vector<double>> vx = Doubles(chain.VelX, n), vy = Doubles(chain.VelY, n), vz = Doubles(chain.VelZ, n);
            // 1/h and κ broadcast once, not per run and coordinate
            Vector<double> invHv = new Vector<double>(invH), kv = new Vector<double>(k);
            for (int b = 0; b < dx.Length; b++)
            {
                int a = 2 * b, z = a + 1;
                VelocityLanes<TMark>(b, dx[b], lx[b], qx[b], sx, bx, vx, invHv, kv, out Vector<double> cx0, out Vector<double> cx1);
                VelocityLanes<TMark>(b, dy[b], ly[b], qy[b], sy, by, vy, invHv, kv, out Vector<double> cy0, out Vector<double> cy1);
                VelocityLanes<TMark>(b, dz[b], lz[b], qz[b], sz, bz, vz, invHv, kv, out Vector<double> cz0, out Vector<double> cz1);
                // the history boost v_prev += c/h of a particle some push moved (c ≠ 0 in any coordinate), as the scalar branch
                Vector<long> still0 = Vector.Equals(cx0, Vector<double>.Zero) & Vector.Equals(cy0, Vector<double>.Zero) & Vector.Equals(cz0, Vector<double>.Zero);
                Vector<long> still1 = Vector.Equals(cx1, Vector<double>.Zero) & Vector.Equals(cy1, Vector<double>.Zero) & Vector.Equals(cz1, Vector<double>.Zero);
                wx[a] = Vector.ConditionalSelect(still0, wx[a], wx[a] + cx0 * invHv); wx[z] = Vector.ConditionalSelect(still1, wx[z], wx[z] + cx1 * invHv);
                wy[a] = Vector.ConditionalSelect(still0, wy[a], wy[a] + cy0 * invHv); wy[z] = Vector.ConditionalSelect(still1, wy[z], wy[z] + cy1 * invHv);
                wz[a] = Vector.ConditionalSelect(still0, wz[a], wz[a] + cz0 * invHv); wz[z] = Vector.ConditionalSelect(still1, wz[z], wz[z] + cz1 * invHv);
            }
            int full = dx.Length * width;
            // the kinematic particles the lanes took (from the list, not a scan of the flags)
            ReadOnlySpan<int> fixedParticles = chain.KinematicIndices;
            for (int q = 0; q < fixedParticles.Length; q++)
                if (fixedParticles[q] < full) KinematicVelocity<TMark>(fixedParticles[q], invH, k);
            if (n - full == 1) SecondOrderVelocityParticle<TMark>(scheme, h, full);
            else if (full < n) SecondOrderVelocitiesRange<TMark>(scheme, h, full, n - full);
        }

        /// <summary>
        /// The scalar velocity loop's kinematic branch for particle i (its Δ as stored, with the last end mark unless TMark is
        /// <see cref="StoredMarks"/>; v_prev = d/h), after the lanes took it as a free one (they read nothing it writes).
        /// </summary>
        private void KinematicVelocity<TMark>(int i, double invH, double k) where TMark : struct
        {
            double mx = (double)chain.DX[i] + chain.DLowX[i], my = (double)chain.DY[i] + chain.DLowY[i], mz = (double)chain.DZ[i] + chain.DLowZ[i];
            double ex = chain.SolveDX[i], ey = chain.SolveDY[i], ez = chain.SolveDZ[i];
            if (typeof(TMark) != typeof(StoredMarks)) { ex += 1.0 * mx; ey += 1.0 * my; ez += 1.0 * mz; }
            chain.PrevVelX[i] = mx * invH; chain.PrevVelY[i] = my * invH; chain.PrevVelZ[i] = mz * invH;
            chain.VelX[i] = chain.BaseVelX[i] + mx * invH + k * ex; chain.VelY[i] = chain.BaseVelY[i] + my * invH + k * ey;
            chain.VelZ[i] = chain.BaseVelZ[i] + mz * invH + k * ez;
        }

        /// <summary>
        /// One coordinate of a block of free particles' second-order velocities: d = D + DLow, Δ (stored or marked as TMark says),
        /// the push c = d − d_pred − Δ (returned) and v = base + d/h + κ·Δ (κ = k; invH and k broadcast by the caller).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void VelocityLanes<TMark>(int b, Vector<float> d, Vector<float> low, Vector<float> q, ReadOnlySpan<Vector<double>> s,
            ReadOnlySpan<Vector<double>> bs, Span<Vector<double>> vs, Vector<double> invH, Vector<double> k, out Vector<double> c0, out Vector<double> c1) where TMark : struct
        {
            int a = 2 * b, z = a + 1;
            ChainState.Widen(d, out Vector<double> d0, out Vector<double> d1);
            ChainState.Widen(low, out Vector<double> l0, out Vector<double> l1);
            ChainState.Widen(q, out Vector<double> q0, out Vector<double> q1);
            Vector<double> m0 = d0 + l0, m1 = d1 + l1, e0, e1;
            if (typeof(TMark) == typeof(ImpliedStartMark)) { e0 = StartMarks(q0); e1 = StartMarks(q1); }
            else { e0 = s[a]; e1 = s[z]; }
            if (typeof(TMark) != typeof(StoredMarks)) { e0 += new Vector<double>(1.0) * m0; e1 += new Vector<double>(1.0) * m1; }
            c0 = m0 - q0 - e0; c1 = m1 - q1 - e1;
            vs[a] = bs[a] + m0 * invH + k * e0;
            vs[z] = bs[z] + m1 * invH + k * e1;
        }

        /// <summary>
        /// <see cref="CommitRange"/> on lanes: x = x_prev + Low + (D + DLow) split into float and remainder, for every block whose
        /// positions and velocities are all finite; a block with a non-finite one, and the tail, by the scalar loop (which restores it).
        /// </summary>
        private void CommitLanes()
        {
            int n = chain.ParticleCount, width = Vector<float>.Count;
            Span<Vector<float>> x = Floats(chain.X, n), y = Floats(chain.Y, n), z = Floats(chain.Z, n);
            Span<Vector<float>> lx = Floats(chain.LowX, n), ly = Floats(chain.LowY, n), lz = Floats(chain.LowZ, n);
            Span<Vector<double>> vx = Doubles(chain.VelX, n), vy = Doubles(chain.VelY, n), vz = Doubles(chain.VelZ, n);
            ReadOnlySpan<Vector<float>> px = Floats(chain.PrevX, n), py = Floats(chain.PrevY, n), pz = Floats(chain.PrevZ, n);
            ReadOnlySpan<Vector<float>> dx = Floats(chain.DX, n), dy = Floats(chain.DY, n), dz = Floats(chain.DZ, n);
            ReadOnlySpan<Vector<float>> rx = Floats(chain.DLowX, n), ry = Floats(chain.DLowY, n), rz = Floats(chain.DLowZ, n);
            int blocks = x.Length;
            for (int b = 0; b < blocks; b++)
            {
                int a = 2 * b, c = a + 1;
                Vector<double> ex0, ex1, ey0, ey1, ez0, ez1;
                Vector<float> nx = Committed(px[b], lx[b], dx[b], rx[b], out ex0, out ex1);
                Vector<float> ny = Committed(py[b], ly[b], dy[b], ry[b], out ey0, out ey1);
                Vector<float> nz = Committed(pz[b], lz[b], dz[b], rz[b], out ez0, out ez1);
                Vector<float> sum = nx + ny + nz;
                if (!(AllFinite(vx[a] + vy[a] + vz[a]) && AllFinite(vx[c] + vy[c] + vz[c]) && Vector.EqualsAll(sum - sum, Vector<float>.Zero)))
                {
                    CommitRange(b * width, width);
                    continue;
                }
                x[b] = nx; y[b] = ny; z[b] = nz;
                lx[b] = Remainder(ex0, ex1, nx); ly[b] = Remainder(ey0, ey1, ny); lz[b] = Remainder(ez0, ez1, nz);
            }
            if (blocks * width == n - 1) CommitParticle(n - 1);
            else if (blocks * width < n) CommitRange(blocks * width, n - blocks * width);
        }

        /// <summary>
        /// <see cref="CommitRange"/> of the one particle i (the lanes' tail of a chain of 8k + 1 particles), on the arrays:
        /// without the range's eighteen span set-ups (goal lanyard: 246 → about 90 instructions per substep).
        /// </summary>
        private void CommitParticle(int i)
        {
            ChainState k = chain;
            // x = x_prev + Low + (D + DLow)
            double ex = (double)k.PrevX[i] + k.LowX[i] + ((double)k.DX[i] + k.DLowX[i]), ey = (double)k.PrevY[i] + k.LowY[i] + ((double)k.DY[i] + k.DLowY[i]);
            double ez = (double)k.PrevZ[i] + k.LowZ[i] + ((double)k.DZ[i] + k.DLowZ[i]);
            float nx = (float)ex, ny = (float)ey, nz = (float)ez;
            if (double.IsFinite(k.VelX[i] + k.VelY[i] + k.VelZ[i]) && float.IsFinite(nx + ny + nz))
            {
                k.X[i] = nx; k.Y[i] = ny; k.Z[i] = nz;
                k.LowX[i] = (float)(ex - nx); k.LowY[i] = (float)(ey - ny); k.LowZ[i] = (float)(ez - nz);
            }
            else RestoreParticle(i);
        }

        /// <summary>One coordinate of a block's committed position: e = (x_prev + Low) + (D + DLow) in double (out, two halves), rounded to float.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<float> Committed(Vector<float> previous, Vector<float> low, Vector<float> d, Vector<float> dLow, out Vector<double> e0, out Vector<double> e1)
        {
            ChainState.Widen(previous, out Vector<double> p0, out Vector<double> p1);
            ChainState.Widen(low, out Vector<double> l0, out Vector<double> l1);
            ChainState.Widen(d, out Vector<double> d0, out Vector<double> d1);
            ChainState.Widen(dLow, out Vector<double> r0, out Vector<double> r1);
            e0 = p0 + l0 + (d0 + r0);
            e1 = p1 + l1 + (d1 + r1);
            return Vector.Narrow(e0, e1);
        }

        /// <summary>The float remainder (e − f) of a double e (two halves) below its float rounding f.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<float> Remainder(Vector<double> e0, Vector<double> e1, Vector<float> f)
        {
            ChainState.Widen(f, out Vector<double> f0, out Vector<double> f1);
            return Vector.Narrow(e0 - f0, e1 - f1);
        }

        /// <summary><see cref="Violent"/> on lanes while no segment is broken: the full blocks of segments, then the scalar tail.</summary>
        private bool ViolentLanes()
        {
            int s = chain.SegmentCount, width = Vector<float>.Count;
            ReadOnlySpan<Vector<float>> length = Floats(chain.Length, s), rest = Floats(chain.RestLength, s);
            ReadOnlySpan<Vector<float>> xA = Floats(chain.PrevX, s), yA = Floats(chain.PrevY, s), zA = Floats(chain.PrevZ, s);
            ReadOnlySpan<Vector<float>> xB = MemoryMarshal.Cast<float, Vector<float>>(ChainState.Shifted(chain.PrevX, s));
            ReadOnlySpan<Vector<float>> yB = MemoryMarshal.Cast<float, Vector<float>>(ChainState.Shifted(chain.PrevY, s));
            ReadOnlySpan<Vector<float>> zB = MemoryMarshal.Cast<float, Vector<float>>(ChainState.Shifted(chain.PrevZ, s));
            var strain = new Vector<float>(ViolentStrain);
            int blocks = length.Length;
            for (int b = 0; b < blocks; b++)
            {
                Vector<float> dx = xB[b] - xA[b], dy = yB[b] - yA[b], dz = zB[b] - zA[b];
                Vector<float> start = Vector.SquareRoot(dx * dx + dy * dy + dz * dz);
                if (Vector.GreaterThanAny(Vector.Abs(length[b] - start), strain * rest[b])) return true;
            }
            return blocks * width < s && ViolentRange(blocks * width, s - blocks * width);
        }

        /// <summary>
        /// <see cref="UpdateTensions"/> on lanes while no segment is broken (1/h² = invH2): T = −λ/h² per lane, then the host
        /// step's largest and summed tension; the scalar tail after the last full block.
        /// </summary>
        private void TensionLanes(double invH2, bool firstSubstep)
        {
            int s = chain.SegmentCount, width = Vector<float>.Count;
            ReadOnlySpan<Vector<double>> lambda = Doubles(chain.Lambda, s);
            Span<Vector<float>> tension = Floats(chain.Tension, s), peak = Floats(chain.PeakTension, s), sum = Floats(chain.MeanTension, s);
            var largest = new Vector<float>(float.MaxValue);
            int blocks = tension.Length;
            for (int b = 0; b < blocks; b++)
            {
                // (float)(−λ·invH2); non-finite reads float.MaxValue (Tension)
                Vector<float> value = Vector.Narrow(Negated(lambda[2 * b]) * invH2, Negated(lambda[2 * b + 1]) * invH2);
                value = Vector.ConditionalSelect(Vector.Equals(value - value, Vector<float>.Zero), value, largest);
                tension[b] = value;
                if (firstSubstep) { peak[b] = value; sum[b] = value; }
                else
                {
                    peak[b] = Vector.ConditionalSelect(Vector.GreaterThan(value, peak[b]), value, peak[b]);
                    sum[b] += value;
                }
            }
            if (blocks * width < s) TensionRange(invH2, firstSubstep, blocks * width, s - blocks * width);
        }

        /// <summary>
        /// <see cref="RefreshLengths"/> on runs of <see cref="Vector{T}"/> segments: each lane forms the segment vector
        /// ((double)x_b − x_a) + ((double)low_b − low_a) per axis, its length in double and the float of it, as the rows do.
        /// Returns the first segment not done (the rows take the rest).
        /// </summary>
        private int RefreshLengthLanes()
        {
            int s = chain.SegmentCount;
            ReadOnlySpan<Vector<float>> xA = Floats(chain.X, s), yA = Floats(chain.Y, s), zA = Floats(chain.Z, s);
            ReadOnlySpan<Vector<float>> xB = VectorPath.AsLanes(ChainState.Shifted(chain.X, s)), yB = VectorPath.AsLanes(ChainState.Shifted(chain.Y, s));
            ReadOnlySpan<Vector<float>> zB = VectorPath.AsLanes(ChainState.Shifted(chain.Z, s));
            ReadOnlySpan<Vector<float>> lxA = Floats(chain.LowX, s), lyA = Floats(chain.LowY, s), lzA = Floats(chain.LowZ, s);
            ReadOnlySpan<Vector<float>> lxB = VectorPath.AsLanes(ChainState.Shifted(chain.LowX, s)), lyB = VectorPath.AsLanes(ChainState.Shifted(chain.LowY, s));
            ReadOnlySpan<Vector<float>> lzB = VectorPath.AsLanes(ChainState.Shifted(chain.LowZ, s));
            Span<Vector<float>> length = Floats(chain.Length, s);
            for (int k = 0; k < length.Length; k++)
            {
                SegmentAxis(xA[k], xB[k], lxA[k], lxB[k], out Vector<double> x0, out Vector<double> x1);
                SegmentAxis(yA[k], yB[k], lyA[k], lyB[k], out Vector<double> y0, out Vector<double> y1);
                SegmentAxis(zA[k], zB[k], lzA[k], lzB[k], out Vector<double> z0, out Vector<double> z1);
                length[k] = Vector.Narrow(Vector.SquareRoot(x0 * x0 + y0 * y0 + z0 * z0), Vector.SquareRoot(x1 * x1 + y1 * y1 + z1 * z1));
            }
            return length.Length * Vector<float>.Count;
        }

        /// <summary>One axis of a run of segment vectors, ((double)b − a) + ((double)lowB − lowA), as its two double halves.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void SegmentAxis(Vector<float> a, Vector<float> b, Vector<float> lowA, Vector<float> lowB, out Vector<double> first, out Vector<double> second)
        {
            ChainState.Widen(a, out Vector<double> a0, out Vector<double> a1);
            ChainState.Widen(b, out Vector<double> b0, out Vector<double> b1);
            ChainState.Widen(lowA, out Vector<double> l0, out Vector<double> l1);
            ChainState.Widen(lowB, out Vector<double> m0, out Vector<double> m1);
            first = (b0 - a0) + (m0 - l0);
            second = (b1 - a1) + (m1 - l1);
        }

        /// <summary>
        /// <see cref="ComputeResidual"/> of an unbroken chain without plasticity on runs of <see cref="Vector{T}"/> segments:
        /// each lane keeps the largest |c − α·T|/L of its segments by the rows' test (error &gt; worst, so a NaN never enters),
        /// then the lanes are combined by the same test: the largest error of a set does not depend on the order it is found
        /// in. Returns it; <paramref name="from"/>: the first segment not done.
        /// </summary>
        private double ResidualLanes(bool tensionOnly, out int from)
        {
            int s = chain.SegmentCount;
            ReadOnlySpan<Vector<float>> length = Floats(chain.Length, s), rest = Floats(chain.RestLength, s);
            ReadOnlySpan<Vector<float>> tension = Floats(chain.Tension, s), compliance = Floats(chain.Compliance, s);
            Vector<double> worst0 = Vector<double>.Zero, worst1 = Vector<double>.Zero;
            for (int k = 0; k < length.Length; k++)
            {
                ChainState.Widen(length[k], out Vector<double> l0, out Vector<double> l1);
                ChainState.Widen(rest[k], out Vector<double> r0, out Vector<double> r1);
                ChainState.Widen(tension[k], out Vector<double> t0, out Vector<double> t1);
                ChainState.Widen(compliance[k], out Vector<double> a0, out Vector<double> a1);
                worst0 = WorstResidual(l0 - r0, r0, t0, a0, tensionOnly, worst0);
                worst1 = WorstResidual(l1 - r1, r1, t1, a1, tensionOnly, worst1);
            }
            double worst = 0.0;
            for (int l = 0; l < Vector<double>.Count; l++)
            {
                if (worst0[l] > worst) worst = worst0[l];
                if (worst1[l] > worst) worst = worst1[l];
            }
            from = length.Length * Vector<float>.Count;
            return worst;
        }

        /// <summary>
        /// One half run of <see cref="ResidualLanes"/>: the error |c − α·T|/L (c = l − L) where the rows take it (not a slack
        /// tension-only segment: T ≤ 0 and c ≤ 0), raised into worst where it is larger.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<double> WorstResidual(Vector<double> c, Vector<double> rest, Vector<double> tension, Vector<double> compliance, bool tensionOnly, Vector<double> worst)
        {
            Vector<double> error = Vector.Abs(c - compliance * tension) / rest;
            Vector<long> larger = Vector.GreaterThan(error, worst);
            if (tensionOnly) larger = Vector.AndNot(larger, Vector.LessThanOrEqual(tension, Vector<double>.Zero) & Vector.LessThanOrEqual(c, Vector<double>.Zero));
            return Vector.ConditionalSelect(larger, error, worst);
        }

        /// <summary>
        /// FNV-1a over the bits of every particle's and segment's state the substep passes write (positions and their
        /// remainders, displacements, the double velocities and the second-order history, multipliers, tensions): tests compare
        /// it with <see cref="VectorPath.Enabled"/> off and on.
        /// </summary>
        internal ulong StateBits()
        {
            ulong h = 14695981039346656037UL;
            float[][] floats =
            {
                chain.X, chain.Y, chain.Z, chain.LowX, chain.LowY, chain.LowZ, chain.PrevX, chain.PrevY, chain.PrevZ, chain.DX, chain.DY, chain.DZ,
                chain.DLowX, chain.DLowY, chain.DLowZ, chain.PredictedDX, chain.PredictedDY, chain.PredictedDZ,
                chain.Tension, chain.PeakTension, chain.MeanTension, chain.Length,
            };
            double[][] doubles =
            {
                chain.VelX, chain.VelY, chain.VelZ, chain.PrevVelX, chain.PrevVelY, chain.PrevVelZ, chain.BaseVelX, chain.BaseVelY, chain.BaseVelZ,
                chain.Lambda,
            };
            foreach (float[] values in floats)
                foreach (float value in values) h = Mix(h, (uint)BitConverter.SingleToInt32Bits(value));
            foreach (double[] values in doubles)
                foreach (double value in values)
                {
                    ulong bits = (ulong)BitConverter.DoubleToInt64Bits(value);
                    h = Mix(Mix(h, (uint)bits), (uint)(bits >> 32));
                }
            ulong size = (ulong)BitConverter.DoubleToInt64Bits(chain.Size);
            return Mix(Mix(h, (uint)size), (uint)(size >> 32));
        }

        private static ulong Mix(ulong h, uint bits)
        {
            for (int b = 0; b < 4; b++) { h ^= (bits >> (8 * b)) & 0xff; h *= 1099511628211UL; }
            return h;
        }

        /// <summary>The first n entries of a float array as whole float vectors (the tail left out).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Span<Vector<float>> Floats(float[] values, int n) => VectorPath.AsLanes(ChainState.Exactly(values, n));

        /// <summary>The first n entries of a double array as whole double vectors (the tail left out).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Span<Vector<double>> Doubles(double[] values, int n) => VectorPath.AsLanes(ChainState.Exactly(values, n));
    }
}
