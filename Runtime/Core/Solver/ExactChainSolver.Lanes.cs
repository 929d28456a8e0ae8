using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    internal static partial class ExactChainSolver
    {
        /// <summary>
        /// <see cref="AssembleRows"/> on runs of <see cref="VectorPath.FloatLanes"/> segments (an unbroken chain without
        /// plasticity), each run as two halves of <see cref="VectorPath.DoubleLanes"/> (<see cref="AssembleHalf{THalf}"/>).
        /// A run with a segment the rows treat apart — a vanishing or non-finite span, no mobility and no compliance, or a
        /// force far off its segment while the chain has contacts — goes to <see cref="AssembleRows"/> whole, before anything
        /// of it is stored. Returns the first segment not assembled (the rows take the rest). <paramref name="views"/>: the
        /// chain's views, built once per host step (<see cref="StepViews"/>).
        /// </summary>
        private static int AssembleLanes(ChainState c, in StepViews views, double invH2, double gammaAll, bool first, bool tensionOnly)
        {
            int s = c.SegmentCount, lanes = VectorPath.FloatLanes, runs = s / lanes;
            var p = new AssemblyParameters { InvH2 = invH2, Gamma = gammaAll, First = first, TensionOnly = tensionOnly, Contacts = c.ContactCount > 0 };
            // the views copied into locals, one by one: indexed through the reference, each access would add an address
            // computation, and a copy of the whole struct takes a bulk move with write barriers. Each is cut to the runs
            // (floats) or their halves (doubles, pairs): views of one length share their bounds checks (the loop bound
            // drops the floats' and one check per half serves every double output), where each view's own stored
            // length took a check of its own per access
            int pairs = 2 * runs;
            ReadOnlySpan<Vector<float>> wa = views.WA.Slice(0, runs), wb = views.WB.Slice(0, runs);
            ReadOnlySpan<Vector<float>> dxA = views.DxA.Slice(0, runs), dxB = views.DxB.Slice(0, runs), dyA = views.DyA.Slice(0, runs), dyB = views.DyB.Slice(0, runs), dzA = views.DzA.Slice(0, runs), dzB = views.DzB.Slice(0, runs);
            ReadOnlySpan<Vector<float>> dlxA = views.DlxA.Slice(0, runs), dlxB = views.DlxB.Slice(0, runs), dlyA = views.DlyA.Slice(0, runs), dlyB = views.DlyB.Slice(0, runs), dlzA = views.DlzA.Slice(0, runs), dlzB = views.DlzB.Slice(0, runs);
            ReadOnlySpan<Vector<float>> pxA = views.PxA.Slice(0, runs), pxB = views.PxB.Slice(0, runs), pyA = views.PyA.Slice(0, runs), pyB = views.PyB.Slice(0, runs), pzA = views.PzA.Slice(0, runs), pzB = views.PzB.Slice(0, runs);
            ReadOnlySpan<Vector<float>> lxA = views.LxA.Slice(0, runs), lxB = views.LxB.Slice(0, runs), lyA = views.LyA.Slice(0, runs), lyB = views.LyB.Slice(0, runs), lzA = views.LzA.Slice(0, runs), lzB = views.LzB.Slice(0, runs);
            ReadOnlySpan<Vector<float>> rest = views.Rest.Slice(0, runs), compliance = views.Compliance.Slice(0, runs), lastTension = views.LastTension.Slice(0, runs);
            Span<Vector<double>> rx = views.ResidualXOut.Slice(0, pairs), ry = views.ResidualYOut.Slice(0, pairs), rz = views.ResidualZOut.Slice(0, pairs);
            Span<Vector<double>> axial = views.AxialOut.Slice(0, pairs), transverse = views.TransverseOut.Slice(0, pairs), estimate = views.EstimateOut.Slice(0, pairs), effectiveRest = views.RestOut.Slice(0, pairs);
            Span<Vector<float>> dirX = views.DirXOut.Slice(0, runs), dirY = views.DirYOut.Slice(0, runs), dirZ = views.DirZOut.Slice(0, runs), length = views.LengthOut.Slice(0, runs);
            Span<bool> assembled = views.AssembledOut;
            // the run's float inputs read once (one check each) for both halves, which read them from there; the halves'
            // results in the chain's fields too (as locals they would be zeroed on every call)
            ref RunInputs r = ref c.AssemblyRun;
            ref AssembledLanes low = ref c.AssemblyLow, high = ref c.AssemblyHigh;
            for (int k = 0; k < wa.Length; k++)
            {
                r.WA = wa[k]; r.WB = wb[k];
                r.DxA = dxA[k]; r.DxB = dxB[k]; r.DyA = dyA[k]; r.DyB = dyB[k]; r.DzA = dzA[k]; r.DzB = dzB[k];
                r.DlxA = dlxA[k]; r.DlxB = dlxB[k]; r.DlyA = dlyA[k]; r.DlyB = dlyB[k]; r.DlzA = dlzA[k]; r.DlzB = dlzB[k];
                r.PxA = pxA[k]; r.PxB = pxB[k]; r.PyA = pyA[k]; r.PyB = pyB[k]; r.PzA = pzA[k]; r.PzB = pzB[k];
                r.LxA = lxA[k]; r.LxB = lxB[k]; r.LyA = lyA[k]; r.LyB = lyB[k]; r.LzA = lzA[k]; r.LzB = lzB[k];
                r.Rest = rest[k]; r.Compliance = compliance[k]; r.LastTension = lastTension[k];
                AssembleHalf<LowHalf>(in r, in views, k, in p, out low);
                AssembleHalf<HighHalf>(in r, in views, k, in p, out high);
                int j = k * lanes;
                if (!Vector.EqualsAll(low.Unusual | high.Unusual, Vector<long>.Zero))
                {
                    AssembleRows(c, j, j + lanes, invH2, gammaAll, first, tensionOnly);
                    continue;
                }
                if (!Vector.EqualsAll(low.Rigid | high.Rigid, Vector<long>.Zero)) c.RigidInSolve = true;
                int a = 2 * k, b = 2 * k + 1;
                rx[a] = low.Rx; ry[a] = low.Ry; rz[a] = low.Rz;
                axial[a] = low.Axial; transverse[a] = low.Transverse; estimate[a] = low.Estimate; effectiveRest[a] = low.Rest;
                rx[b] = high.Rx; ry[b] = high.Ry; rz[b] = high.Rz;
                axial[b] = high.Axial; transverse[b] = high.Transverse; estimate[b] = high.Estimate; effectiveRest[b] = high.Rest;
                dirX[k] = Vector.Narrow(low.Nx, high.Nx); dirY[k] = Vector.Narrow(low.Ny, high.Ny); dirZ[k] = Vector.Narrow(low.Nz, high.Nz);
                length[k] = Vector.Narrow(low.Length, high.Length);
                assembled.Slice(j, lanes).Fill(true);
            }
            return runs * lanes;
        }

        /// <summary>
        /// The rows of one half of run k (<typeparamref name="THalf"/>: <see cref="LowHalf"/> or <see cref="HighHalf"/>): each
        /// lane does <see cref="AssembleRows"/>'s operations in its order, and both sides of each of its branches are computed
        /// on every lane and selected, so every lane keeps the row's bits.
        /// </summary>
        private static void AssembleHalf<THalf>(in RunInputs v, in StepViews views, int k, in AssemblyParameters p, out AssembledLanes o) where THalf : struct
        {
            int h = 2 * k + (typeof(THalf) == typeof(HighHalf) ? 1 : 0);
            Vector<double> zero = Vector<double>.Zero, one = Vector<double>.One, invH2 = new Vector<double>(p.InvH2);
            // ChainState.Change, Component and Normalise
            Vector<double> ddx = (Wide<THalf>(v.DxB) - Wide<THalf>(v.DxA)) + (Wide<THalf>(v.DlxB) - Wide<THalf>(v.DlxA));
            Vector<double> ddy = (Wide<THalf>(v.DyB) - Wide<THalf>(v.DyA)) + (Wide<THalf>(v.DlyB) - Wide<THalf>(v.DlyA));
            Vector<double> ddz = (Wide<THalf>(v.DzB) - Wide<THalf>(v.DzA)) + (Wide<THalf>(v.DlzB) - Wide<THalf>(v.DlzA));
            Vector<double> sx = Wide<THalf>(v.PxB) - Wide<THalf>(v.PxA), lx = Wide<THalf>(v.LxB) - Wide<THalf>(v.LxA);
            Vector<double> sy = Wide<THalf>(v.PyB) - Wide<THalf>(v.PyA), ly = Wide<THalf>(v.LyB) - Wide<THalf>(v.LyA);
            Vector<double> sz = Wide<THalf>(v.PzB) - Wide<THalf>(v.PzA), lz = Wide<THalf>(v.LzB) - Wide<THalf>(v.LzA);
            Vector<double> cx = sx + (lx + ddx), cy = sy + (ly + ddy), cz = sz + (lz + ddz);
            Vector<double> len = Vector.SquareRoot(cx * cx + cy * cy + cz * cz);
            Vector<long> unusual = ~(Vector.GreaterThan(len, new Vector<double>(1e-12)) & Vector.LessThanOrEqual(len, new Vector<double>(float.MaxValue)));
            Vector<double> inv = one / len;
            Vector<double> nx = cx * inv, ny = cy * inv, nz = cz * inv;
            Vector<double> alpha = Wide<THalf>(v.Compliance);
            Vector<double> mobility = Wide<THalf>(v.WA) + Wide<THalf>(v.WB);
            Vector<long> rigid = Vector.Equals(alpha, zero);
            unusual |= Vector.Equals(mobility, zero) & rigid;
            // g = alpha > 0 ? gammaAll : 0, damped where g > 0
            Vector<long> compliant = Vector.GreaterThan(alpha, zero);
            Vector<double> g = Vector.ConditionalSelect(compliant, new Vector<double>(p.Gamma), zero);
            Vector<double> restJ = Wide<THalf>(v.Rest);
            Vector<double> alphaTilde = alpha * invH2, restEffective = restJ;
            if (p.Gamma > 0.0)
            {
                Vector<double> rate;
                if (p.TensionOnly) rate = nx * ddx + ny * ddy + nz * ddz;
                else
                {
                    // StartLength: its components add 0.0 to the remainders' difference, which changes at most the sign of a
                    // zero, and the squares drop that
                    Vector<double> ox = sx + lx, oy = sy + ly, oz = sz + lz;
                    rate = len - Vector.SquareRoot(ox * ox + oy * oy + oz * oz);
                }
                Vector<double> onePlusG = one + g;
                restEffective = Vector.ConditionalSelect(compliant, (restJ + g * (len - rate)) / onePlusG, restJ);
                alphaTilde = Vector.ConditionalSelect(compliant, alphaTilde / onePlusG, alphaTilde);
            }
            Vector<double> fx = views.Fx[h], fy = views.Fy[h], fz = views.Fz[h];
            Vector<double> magnitude = Vector.SquareRoot(fx * fx + fy * fy + fz * fz);
            Vector<long> loaded = Vector.GreaterThan(magnitude, zero);
            Vector<double> sense = Vector.ConditionalSelect(Vector.GreaterThanOrEqual(fx * nx + fy * ny + fz * nz, zero), one, -one);
            Vector<double> inverse = sense / magnitude;
            Vector<double> signed = Vector.ConditionalSelect(loaded, sense * magnitude, zero);
            Vector<double> ex = Vector.ConditionalSelect(loaded, fx * inverse, nx);
            Vector<double> ey = Vector.ConditionalSelect(loaded, fy * inverse, ny);
            Vector<double> ez = Vector.ConditionalSelect(loaded, fz * inverse, nz);
            // beside a held contact a force far off its segment takes the rows' test (BesideHeldContact)
            if (p.Contacts) unusual |= loaded & Vector.LessThan(ex * nx + ey * ny + ez * nz, new Vector<double>(MinForceAlignment));
            Vector<double> last = Wide<THalf>(v.LastTension);
            Vector<double> tension = p.First ? Vector.Abs(last) : Vector.Abs(signed * invH2);
            Vector<double> target = restEffective + alphaTilde * signed;
            Vector<double> floor = new Vector<double>(1e-6) * restJ;
            Vector<double> geometric = Vector.ConditionalSelect(Vector.LessThan(target, floor), floor, target) * invH2;
            Vector<double> cap = new Vector<double>(MaxTransverseComplianceRatio) * mobility;
            Vector<long> axialOnly = ~Vector.LessThan(geometric, cap * tension);
            if (!p.TensionOnly)
            {
                axialOnly |= Vector.LessThan(p.First ? last : signed, zero); // pushing
                ex = Vector.ConditionalSelect(axialOnly, nx, ex); ey = Vector.ConditionalSelect(axialOnly, ny, ey); ez = Vector.ConditionalSelect(axialOnly, nz, ez);
            }
            o.Unusual = unusual; o.Rigid = rigid;
            o.Nx = nx; o.Ny = ny; o.Nz = nz; o.Length = len;
            o.Transverse = Vector.ConditionalSelect(axialOnly, cap, geometric / tension);
            o.Estimate = tension; o.Axial = alphaTilde; o.Rest = restEffective;
            o.Rx = len * nx - target * ex; o.Ry = len * ny - target * ey; o.Rz = len * nz - target * ez;
        }

        /// <summary>The half <typeparamref name="THalf"/> of a run of floats, as doubles (exact).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<double> Wide<THalf>(Vector<float> run) where THalf : struct
        {
            ChainState.Widen(run, out Vector<double> low, out Vector<double> high);
            return typeof(THalf) == typeof(HighHalf) ? high : low;
        }

        /// <summary>Type argument of the half kernels: the first <see cref="VectorPath.DoubleLanes"/> lanes of a run.</summary>
        private struct LowHalf { }

        /// <summary>Type argument of the half kernels: the last <see cref="VectorPath.DoubleLanes"/> lanes of a run.</summary>
        private struct HighHalf { }

        /// <summary>The per-call inputs of <see cref="AssembleHalf{THalf}"/>.</summary>
        private struct AssemblyParameters
        {
            public double InvH2, Gamma;
            public bool First, TensionOnly, Contacts;
        }

        /// <summary>One half run's results of <see cref="AssembleHalf{THalf}"/>, stored only when no lane of the run is unusual.</summary>
        internal struct AssembledLanes
        {
            public Vector<long> Unusual, Rigid;
            public Vector<double> Nx, Ny, Nz, Length, Rx, Ry, Rz, Axial, Transverse, Estimate, Rest;
        }

        /// <summary>One run's float inputs of <see cref="AssembleHalf{THalf}"/> (the fields of <see cref="StepViews"/> at run k).</summary>
        internal struct RunInputs
        {
            public Vector<float> WA, WB, DxA, DxB, DyA, DyB, DzA, DzB, DlxA, DlxB, DlyA, DlyB, DlzA, DlzB;
            public Vector<float> PxA, PxB, PyA, PyB, PzA, PzB, LxA, LxB, LyA, LyB, LzA, LzB, Rest, Compliance, LastTension;
        }

        /// <summary>An array's first s entries as runs of <see cref="VectorPath.DoubleLanes"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Span<Vector<double>> Doubles(double[] values, int s) => VectorPath.AsLanes(ChainState.Exactly(values, s));

        /// <summary>
        /// The views of one chain the exact solve's assembly on lanes reads and writes, built once per host step (the step of
        /// <see cref="Rope"/>, for the exact solve on lanes) instead of once per iteration: the arrays of a <see cref="ChainState"/>
        /// are fixed at its construction. <see cref="Chain"/> is the chain they view (null for none: a kernel then builds
        /// its own). For <see cref="AssembleLanes"/>: the inputs of <see cref="AssembleHalf{THalf}"/> as runs of
        /// <see cref="VectorPath.FloatLanes"/> (A: a segment's first particle, B: its second; the forces as runs of
        /// <see cref="VectorPath.DoubleLanes"/>) and its outputs (…Out, the doubles as runs of
        /// <see cref="VectorPath.DoubleLanes"/>: one check per store, not a slice each); for <see cref="MoveParticlesLanes"/>
        /// and <see cref="ApplyLanes"/> the steps, motions, λ, length errors and active flags besides. Each kernel cuts the
        /// views it copies to its runs (floats) or their halves (doubles): views of one length share their bounds checks.
        /// </summary>
        internal readonly ref struct StepViews
        {
            public readonly ChainState Chain;
            public readonly ReadOnlySpan<Vector<float>> WA, WB, DxA, DyA, DzA, DlxA, DlyA, DlzA;
            public readonly Span<Vector<float>> DxB, DyB, DzB, DlxB, DlyB, DlzB;
            public readonly ReadOnlySpan<Vector<float>> PxA, PxB, PyA, PyB, PzA, PzB, LxA, LxB, LyA, LyB, LzA, LzB, Rest, Compliance, LastTension;
            public readonly Span<Vector<double>> Fx, Fy, Fz;
            public readonly Span<Vector<double>> ResidualXOut, ResidualYOut, ResidualZOut, AxialOut, TransverseOut, EstimateOut, RestOut;
            public readonly Span<Vector<float>> DirXOut, DirYOut, DirZOut, LengthOut;
            public readonly Span<bool> AssembledOut;
            /// <summary>
            /// For <see cref="MoveParticlesLanes"/> and <see cref="ApplyLanes"/>: the steps δΛ at each segment (…A) and at
            /// its second particle (…B, the spare entry s included), the motions at both ends, λ, the length errors and
            /// the active flags (their forces, directions, lengths, rest lengths and estimates are the assembly's views).
            /// </summary>
            public readonly Span<Vector<double>> StepXA, StepYA, StepZA, StepXB, StepYB, StepZB;
            public readonly Span<Vector<double>> MotionXA, MotionYA, MotionZA, MotionXB, MotionYB, MotionZB, Lambda, LengthError;
            public readonly Span<bool> Active;
            /// <summary>For <see cref="SegmentForceSystem.PrepareBlocks"/> on lanes: the free blocks' six entries (ChainState.BlockXX … BlockZZ).</summary>
            public readonly Span<Vector<double>> BlockXX, BlockXY, BlockXZ, BlockYY, BlockYZ, BlockZZ;

            /// <summary>
            /// The views of chain c (its arrays at c.SegmentCount) when <paramref name="build"/>, else none (built in place
            /// either way: a conditional between the two would copy the views).
            /// </summary>
            public StepViews(ChainState c, bool build)
            {
                this = default;
                if (!build) return;
                Chain = c;
                int s = c.SegmentCount;
                WA = A(c.InverseMass, s); WB = B(c.InverseMass, s);
                DxA = A(c.DX, s); DxB = B(c.DX, s); DyA = A(c.DY, s); DyB = B(c.DY, s); DzA = A(c.DZ, s); DzB = B(c.DZ, s);
                DlxA = A(c.DLowX, s); DlxB = B(c.DLowX, s); DlyA = A(c.DLowY, s); DlyB = B(c.DLowY, s); DlzA = A(c.DLowZ, s); DlzB = B(c.DLowZ, s);
                PxA = A(c.PrevX, s); PxB = B(c.PrevX, s); PyA = A(c.PrevY, s); PyB = B(c.PrevY, s); PzA = A(c.PrevZ, s); PzB = B(c.PrevZ, s);
                LxA = A(c.LowX, s); LxB = B(c.LowX, s); LyA = A(c.LowY, s); LyB = B(c.LowY, s); LzA = A(c.LowZ, s); LzB = B(c.LowZ, s);
                Rest = A(c.RestLength, s); Compliance = A(c.Compliance, s); LastTension = A(c.Tension, s);
                Fx = MemoryMarshal.Cast<double, Vector<double>>(ChainState.Exactly(c.ForceX, s));
                Fy = MemoryMarshal.Cast<double, Vector<double>>(ChainState.Exactly(c.ForceY, s));
                Fz = MemoryMarshal.Cast<double, Vector<double>>(ChainState.Exactly(c.ForceZ, s));
                ResidualXOut = Doubles(c.ResidualX, s); ResidualYOut = Doubles(c.ResidualY, s); ResidualZOut = Doubles(c.ResidualZ, s);
                AxialOut = Doubles(c.AxialCompliance, s); TransverseOut = Doubles(c.TransverseCompliance, s); EstimateOut = Doubles(c.EstimatedTension, s);
                RestOut = Doubles(c.EffectiveRest, s);
                DirXOut = VectorPath.AsLanes(ChainState.Exactly(c.DirX, s)); DirYOut = VectorPath.AsLanes(ChainState.Exactly(c.DirY, s));
                DirZOut = VectorPath.AsLanes(ChainState.Exactly(c.DirZ, s)); LengthOut = VectorPath.AsLanes(ChainState.Exactly(c.Length, s));
                AssembledOut = ChainState.Exactly(c.Assembled, s);
                StepXA = Doubles(c.StepX, s); StepYA = Doubles(c.StepY, s); StepZA = Doubles(c.StepZ, s);
                StepXB = Later(c.StepX, s); StepYB = Later(c.StepY, s); StepZB = Later(c.StepZ, s);
                MotionXA = Doubles(c.MotionX, s); MotionYA = Doubles(c.MotionY, s); MotionZA = Doubles(c.MotionZ, s);
                MotionXB = Later(c.MotionX, s); MotionYB = Later(c.MotionY, s); MotionZB = Later(c.MotionZ, s);
                Lambda = Doubles(c.Lambda, s); LengthError = Doubles(c.LengthError, s);
                Active = ChainState.Exactly(c.Active, s);
                BlockXX = Doubles(c.BlockXX, s); BlockXY = Doubles(c.BlockXY, s); BlockXZ = Doubles(c.BlockXZ, s);
                BlockYY = Doubles(c.BlockYY, s); BlockYZ = Doubles(c.BlockYZ, s); BlockZZ = Doubles(c.BlockZZ, s);
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static Span<Vector<double>> Later(double[] values, int s) => VectorPath.AsLanes(ChainState.Shifted(values, s));

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static ReadOnlySpan<Vector<float>> A(float[] values, int s) => VectorPath.AsLanes(ChainState.Exactly(values, s));

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static Span<Vector<float>> B(float[] values, int s) => VectorPath.AsLanes(ChainState.Shifted(values, s));
        }

        /// <summary>
        /// <see cref="MoveParticles{T}"/> of a chain without contacts or broken segments on lanes: the particle pass (motion
        /// w_i·(δΛ_i − δΛ_{i−1}) and the displacement's double split) on runs of <see cref="VectorPath.FloatLanes"/>
        /// particles from particle 1; the segments' second-order length errors from the recorded motions are left to
        /// <see cref="ApplyLanes"/> (lengthErrors), which has the runs' directions and rest lengths at hand. Each lane does
        /// the scalar pass's operations in its order, so the bits are the same. <paramref name="views"/>: the chain's views,
        /// built once per host step (<see cref="StepViews"/>, by <see cref="Apply"/>'s caller) or for this call.
        /// </summary>
        private static void MoveParticlesLanes(ChainState c, in StepViews views)
        {
            int s = c.SegmentCount, lanes = VectorPath.FloatLanes, runs = s / lanes;
            // particle 0, whose pull has no segment before it
            MoveParticle(c, 0, c.StepX[0], c.StepY[0], c.StepZ[0]);
            // the last particle's pull, −δΛ_{s−1}, is (−0) − δΛ_{s−1} on the lanes (the same bits for every δΛ, zeros
            // included): with −0 in the step arrays' spare entry the runs reach particle s, with no scalar tail when s is a
            // multiple of the lanes
            c.StepX[s] = -0.0; c.StepY[s] = -0.0; c.StepZ[s] = -0.0;
            // the views once per host step (copied here, not per run and axis)
            // (cut to the runs or their halves: views of one length share their bounds checks)
            int pairs = 2 * runs;
            ReadOnlySpan<Vector<float>> w = views.WB.Slice(0, runs);
            var x = new MoveViews(views.StepXB.Slice(0, pairs), views.StepXA.Slice(0, pairs), views.MotionXB.Slice(0, pairs), views.DxB.Slice(0, runs), views.DlxB.Slice(0, runs));
            var y = new MoveViews(views.StepYB.Slice(0, pairs), views.StepYA.Slice(0, pairs), views.MotionYB.Slice(0, pairs), views.DyB.Slice(0, runs), views.DlyB.Slice(0, runs));
            var z = new MoveViews(views.StepZB.Slice(0, pairs), views.StepZA.Slice(0, pairs), views.MotionZB.Slice(0, pairs), views.DzB.Slice(0, runs), views.DlzB.Slice(0, runs));
            for (int k = 0; k < w.Length; k++)
            {
                ChainState.Widen(w[k], out Vector<double> wLow, out Vector<double> wHigh);
                MoveLanes(in x, k, wLow, wHigh);
                MoveLanes(in y, k, wLow, wHigh);
                MoveLanes(in z, k, wLow, wHigh);
            }
            for (int i = 1 + runs * lanes; i <= s; i++)
                MoveParticle(c, i, c.StepX[i] - c.StepX[i - 1], c.StepY[i] - c.StepY[i - 1], c.StepZ[i] - c.StepZ[i - 1]);
        }

        /// <summary>Particle i moved by its inverse mass times the pull (N·s²), recorded as its motion (the scalar pass's step).</summary>
        private static void MoveParticle(ChainState c, int i, double px, double py, double pz)
        {
            double wi = c.InverseMass[i];
            double mx = wi * px, my = wi * py, mz = wi * pz;
            c.AddDisplacement(i, mx, my, mz);
            c.MotionX[i] = mx; c.MotionY[i] = my; c.MotionZ[i] = mz;
        }

        /// <summary>
        /// One axis of run k of particles 1 + k·FloatLanes …: motion m = w·(δΛ_i − δΛ_{i−1}) (wLow, wHigh: the run's inverse
        /// masses), added to the displacement d + low in double and split back as <see cref="ChainState.Add"/> does.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void MoveLanes(in MoveViews v, int k, Vector<double> wLow, Vector<double> wHigh)
        {
            Vector<double> mLow = wLow * (v.After[2 * k] - v.Before[2 * k]), mHigh = wHigh * (v.After[2 * k + 1] - v.Before[2 * k + 1]);
            v.Motion[2 * k] = mLow; v.Motion[2 * k + 1] = mHigh;
            ChainState.Widen(v.D[k], out Vector<double> dLow, out Vector<double> dHigh);
            ChainState.Widen(v.Low[k], out Vector<double> lLow, out Vector<double> lHigh);
            Vector<double> xLow = (dLow + lLow) + mLow, xHigh = (dHigh + lHigh) + mHigh;
            Vector<float> f = Vector.Narrow(xLow, xHigh);
            ChainState.Widen(f, out Vector<double> fLow, out Vector<double> fHigh);
            v.D[k] = f;
            v.Low[k] = Vector.Narrow(xLow - fLow, xHigh - fHigh);
        }

        /// <summary>
        /// One axis of <see cref="MoveParticlesLanes"/> as runs from particle 1: the step δΛ at and before each particle (the
        /// step arrays' spare entry s included), its motion and its displacement with remainder.
        /// </summary>
        private readonly ref struct MoveViews
        {
            public readonly ReadOnlySpan<Vector<double>> After, Before;
            public readonly Span<Vector<double>> Motion;
            public readonly Span<Vector<float>> D, Low;

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public MoveViews(ReadOnlySpan<Vector<double>> after, ReadOnlySpan<Vector<double>> before, Span<Vector<double>> motion, Span<Vector<float>> d, Span<Vector<float>> low)
            {
                After = after; Before = before; Motion = motion; D = d; Low = low;
            }
        }

        /// <summary><see cref="LengthError"/> per lane (floor: 1e-6 times the rest length).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<double> LengthErrors(Vector<double> ux, Vector<double> uy, Vector<double> uz, Vector<double> ex, Vector<double> ey, Vector<double> ez,
            Vector<double> length, Vector<double> floor, Vector<double> two)
        {
            Vector<double> along = ux * ex + uy * ey + uz * ez;
            Vector<double> perp = ux * ux + uy * uy + uz * uz - along * along;
            return perp / (two * Vector.ConditionalSelect(Vector.LessThan(length, floor), floor, length));
        }

        /// <summary>The length errors of the active segments from … to − 1, row by row.</summary>
        private static void LengthErrorRows(ChainState c, int from, int to)
        {
            for (int j = from; j < to; j++)
            {
                if (!c.Active[j]) continue;
                c.LengthError[j] = LengthError(c.MotionX[j + 1] - c.MotionX[j], c.MotionY[j + 1] - c.MotionY[j], c.MotionZ[j + 1] - c.MotionZ[j],
                    c.DirX[j], c.DirY[j], c.DirZ[j], c.Length[j], c.RestLength[j]);
            }
        }

        /// <summary>
        /// True when the <see cref="VectorPath.FloatLanes"/> flags at flags[index …] are all true: a C# true is the byte 1, so
        /// eight or four flags are read as one word (any other byte reads as not all true, which only sends the run row by row).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool AllTrue(ReadOnlySpan<bool> flags, int index)
        {
            ReadOnlySpan<byte> run = MemoryMarshal.AsBytes(flags.Slice(index, VectorPath.FloatLanes));
            if (run.Length == 8) return MemoryMarshal.Read<ulong>(run) == 0x0101010101010101UL;
            if (run.Length == 4) return MemoryMarshal.Read<uint>(run) == 0x01010101U;
            for (int k = 0; k < run.Length; k++)
                if (run[k] != 1) return false;
            return true;
        }

        /// <summary>
        /// <see cref="ApplyRows"/> on runs of <see cref="VectorPath.FloatLanes"/> active segments whose tests all pass
        /// quietly — no tension above twice its estimate, a pushing segment's error within the tolerance, a pulling one's
        /// within the round-off floor — which then only accumulate their forces and write λ (the lanes' bits are the rows').
        /// Any other run goes to <see cref="ApplyRows"/> whole, in order, before anything of it is stored. Returns the
        /// first segment not done. With <paramref name="lengthErrors"/> (after <see cref="MoveParticlesLanes"/>) each run
        /// first writes its active segments' length errors (<see cref="LengthErrors"/> on lanes, a run with a released
        /// segment and the tail row by row: <see cref="LengthErrorRows"/>), so every error is written before the rows or
        /// <see cref="Mismatched"/> read it.
        /// </summary>
        private static int ApplyLanes(ChainState c, in StepViews views, bool tensionOnly, double invH2, bool lengthErrors, ref ConvergenceTests tests)
        {
            int s = c.SegmentCount, lanes = VectorPath.FloatLanes, runs = s / lanes;
            // the views once per host step (StepViews), copied into locals one by one and cut to the runs or their halves
            // as AssembleLanes does (views of one length share their bounds checks)
            int pairs = 2 * runs;
            ReadOnlySpan<Vector<float>> dirX = views.DirXOut.Slice(0, runs), dirY = views.DirYOut.Slice(0, runs), dirZ = views.DirZOut.Slice(0, runs);
            ReadOnlySpan<Vector<float>> rest = views.Rest.Slice(0, runs), length = views.LengthOut.Slice(0, runs);
            Span<Vector<double>> error = views.LengthError.Slice(0, pairs);
            ReadOnlySpan<Vector<double>> estimate = views.EstimateOut.Slice(0, pairs);
            ReadOnlySpan<Vector<double>> ax = views.MotionXA.Slice(0, pairs), ay = views.MotionYA.Slice(0, pairs), az = views.MotionZA.Slice(0, pairs);
            ReadOnlySpan<Vector<double>> bx = views.MotionXB.Slice(0, pairs), by = views.MotionYB.Slice(0, pairs), bz = views.MotionZB.Slice(0, pairs);
            ReadOnlySpan<Vector<double>> sx = views.StepXA.Slice(0, pairs), sy = views.StepYA.Slice(0, pairs), sz = views.StepZA.Slice(0, pairs);
            Span<Vector<double>> fx = views.Fx.Slice(0, pairs), fy = views.Fy.Slice(0, pairs), fz = views.Fz.Slice(0, pairs);
            Span<Vector<double>> lambda = views.Lambda.Slice(0, pairs);
            ReadOnlySpan<bool> active = views.Active;
            Vector<double> h2 = new Vector<double>(invH2), two = new Vector<double>(2.0), tolerance = new Vector<double>(NonlinearTolerance);
            Vector<double> floor = new Vector<double>(tests.Floor), micro = new Vector<double>(1e-6);
            for (int k = 0; k < dirX.Length; k++)
            {
                if (!AllTrue(active, k * lanes))
                {
                    if (lengthErrors) LengthErrorRows(c, k * lanes, (k + 1) * lanes);
                    ApplyRows(c, k * lanes, (k + 1) * lanes, tensionOnly, invH2, ref tests);
                    continue;
                }
                ChainState.Widen(dirX[k], out Vector<double> exLow, out Vector<double> exHigh);
                ChainState.Widen(dirY[k], out Vector<double> eyLow, out Vector<double> eyHigh);
                ChainState.Widen(dirZ[k], out Vector<double> ezLow, out Vector<double> ezHigh);
                ChainState.Widen(rest[k], out Vector<double> rLow, out Vector<double> rHigh);
                int a = 2 * k, b = 2 * k + 1;
                if (lengthErrors)
                {
                    // the run's second-order length errors (LengthErrors, as the rows' LengthError) from the motions just recorded
                    ChainState.Widen(length[k], out Vector<double> lengthLow, out Vector<double> lengthHigh);
                    error[a] = LengthErrors(bx[a] - ax[a], by[a] - ay[a], bz[a] - az[a], exLow, eyLow, ezLow, lengthLow, micro * rLow, two);
                    error[b] = LengthErrors(bx[b] - ax[b], by[b] - ay[b], bz[b] - az[b], exHigh, eyHigh, ezHigh, lengthHigh, micro * rHigh, two);
                }
                Vector<double> gxLow = fx[a] + sx[a], gyLow = fy[a] + sy[a], gzLow = fz[a] + sz[a];
                Vector<double> gxHigh = fx[b] + sx[b], gyHigh = fy[b] + sy[b], gzHigh = fz[b] + sz[b];
                // λ = −(g·n): the sign bit flipped as the scalar negation does (Vector's unary minus may be 0 − x, which
                // makes −(+0) +0)
                Vector<double> sign = new Vector<double>(-0.0);
                Vector<double> lLow = (gxLow * exLow + gyLow * eyLow + gzLow * ezLow) ^ sign, lHigh = (gxHigh * exHigh + gyHigh * eyHigh + gzHigh * ezHigh) ^ sign;
                Vector<long> loud = Loud(lLow, error[a], estimate[a], rLow, h2, two, tolerance, floor) | Loud(lHigh, error[b], estimate[b], rHigh, h2, two, tolerance, floor);
                if (!Vector.EqualsAll(loud, Vector<long>.Zero))
                {
                    ApplyRows(c, k * lanes, (k + 1) * lanes, tensionOnly, invH2, ref tests);
                    continue;
                }
                fx[a] = gxLow; fy[a] = gyLow; fz[a] = gzLow; fx[b] = gxHigh; fy[b] = gyHigh; fz[b] = gzHigh;
                lambda[a] = lLow; lambda[b] = lHigh;
            }
            if (lengthErrors && runs * lanes < s) LengthErrorRows(c, runs * lanes, s);
            return runs * lanes;
        }

        /// <summary>
        /// Lanes of active segments (λ l, length error e, tension estimate, rest length r) on which a test of
        /// <see cref="ApplyRows"/> does something: the found tension −λ/h² above twice the estimate, a pushing segment's
        /// error above NonlinearTolerance·r, or a pulling one's not within the floor (a NaN error included, as in the rows).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<long> Loud(Vector<double> l, Vector<double> e, Vector<double> estimate, Vector<double> r,
            Vector<double> h2, Vector<double> two, Vector<double> tolerance, Vector<double> floor)
        {
            Vector<long> pushing = Vector.GreaterThan(l, Vector<double>.Zero);
            return Vector.GreaterThan((l ^ new Vector<double>(-0.0)) * h2, two * estimate)
                | (pushing & Vector.GreaterThan(e, tolerance * r))
                | Vector.AndNot(~Vector.LessThanOrEqual(e, floor), pushing);
        }

        /// <summary>
        /// <see cref="UpdateTensionOnlySet"/> on runs of <see cref="VectorPath.FloatLanes"/> segments of an unbroken chain:
        /// a run of active segments whose total force n·(Λ + δΛ) all still pull (≥ 0, as the rows test it) changes nothing
        /// and is skipped; any other run goes to <see cref="UpdateTensionOnlyRows"/>, in order. Returns the first segment
        /// not done.
        /// </summary>
        private static int UpdateTensionOnlyLanes(ChainState c, in StepViews views, ref bool changed, ref int first)
        {
            int s = c.SegmentCount, lanes = VectorPath.FloatLanes, runs = s / lanes, pairs = 2 * runs;
            // the host step's views, cut to the runs or their halves (views of one length share their bounds checks)
            ReadOnlySpan<Vector<float>> dirX = views.DirXOut.Slice(0, runs), dirY = views.DirYOut.Slice(0, runs), dirZ = views.DirZOut.Slice(0, runs);
            ReadOnlySpan<Vector<double>> fx = views.Fx.Slice(0, pairs), fy = views.Fy.Slice(0, pairs), fz = views.Fz.Slice(0, pairs);
            ReadOnlySpan<Vector<double>> dx = views.StepXA.Slice(0, pairs), dy = views.StepYA.Slice(0, pairs), dz = views.StepZA.Slice(0, pairs);
            ReadOnlySpan<bool> active = views.Active;
            for (int k = 0; k < dirX.Length; k++)
            {
                if (AllTrue(active, k * lanes))
                {
                    ChainState.Widen(dirX[k], out Vector<double> exLow, out Vector<double> exHigh);
                    ChainState.Widen(dirY[k], out Vector<double> eyLow, out Vector<double> eyHigh);
                    ChainState.Widen(dirZ[k], out Vector<double> ezLow, out Vector<double> ezHigh);
                    int a = 2 * k, b = 2 * k + 1;
                    Vector<double> alongLow = (fx[a] + dx[a]) * exLow + (fy[a] + dy[a]) * eyLow + (fz[a] + dz[a]) * ezLow;
                    Vector<double> alongHigh = (fx[b] + dx[b]) * exHigh + (fy[b] + dy[b]) * eyHigh + (fz[b] + dz[b]) * ezHigh;
                    if (Vector.GreaterThanOrEqualAll(alongLow, Vector<double>.Zero) && Vector.GreaterThanOrEqualAll(alongHigh, Vector<double>.Zero)) continue;
                }
                UpdateTensionOnlyRows(c, k * lanes, (k + 1) * lanes, ref changed, ref first);
            }
            return runs * lanes;
        }
    }
}
