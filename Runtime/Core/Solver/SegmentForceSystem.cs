using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// The block-tridiagonal system of <see cref="ExactChainSolver"/> in the segment force changes δΛ_j (3-vectors,
    /// N·s²): row j reads −W_j δΛ_{j−1} + (W_j + W_{j+1} + α̃_j n nᵀ + τ_j (I − n nᵀ)) δΛ_j − W_{j+1} δΛ_{j+1} = R_j, with
    /// W_i = w_i I, or w_t (I − c cᵀ) for a particle held on a surface of normal c (w_t its tangential mobility under friction,
    /// see <see cref="ChainContacts"/>; 0 when it is stuck, which decouples its two segments: the elimination passes nothing
    /// through it). A released or invalid row is
    /// δΛ_j = −Λ_j (its force returns to zero). Solved by block Thomas elimination in double precision: the 3×3 pivots
    /// are symmetric positive definite (each is a compliance plus a mobility), so no pivoting is needed; where the
    /// couplings are isotropic (no contact) the elimination costs one 3×3 inverse and a few scaled adds per segment.
    /// </summary>
    internal static class SegmentForceSystem
    {
        /// <summary>
        /// Solves the system of the current active set and contact set into Step (δΛ). <paramref name="from"/>: the first row
        /// whose inputs changed since the last solve of the same linearisation (0: all); the rows before it keep their pivots
        /// and reduced right-hand sides, which depend only on the rows before them.
        /// </summary>
        public static void Solve(ChainState c, int from)
        {
            // the forward sweep specialised on whether there are contacts: without them the loop calls nothing, so its
            // carried pivot and reduced vector stay in registers (every xmm register is caller-saved on x86-64)
            // and on whether it reads the blocks PrepareBlocks stored (StoresBlocks) or builds its own
            bool stored = StoresBlocks;
            if (c.ContactCount > 0)
            {
                if (stored) Forward<WithContacts, StoredBlocks>(c, from);
                else Forward<WithContacts, OwnBlocks>(c, from);
            }
            else if (stored) Forward<NoContacts, StoredBlocks>(c, from);
            else Forward<NoContacts, OwnBlocks>(c, from);
            if (c.ContactCount > 0) Back<WithContacts>(c);
            else Back<NoContacts>(c);
        }

        /// <summary>
        /// True when <see cref="PrepareBlocks"/> builds the free blocks on lanes for <see cref="Forward{T, TBlocks}"/> to read:
        /// with <see cref="VectorPath.Enabled"/> and at least 4 double lanes (AVX2). On 2 lanes the lane build costs as many
        /// instructions as the sweep's own scalar build it replaces (goal lanyard, x86-64-v2: +1.8 k per host step), so there
        /// the sweep builds each block itself. Either way the blocks have the same bits.
        /// </summary>
        internal static bool StoresBlocks
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            get => VectorPath.Enabled && VectorPath.DoubleLanes >= 4;
        }

        /// <summary>
        /// Builds every row's free block A_j (<see cref="Block"/>, into ChainState.BlockXX … BlockZZ) from the stored float
        /// direction, the compliances and the ends' mobilities where <see cref="StoresBlocks"/>: they do not change between
        /// the active-set passes of one linearisation, so <see cref="Forward{T, TBlocks}"/> reads them. Runs of
        /// <see cref="VectorPath.FloatLanes"/> segments go on lanes (each lane does <see cref="Block"/>'s operations in its
        /// order: the same bits), the tail row by row. A released or invalid row's block is built too and never read.
        /// <paramref name="views"/>: the chain's lane views of the host step (<see cref="ExactChainSolver.StepViews"/>; blocks are
        /// stored only with the vector paths on, when they are built).
        /// </summary>
        public static void PrepareBlocks(ChainState c, in ExactChainSolver.StepViews views)
        {
            if (!StoresBlocks) return;
            int s = c.SegmentCount;
            int from = PrepareBlockLanes(c, in views);
            // no tail (the segment count a multiple of VectorPath.FloatLanes): none of the rows' spans made
            if (from >= s) return;
            ReadOnlySpan<float> wA = ChainState.Exactly(c.InverseMass, s), wB = ChainState.Shifted(c.InverseMass, s);
            ReadOnlySpan<float> dirX = ChainState.Exactly(c.DirX, s), dirY = ChainState.Exactly(c.DirY, s), dirZ = ChainState.Exactly(c.DirZ, s);
            ReadOnlySpan<double> axial = ChainState.Exactly(c.AxialCompliance, s), transverse = ChainState.Exactly(c.TransverseCompliance, s);
            Span<double> bxx = ChainState.Exactly(c.BlockXX, s), bxy = ChainState.Exactly(c.BlockXY, s), bxz = ChainState.Exactly(c.BlockXZ, s);
            Span<double> byy = ChainState.Exactly(c.BlockYY, s), byz = ChainState.Exactly(c.BlockYZ, s), bzz = ChainState.Exactly(c.BlockZZ, s);
            for (int j = from; j < s; j++)
            {
                Block(dirX[j], dirY[j], dirZ[j], transverse[j], axial[j], (double)wA[j] + wB[j], out bxx[j], out bxy[j], out bxz[j], out byy[j], out byz[j], out bzz[j]);
            }
        }

        /// <summary>
        /// <see cref="PrepareBlocks"/> on runs of <see cref="VectorPath.FloatLanes"/> segments (two halves of doubles each);
        /// returns the first segment not built (the rows take the rest).
        /// </summary>
        private static int PrepareBlockLanes(ChainState c, in ExactChainSolver.StepViews views)
        {
            int s = c.SegmentCount, lanes = VectorPath.FloatLanes, runs = s / lanes, pairs = 2 * runs;
            // the host step's views (ExactChainSolver.StepViews), cut to the runs or their halves: views of one length share
            // their bounds checks
            ReadOnlySpan<Vector<float>> wA = views.WA.Slice(0, runs), wB = views.WB.Slice(0, runs);
            ReadOnlySpan<Vector<float>> dirX = views.DirXOut.Slice(0, runs), dirY = views.DirYOut.Slice(0, runs), dirZ = views.DirZOut.Slice(0, runs);
            ReadOnlySpan<Vector<double>> axial = views.AxialOut.Slice(0, pairs), transverse = views.TransverseOut.Slice(0, pairs);
            Span<Vector<double>> bxx = views.BlockXX.Slice(0, pairs), bxy = views.BlockXY.Slice(0, pairs), bxz = views.BlockXZ.Slice(0, pairs);
            Span<Vector<double>> byy = views.BlockYY.Slice(0, pairs), byz = views.BlockYZ.Slice(0, pairs), bzz = views.BlockZZ.Slice(0, pairs);
            for (int k = 0; k < wA.Length; k++)
            {
                ChainState.Widen(dirX[k], out Vector<double> nxLow, out Vector<double> nxHigh);
                ChainState.Widen(dirY[k], out Vector<double> nyLow, out Vector<double> nyHigh);
                ChainState.Widen(dirZ[k], out Vector<double> nzLow, out Vector<double> nzHigh);
                ChainState.Widen(wA[k], out Vector<double> aLow, out Vector<double> aHigh);
                ChainState.Widen(wB[k], out Vector<double> bLow, out Vector<double> bHigh);
                int h = 2 * k;
                BlockLanes(nxLow, nyLow, nzLow, transverse[h], axial[h], aLow + bLow,
                    out bxx[h], out bxy[h], out bxz[h], out byy[h], out byz[h], out bzz[h]);
                BlockLanes(nxHigh, nyHigh, nzHigh, transverse[h + 1], axial[h + 1], aHigh + bHigh,
                    out bxx[h + 1], out bxy[h + 1], out bxz[h + 1], out byy[h + 1], out byz[h + 1], out bzz[h + 1]);
            }
            return runs * lanes;
        }

        /// <summary><see cref="Block"/> on <see cref="VectorPath.DoubleLanes"/> lanes, operation for operation.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void BlockLanes(Vector<double> nx, Vector<double> ny, Vector<double> nz, Vector<double> tau, Vector<double> axial, Vector<double> mobility,
            out Vector<double> xx, out Vector<double> xy, out Vector<double> xz, out Vector<double> yy, out Vector<double> yz, out Vector<double> zz)
        {
            Vector<double> unit = Vector<double>.One / Vector.SquareRoot(nx * nx + ny * ny + nz * nz);
            nx *= unit; ny *= unit; nz *= unit;
            Vector<double> d = axial - tau;
            Vector<double> m = mobility + tau;
            xx = m + d * nx * nx; yy = m + d * ny * ny; zz = m + d * nz * nz;
            xy = d * nx * ny; xz = d * nx * nz; yz = d * ny * nz;
        }

        /// <summary>Type argument of <see cref="Forward{T, TBlocks}"/>: it reads the blocks <see cref="PrepareBlocks"/> stored.</summary>
        internal struct StoredBlocks { }

        /// <summary>Type argument of <see cref="Forward{T, TBlocks}"/>: it builds each row's block itself (<see cref="Block"/>).</summary>
        internal struct OwnBlocks { }

        /// <summary>
        /// Type argument of the kernels specialised on contacts (<see cref="Forward{T, TBlocks}"/>, ExactChainSolver's particle pass):
        /// the JIT compiles one copy per struct and folds the test typeof(T) == typeof(WithContacts).
        /// </summary>
        internal struct WithContacts { }

        /// <summary>See <see cref="WithContacts"/>: the copy for a chain without contacts, which calls nothing per element.</summary>
        internal struct NoContacts { }

        /// <summary>
        /// Forward sweep from row <paramref name="from"/>: S_j = A_j − L_j S_{j−1}⁻¹ U_{j−1} (its inverse) and
        /// y_j = R_j − L_j S_{j−1}⁻¹ y_{j−1}, into ChainState.Eliminated (from the stored row before).
        /// </summary>
        private static void Forward<T, TBlocks>(ChainState c, int from) where T : struct where TBlocks : struct
        {
            bool contacts = typeof(T) == typeof(WithContacts), stored = typeof(TBlocks) == typeof(StoredBlocks);
            int s = c.SegmentCount;
            if (from >= s) return;
            // row 0 (no row before it) goes first, so the loop eliminates through particle j on every row it does; called
            // before the spans are made, which then need not live across a call (in callee-saved registers or spilled)
            if (from == 0) FirstRow<T, TBlocks>(c);
            // spans of exactly s entries (the loop bound) index without bounds checks; wB[j] is particle j + 1's. Only the
            // spans the blocks' variant reads are made (each costs a null and a length check per call)
            ReadOnlySpan<float> wA = ChainState.Exactly(c.InverseMass, s), wB = stored ? default : ChainState.Shifted(c.InverseMass, s);
            ReadOnlySpan<float> dirX = stored ? default : ChainState.Exactly(c.DirX, s), dirY = stored ? default : ChainState.Exactly(c.DirY, s);
            ReadOnlySpan<float> dirZ = stored ? default : ChainState.Exactly(c.DirZ, s);
            ReadOnlySpan<double> axial = stored ? default : ChainState.Exactly(c.AxialCompliance, s);
            ReadOnlySpan<double> transverse = stored ? default : ChainState.Exactly(c.TransverseCompliance, s);
            ReadOnlySpan<double> bxx = stored ? ChainState.Exactly(c.BlockXX, s) : default, bxy = stored ? ChainState.Exactly(c.BlockXY, s) : default;
            ReadOnlySpan<double> bxz = stored ? ChainState.Exactly(c.BlockXZ, s) : default, byy = stored ? ChainState.Exactly(c.BlockYY, s) : default;
            ReadOnlySpan<double> byz = stored ? ChainState.Exactly(c.BlockYZ, s) : default, bzz = stored ? ChainState.Exactly(c.BlockZZ, s) : default;
            Span<EliminatedRow> rows = ChainState.Exactly(c.Eliminated, s);
            ReadOnlySpan<double> rx = ChainState.Exactly(c.ResidualX, s), ry = ChainState.Exactly(c.ResidualY, s), rz = ChainState.Exactly(c.ResidualZ, s);
            ReadOnlySpan<bool> active = ChainState.Exactly(c.Active, s);
            int start = from > 0 ? from : 1;
            // the row before (its inverse pivot G and reduced vector p) is read from where it was stored, not carried in
            // registers: the loads fold into the arithmetic, and the sweep's other pointers and the row's own block keep
            // the registers
            ref EliminatedRow before = ref rows[start - 1];
            bool previousActive = active[start - 1];
            // (uint) bound: j is an index (start ≥ 1), so every span of s entries is read without a bounds check
            for (int j = start; (uint)j < (uint)s; j++)
            {
                double sxx, sxy, sxz, syy, syz, szz, bx, by, bz;
                if (!active[j])
                {
                    // the forces read from the arrays: the few released rows pay the checks, the loop keeps three pointers fewer
                    sxx = 1; sxy = 0; sxz = 0; syy = 1; syz = 0; szz = 1;
                    bx = -c.ForceX[j]; by = -c.ForceY[j]; bz = -c.ForceZ[j];
                }
                else
                {
                    if (stored) { sxx = bxx[j]; sxy = bxy[j]; sxz = bxz[j]; syy = byy[j]; syz = byz[j]; szz = bzz[j]; }
                    else Block(dirX[j], dirY[j], dirZ[j], transverse[j], axial[j], (double)wA[j] + wB[j], out sxx, out sxy, out sxz, out syy, out syz, out szz);
                    bx = rx[j]; by = ry[j]; bz = rz[j];
                    bool held = false;
                    if (contacts)
                    {
                        // the contact terms work on a copy: the row's own locals are never passed by reference
                        var row = new Row { XX = sxx, XY = sxy, XZ = sxz, YY = syy, YZ = syz, ZZ = szz, X = bx, Y = by, Z = bz };
                        SubtractHeldNormal(c, j, ref row.XX, ref row.XY, ref row.XZ, ref row.YY, ref row.YZ, ref row.ZZ);
                        SubtractHeldNormal(c, j + 1, ref row.XX, ref row.XY, ref row.XZ, ref row.YY, ref row.YZ, ref row.ZZ);
                        held = c.ContactActive[j];
                        if (held)
                            EliminateHeld(c, j, previousActive, before.XX, before.XY, before.XZ, before.YY, before.YZ, before.ZZ, before.X, before.Y, before.Z,
                                ref row.XX, ref row.XY, ref row.XZ, ref row.YY, ref row.YZ, ref row.ZZ, ref row.X, ref row.Y, ref row.Z);
                        sxx = row.XX; sxy = row.XY; sxz = row.XZ; syy = row.YY; syz = row.YZ; szz = row.ZZ; bx = row.X; by = row.Y; bz = row.Z;
                    }
                    if (!held)
                    {
                        // elimination through a free particle j (isotropic coupling −w_j I)
                        double wj = wA[j];
                        if (previousActive)
                        {
                            double k = wj * wj;
                            sxx -= k * before.XX; sxy -= k * before.XY; sxz -= k * before.XZ; syy -= k * before.YY; syz -= k * before.YZ; szz -= k * before.ZZ;
                        }
                        // p in locals first: each product then reads its pivot entry from memory
                        double px = before.X, py = before.Y, pz = before.Z;
                        bx += wj * (before.XX * px + before.XY * py + before.XZ * pz);
                        by += wj * (before.XY * px + before.YY * py + before.YZ * pz);
                        bz += wj * (before.XZ * px + before.YZ * py + before.ZZ * pz);
                    }
                }
                Invert(sxx, sxy, sxz, syy, syz, szz, out double gxx, out double gxy, out double gxz, out double gyy, out double gyz, out double gzz);
                ref EliminatedRow eliminated = ref rows[j];
                eliminated.XX = gxx; eliminated.XY = gxy; eliminated.XZ = gxz; eliminated.YY = gyy; eliminated.YZ = gyz; eliminated.ZZ = gzz;
                eliminated.X = bx; eliminated.Y = by; eliminated.Z = bz;
                before = ref eliminated;
                // read again, not carried: the row's flag keeps no register through the row
                previousActive = active[j];
            }
        }

        /// <summary>
        /// Row 0 of <see cref="Forward{T, TBlocks}"/>: its block (with the held contacts' terms) and right-hand side, no row
        /// before it to eliminate.
        /// </summary>
        private static void FirstRow<T, TBlocks>(ChainState c) where T : struct where TBlocks : struct
        {
            double sxx, sxy, sxz, syy, syz, szz, bx, by, bz;
            if (!c.Active[0])
            {
                sxx = 1; sxy = 0; sxz = 0; syy = 1; syz = 0; szz = 1;
                bx = -c.ForceX[0]; by = -c.ForceY[0]; bz = -c.ForceZ[0];
            }
            else
            {
                if (typeof(TBlocks) == typeof(StoredBlocks)) { sxx = c.BlockXX[0]; sxy = c.BlockXY[0]; sxz = c.BlockXZ[0]; syy = c.BlockYY[0]; syz = c.BlockYZ[0]; szz = c.BlockZZ[0]; }
                else Block(c.DirX[0], c.DirY[0], c.DirZ[0], c.TransverseCompliance[0], c.AxialCompliance[0], (double)c.InverseMass[0] + c.InverseMass[1],
                    out sxx, out sxy, out sxz, out syy, out syz, out szz);
                bx = c.ResidualX[0]; by = c.ResidualY[0]; bz = c.ResidualZ[0];
                if (typeof(T) == typeof(WithContacts))
                {
                    SubtractHeldNormal(c, 0, ref sxx, ref sxy, ref sxz, ref syy, ref syz, ref szz);
                    SubtractHeldNormal(c, 1, ref sxx, ref sxy, ref sxz, ref syy, ref syz, ref szz);
                }
            }
            Invert(sxx, sxy, sxz, syy, syz, szz, out double gxx, out double gxy, out double gxz, out double gyy, out double gyz, out double gzz);
            ref EliminatedRow first = ref c.Eliminated[0];
            first.XX = gxx; first.XY = gxy; first.XZ = gxz; first.YY = gyy; first.YZ = gyz; first.ZZ = gzz;
            first.X = bx; first.Y = by; first.Z = bz;
        }

        /// <summary>
        /// Back substitution: δ_j = S_j⁻¹ (y_j − U_j δ_{j+1}), U_j = −W_{j+1} on an active row; specialised on contacts as
        /// <see cref="Forward{T, TBlocks}"/> (without them U_j = −w_{j+1} I), the last row (no row after it) peeled.
        /// </summary>
        private static void Back<T>(ChainState c) where T : struct
        {
            bool contacts = typeof(T) == typeof(WithContacts);
            int s = c.SegmentCount;
            ReadOnlySpan<float> wB = ChainState.Shifted(c.InverseMass, s);
            ReadOnlySpan<EliminatedRow> rows = ChainState.Exactly(c.Eliminated, s);
            ReadOnlySpan<bool> active = ChainState.Exactly(c.Active, s);
            Span<double> dx = ChainState.Exactly(c.StepX, s), dy = ChainState.Exactly(c.StepY, s), dz = ChainState.Exactly(c.StepZ, s);
            int last = s - 1;
            if (last < 0) return;
            ref readonly EliminatedRow end = ref rows[last];
            BackRow(in end, end.X, end.Y, end.Z, out double nx, out double ny, out double nz);
            dx[last] = nx; dy[last] = ny; dz[last] = nz;
            // (uint) bound: the loop ends when j passes 0 (−1 is above every index), and every span of s entries is read
            // without a bounds check
            for (int j = last - 1; (uint)j < (uint)s; j--)
            {
                ref readonly EliminatedRow row = ref rows[j];
                double vx = row.X, vy = row.Y, vz = row.Z;
                if (active[j])
                {
                    double mx, my, mz;
                    if (contacts) Mobility(c, j + 1, nx, ny, nz, out mx, out my, out mz);
                    else
                    {
                        double w = wB[j];
                        mx = w * nx; my = w * ny; mz = w * nz;
                    }
                    vx += mx; vy += my; vz += mz;
                }
                BackRow(in row, vx, vy, vz, out nx, out ny, out nz);
                dx[j] = nx; dy[j] = ny; dz[j] = nz;
            }
        }

        /// <summary>One row of <see cref="Back{T}"/>: the symmetric inverse pivot times v.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void BackRow(in EliminatedRow pivot, double vx, double vy, double vz, out double ox, out double oy, out double oz)
        {
            ox = pivot.XX * vx + pivot.XY * vy + pivot.XZ * vz;
            oy = pivot.XY * vx + pivot.YY * vy + pivot.YZ * vz;
            oz = pivot.XZ * vx + pivot.YZ * vy + pivot.ZZ * vz;
        }

        /// <summary>
        /// One row of the forward sweep's result (ChainState.Eliminated): the inverse pivot S_j⁻¹ (symmetric, XX … ZZ, kg) and
        /// the reduced right-hand side y_j (X, Y, Z; m), side by side, so the sweep reads the row before and the back
        /// substitution its row through one pointer.
        /// </summary>
        internal struct EliminatedRow
        {
            public double XX, XY, XZ, YY, YZ, ZZ, X, Y, Z;
        }

        /// <summary>A row's symmetric block (XX … ZZ) and right-hand side (X, Y, Z) while the contact terms change it.</summary>
        private struct Row
        {
            public double XX, XY, XZ, YY, YZ, ZZ, X, Y, Z;
        }

        /// <summary>
        /// A_j = W_j + W_{j+1} + α̃ n nᵀ + τ (I − n nᵀ) for free ends (mobility = w_j + w_{j+1}, 1/kg; τ the transverse and
        /// axial the axial compliance); n (the stored float direction) is normalised in double: τ may be 10⁶ times the rest.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Block(double nx, double ny, double nz, double tau, double axial, double mobility,
            out double xx, out double xy, out double xz, out double yy, out double yz, out double zz)
        {
            double unit = 1.0 / Math.Sqrt(nx * nx + ny * ny + nz * nz);
            nx *= unit; ny *= unit; nz *= unit;
            double d = axial - tau;
            double m = mobility + tau;
            xx = m + d * nx * nx; yy = m + d * ny * ny; zz = m + d * nz * nz;
            xy = d * nx * ny; xz = d * nx * nz; yz = d * ny * nz;
        }

        /// <summary>
        /// W_i = w_t (I − c cᵀ) for a held contact (w_t its tangential mobility: w without friction, 0 stuck): replaces w I in a
        /// diagonal block, subtracting (w − w_t) I + w_t c cᵀ.
        /// </summary>
        private static void SubtractHeldNormal(ChainState c, int i, ref double xx, ref double xy, ref double xz, ref double yy, ref double yz, ref double zz)
        {
            if (!c.ContactActive[i]) return;
            double wt = c.ContactMobility[i], d = c.InverseMass[i] - wt;
            double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
            xx -= d + wt * nx * nx; xy -= wt * nx * ny; xz -= wt * nx * nz; yy -= d + wt * ny * ny; yz -= wt * ny * nz; zz -= d + wt * nz * nz;
        }

        /// <summary>The elimination step through a held contact particle j: S −= W G W (when the row before is active), y += W G y_{j−1}.</summary>
        private static void EliminateHeld(ChainState c, int j, bool previousActive,
            double gxx, double gxy, double gxz, double gyy, double gyz, double gzz, double px, double py, double pz,
            ref double sxx, ref double sxy, ref double sxz, ref double syy, ref double syz, ref double szz,
            ref double bx, ref double by, ref double bz)
        {
            // G y_{j−1}, then W of it
            double tx = gxx * px + gxy * py + gxz * pz, ty = gxy * px + gyy * py + gyz * pz, tz = gxz * px + gyz * py + gzz * pz;
            Mobility(c, j, tx, ty, tz, out double mx, out double my, out double mz);
            bx += mx; by += my; bz += mz;
            if (!previousActive) return;
            // W G W column by column (W and G symmetric, so the product is too)
            Mobility(c, j, 1, 0, 0, out double w0x, out double w0y, out double w0z);
            Mobility(c, j, 0, 1, 0, out double w1x, out double w1y, out double w1z);
            Mobility(c, j, 0, 0, 1, out double w2x, out double w2y, out double w2z);
            GW(gxx, gxy, gxz, gyy, gyz, gzz, w0x, w0y, w0z, out double a0x, out double a0y, out double a0z);
            GW(gxx, gxy, gxz, gyy, gyz, gzz, w1x, w1y, w1z, out double a1x, out double a1y, out double a1z);
            GW(gxx, gxy, gxz, gyy, gyz, gzz, w2x, w2y, w2z, out double a2x, out double a2y, out double a2z);
            Mobility(c, j, a0x, a0y, a0z, out double c0x, out double c0y, out double c0z);
            Mobility(c, j, a1x, a1y, a1z, out _, out double c1y, out double c1z);
            Mobility(c, j, a2x, a2y, a2z, out _, out _, out double c2z);
            sxx -= c0x; sxy -= c0y; sxz -= c0z; syy -= c1y; syz -= c1z; szz -= c2z;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void GW(double gxx, double gxy, double gxz, double gyy, double gyz, double gzz, double vx, double vy, double vz, out double rx, out double ry, out double rz)
        {
            rx = gxx * vx + gxy * vy + gxz * vz;
            ry = gxy * vx + gyy * vy + gyz * vz;
            rz = gxz * vx + gyz * vy + gzz * vz;
        }

        /// <summary>r = W_i v (1/kg · N·s² = m): w v, or w_t (v − c (c·v)) with a held contact (w_t its tangential mobility, 0 stuck).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Mobility(ChainState c, int i, double vx, double vy, double vz, out double rx, out double ry, out double rz)
        {
            double w = c.InverseMass[i];
            if (c.ContactCount > 0 && c.ContactActive[i])
            {
                w = c.ContactMobility[i];
                double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
                double along = nx * vx + ny * vy + nz * vz;
                vx -= nx * along; vy -= ny * along; vz -= nz * along;
            }
            rx = w * vx; ry = w * vy; rz = w * vz;
        }

        /// <summary>nᵀ W_i n for a unit n (1/kg).</summary>
        public static double AlongMobility(ChainState c, int i, double nx, double ny, double nz)
        {
            Mobility(c, i, nx, ny, nz, out double rx, out double ry, out double rz);
            return nx * rx + ny * ry + nz * rz;
        }

        /// <summary>The pull δΛ_i − δΛ_{i−1} (N·s²) of this solution on particle i (a broken segment carries none).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Pull(ChainState c, int i, out double px, out double py, out double pz)
        {
            px = 0; py = 0; pz = 0;
            if (i < c.SegmentCount && !c.Broken[i]) { px = c.StepX[i]; py = c.StepY[i]; pz = c.StepZ[i]; }
            if (i > 0 && !c.Broken[i - 1]) { px -= c.StepX[i - 1]; py -= c.StepY[i - 1]; pz -= c.StepZ[i - 1]; }
        }

        /// <summary>Particle i's motion W_i (pull) under this solution (m), without a held contact's gap allowance.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Motion(ChainState c, int i, out double mx, out double my, out double mz)
        {
            Pull(c, i, out double px, out double py, out double pz);
            Mobility(c, i, px, py, pz, out mx, out my, out mz);
        }

        /// <summary>Inverse of a symmetric 3×3 matrix (by cofactors, in double).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Invert(double xx, double xy, double xz, double yy, double yz, double zz,
            out double ixx, out double ixy, out double ixz, out double iyy, out double iyz, out double izz)
        {
            double cxx = yy * zz - yz * yz, cxy = xz * yz - xy * zz, cxz = xy * yz - xz * yy;
            double inverse = 1.0 / (xx * cxx + xy * cxy + xz * cxz);
            ixx = cxx * inverse; ixy = cxy * inverse; ixz = cxz * inverse;
            iyy = (xx * zz - xz * xz) * inverse; iyz = (xy * xz - xx * yz) * inverse; izz = (xx * yy - xy * xy) * inverse;
        }
    }
}
