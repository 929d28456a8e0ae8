using System;
using System.Numerics;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// The second-order integrator <see cref="TimeIntegrator.Bdf2"/>: x_{n+1} = (4x_n − x_{n−1})/3 + (2h/3)·v_{n+1},
    /// v_{n+1} = (4v_n − v_{n−1})/3 + (2h/3)·a_{n+1}. Each substep predicts d_pred = d_prev/3 + (2h/9)(4v − v_prev) + (4h²/9)·g
    /// (m; d_prev = x_n − x_{n−1}), runs the unchanged constraint solve with the effective step h_eff = 2h/3
    /// (α̃ = 9α/(4h²)), and sets v = base + d/h + Δ/(2h) with base = (4v − v_prev)/3 + (2h/3)·g − d_pred/h, where Δ is the
    /// displacement the chain solve applied (its constraint forces, a = Δ/h_eff²). Whatever else moved a particle after the
    /// prediction (collider push-out, friction, compliant pins) therefore enters the velocity as in backward Euler, as Δ/h,
    /// and does not bounce. Without a valid history (the first substep, a change of integrator or of h) the substep is
    /// backward Euler, which starts the history.
    /// </summary>
    public sealed partial class Rope
    {
        private bool historyValid;
        private double historyStep;

        /// <summary>
        /// True for a substep of a second-order run in which nothing but the rigid pins moves a particle between the
        /// prediction and the solve, nor after the solve (no colliders, no drag). Then the solve displacement Δ needs no
        /// passes of its own (<see cref="TrackSolveDisplacement"/>'s two per iteration), with the same arithmetic: a free
        /// particle's start mark is implied by its prediction (D + DLow = PredictedD + 0 when the solve starts), a kinematic
        /// one's is stored by the prediction (0) and after <see cref="MovePins"/> (<see cref="MarkPinnedSolveStarts"/>; the pinned particles are exactly the kinematic
        /// ones, <see cref="RefreshKinematic"/>), and the last end mark is taken in <see cref="UpdateVelocitiesSecondOrder"/>
        /// (<see cref="solveEndPending"/>).
        /// </summary>
        private bool solveMarksFused;

        /// <summary>True when the solve's last end mark is left to the velocity pass (see <see cref="solveMarksFused"/>).</summary>
        private bool solveEndPending;

        /// <summary>True while a free particle's Δ start mark is implied by its prediction, not stored (the first iteration of a substep with <see cref="solveMarksFused"/>).</summary>
        private bool solveStartImplied;
        /// <summary>
        /// Change of strain (dimensionless) within one substep beyond which the substep counts as violent (a teleported
        /// anchor, a rope released far stretched): the history restarts and the next substep is backward Euler. A
        /// linearisation that far from where the substep started makes the solve's displacement a poor force estimate, and
        /// BDF2 would carry it into two velocities. A rope that is merely stretched far (a soft lanyard at 100 % strain
        /// during an arrest) changes its strain smoothly and keeps the second-order scheme.
        /// </summary>
        public const float ViolentStrain = 0.5f;

        /// <summary>
        /// True when some intact segment's length at the solve's linearisation point differs from its length at the start
        /// of the substep by more than <see cref="ViolentStrain"/>·L.
        /// </summary>
        private bool Violent() => VectorPath.Enabled && chain.BrokenCount == 0 ? ViolentLanes() : ViolentRange(0, chain.SegmentCount);

        /// <summary><see cref="Violent"/> for the segments from … from + count − 1.</summary>
        private bool ViolentRange(int from, int count)
        {
            // spans of exactly count entries (the loop bound), B for particle j + 1: indexed without bounds checks
            ReadOnlySpan<float> length = ChainState.Range(chain.Length, from, count), rest = ChainState.Range(chain.RestLength, from, count);
            ReadOnlySpan<float> xA = ChainState.Range(chain.PrevX, from, count), yA = ChainState.Range(chain.PrevY, from, count), zA = ChainState.Range(chain.PrevZ, from, count);
            ReadOnlySpan<float> xB = ChainState.Range(chain.PrevX, from + 1, count), yB = ChainState.Range(chain.PrevY, from + 1, count), zB = ChainState.Range(chain.PrevZ, from + 1, count);
            ReadOnlySpan<bool> broken = ChainState.Range(chain.Broken, from, count);
            for (int j = 0; j < count; j++)
            {
                if (broken[j]) continue;
                float dx = xB[j] - xA[j], dy = yB[j] - yA[j], dz = zB[j] - zA[j];
                float start = MathF.Sqrt(dx * dx + dy * dy + dz * dz);
                if (MathF.Abs(length[j] - start) > ViolentStrain * rest[j]) return true;
            }
            return false;
        }

        /// <summary>
        /// True when the collision pass at the start of this substep pushed out a dynamic particle that was not in the contact
        /// set at the end of the substep before (<see cref="ChainState.ContactLoad"/> &gt; 0, not <see cref="ChainState.ContactNear"/>):
        /// an impact, a particle that came from beyond the contact margin into the collider within one substep. BDF2's two-step
        /// prediction carries no contact force for it, and the push-out then moves it by the whole penetration at once. When such
        /// a substep's solve ends violent and unconverged, <see cref="Step"/> runs the substep again as backward Euler (the most
        /// robust scheme; the next substep is backward Euler too, as after any violent substep). Measured on the stability
        /// grid's 1 GPa, 256-segment rope with a 10³ load hitting the sphere at 1/30 s: 24 contacts at once, 32 iterations
        /// unconverged and 1.16 MJ of length error under BDF2 (+0.63 J over the host step, +14.8 J bilateral); as backward
        /// Euler 9 contacts, 3 iterations, no gain. A smooth wrap (particles entering the margin first) and an impact the
        /// BDF2 solve converges on keep BDF2: restarting at every impact cost more cases than it passed.
        /// </summary>
        private bool NewImpact()
        {
            float[] load = chain.ContactLoad;
            bool[] near = chain.ContactNear;
            for (int i = 0; i < chain.ParticleCount; i++)
                if (load[i] > 0f && !near[i]) return true;
            return false;
        }

        /// <summary>
        /// Before an impact substep runs again as backward Euler (<see cref="NewImpact"/>): takes back what the failed BDF2
        /// solve handed on to the solve after it, so that the re-run starts as the substep did: the friction states the
        /// failed solve's last friction decision gave its contacts (<see cref="ChainContacts.DecideFriction"/>; no contact
        /// sticks or slides as a BDF2 substep starts, since friction in contact makes the substep backward Euler,
        /// <see cref="ChainState.HeldWithFriction"/>, and the re-run's detection would take them over), the contacts' normal
        /// scale (<paramref name="normalScale"/>, N·s², the value at the substep's start) and the plastic segments' branches
        /// (<see cref="SegmentPlasticity.RestoreBranches"/>). Before, the re-run's contacts started sticking with the damping ζ
        /// of the failed solve's violent normal impulses.
        /// </summary>
        private void ForgetFailedSolve(double normalScale)
        {
            for (int k = 0; k < chain.ContactCount; k++)
            {
                int i = chain.ContactList[k];
                chain.ContactSticking[i] = false;
                chain.ContactSliding[i] = false;
            }
            chain.ContactNormalScale = normalScale;
            chain.HeldWithFriction = false;
            chain.Plasticity?.RestoreBranches();
        }

        /// <summary>When an impact substep runs again as backward Euler (tests only: the re-run must not depend on the failed solve).</summary>
        internal enum ImpactRerun
        {
            /// <summary>The rule: when its BDF2 solve ends violent and unconverged.</summary>
            WhenUnconverged,
            /// <summary>After every BDF2 solve of an impact substep, converged or not.</summary>
            Always,
            /// <summary>At every impact substep, without its BDF2 solve (the re-run alone: what <see cref="Always"/> must give to the bit).</summary>
            WithoutFirstSolve,
        }

        /// <summary>Tests only: when an impact substep runs again (<see cref="ImpactRerun"/>; the rule by default).</summary>
        internal ImpactRerun ImpactRerunProbe { get; set; }

        /// <summary>The scheme substep h (s) runs: the chosen one, or backward Euler while the history does not fit it.</summary>
        private TimeIntegrator SubstepScheme(TimeIntegrator chosen, double h)
        {
            if (chosen == TimeIntegrator.BackwardEuler) { historyValid = false; return chosen; }
            return historyValid && h == historyStep ? chosen : TimeIntegrator.BackwardEuler;
        }

        /// <summary>Effective step h_eff (s) of the solve, α̃ = α/h_eff², for a substep h (s) of the scheme.</summary>
        private static double EffectiveStep(TimeIntegrator scheme, double h) => scheme == TimeIntegrator.Bdf2 ? h * (2.0 / 3.0) : h;

        /// <summary>
        /// Prediction of a second-order run (scheme: this substep's, h s, g m/s²): d = d_pred, the velocity base, v_prev = v,
        /// Δ = 0; kinematic particles do not move here (the pins place them). A backward-Euler substep predicts d = h·v + h²·g
        /// with base v + h·g − d/h (v = d/h of the unrounded prediction plus what moved the particle since).
        /// </summary>
        private void PredictSecondOrder<TSize>(TimeIntegrator scheme, double h, Float3 g, bool markSolveStart) where TSize : struct
        {
            // ChainState.Size for the exact solve only (see Predict); BDF2 on lanes where VectorPath.Enabled (Rope.Lanes)
            chain.Size = scheme == TimeIntegrator.Bdf2 && VectorPath.Enabled
                ? PredictSecondOrderLanes<TSize>(h, g, markSolveStart)
                : PredictSecondOrderRange<TSize>(scheme, h, g, markSolveStart, 0, chain.ParticleCount, 0f);
            // Δ (SolveDX/Y/Z) starts from 0 at the substep's first mark (TrackSolveDisplacement's start): no clearing pass
        }

        /// <summary>
        /// <see cref="PredictSecondOrder{TSize}"/> for the particles from … from + count − 1; returns size raised to their
        /// coordinates' largest magnitude (TSize <see cref="Sized"/>).
        /// </summary>
        private float PredictSecondOrderRange<TSize>(TimeIntegrator scheme, double h, Float3 g, bool markSolveStart, int from, int n, float size) where TSize : struct
        {
            bool measureSize = typeof(TSize) == typeof(Sized); // ChainState.Size for the exact solve only (see Predict)
            // spans of exactly n entries (the loop bound): indexed without bounds checks
            ReadOnlySpan<float> x = ChainState.Range(chain.X, from, n), y = ChainState.Range(chain.Y, from, n), z = ChainState.Range(chain.Z, from, n);
            Span<float> px = ChainState.Range(chain.PrevX, from, n), py = ChainState.Range(chain.PrevY, from, n), pz = ChainState.Range(chain.PrevZ, from, n);
            ReadOnlySpan<double> vx = ChainState.Range(chain.VelX, from, n), vy = ChainState.Range(chain.VelY, from, n), vz = ChainState.Range(chain.VelZ, from, n);
            Span<double> ux = ChainState.Range(chain.PrevVelX, from, n), uy = ChainState.Range(chain.PrevVelY, from, n), uz = ChainState.Range(chain.PrevVelZ, from, n);
            Span<float> dx = ChainState.Range(chain.DX, from, n), dy = ChainState.Range(chain.DY, from, n), dz = ChainState.Range(chain.DZ, from, n);
            Span<float> lx = ChainState.Range(chain.DLowX, from, n), ly = ChainState.Range(chain.DLowY, from, n), lz = ChainState.Range(chain.DLowZ, from, n);
            Span<double> bx = ChainState.Range(chain.BaseVelX, from, n), by = ChainState.Range(chain.BaseVelY, from, n), bz = ChainState.Range(chain.BaseVelZ, from, n);
            Span<float> qx = ChainState.Range(chain.PredictedDX, from, n), qy = ChainState.Range(chain.PredictedDY, from, n), qz = ChainState.Range(chain.PredictedDZ, from, n);
            ReadOnlySpan<bool> kinematic = ChainState.Range(chain.Kinematic, from, n);
            Span<double> sx = ChainState.Range(chain.SolveDX, from, n), sy = ChainState.Range(chain.SolveDY, from, n), sz = ChainState.Range(chain.SolveDZ, from, n);
            bool bdf2 = scheme == TimeIntegrator.Bdf2;
            double invH = 1.0 / h, h2 = h * h, c = 4.0 * h2 / 9.0, e = 2.0 * h / 3.0;
            double gx = g.X, gy = g.Y, gz = g.Z;
            for (int i = 0; i < n; i++)
            {
                if (measureSize) size = Larger(size, x[i], y[i], z[i]);
                bool fixedParticle = kinematic[i];
                PredictCoordinate(fixedParticle, bdf2, markSolveStart, x[i], vx[i], ref px[i], ref ux[i], ref dx[i], ref lx[i], ref bx[i], ref qx[i], ref sx[i], invH, h, h2, c, e, gx);
                PredictCoordinate(fixedParticle, bdf2, markSolveStart, y[i], vy[i], ref py[i], ref uy[i], ref dy[i], ref ly[i], ref by[i], ref qy[i], ref sy[i], invH, h, h2, c, e, gy);
                PredictCoordinate(fixedParticle, bdf2, markSolveStart, z[i], vz[i], ref pz[i], ref uz[i], ref dz[i], ref lz[i], ref bz[i], ref qz[i], ref sz[i], invH, h, h2, c, e, gz);
            }
            return size;
        }

        /// <summary>
        /// <see cref="PredictSecondOrderRange{TSize}"/> of the one particle i (the lanes' tail of a chain of 8k + 1 particles),
        /// on the arrays: without the range's thirty span set-ups (goal lanyard: 372 → about 110 instructions per substep).
        /// </summary>
        private float PredictSecondOrderParticle<TSize>(TimeIntegrator scheme, double h, Float3 g, bool markSolveStart, int i) where TSize : struct
        {
            ChainState k = chain;
            bool bdf2 = scheme == TimeIntegrator.Bdf2, fixedParticle = k.Kinematic[i];
            double invH = 1.0 / h, h2 = h * h, c = 4.0 * h2 / 9.0, e = 2.0 * h / 3.0;
            float size = typeof(TSize) == typeof(Sized) ? Larger(0f, k.X[i], k.Y[i], k.Z[i]) : 0f;
            PredictCoordinate(fixedParticle, bdf2, markSolveStart, k.X[i], k.VelX[i], ref k.PrevX[i], ref k.PrevVelX[i], ref k.DX[i], ref k.DLowX[i], ref k.BaseVelX[i], ref k.PredictedDX[i], ref k.SolveDX[i], invH, h, h2, c, e, g.X);
            PredictCoordinate(fixedParticle, bdf2, markSolveStart, k.Y[i], k.VelY[i], ref k.PrevY[i], ref k.PrevVelY[i], ref k.DY[i], ref k.DLowY[i], ref k.BaseVelY[i], ref k.PredictedDY[i], ref k.SolveDY[i], invH, h, h2, c, e, g.Y);
            PredictCoordinate(fixedParticle, bdf2, markSolveStart, k.Z[i], k.VelZ[i], ref k.PrevZ[i], ref k.PrevVelZ[i], ref k.DZ[i], ref k.DLowZ[i], ref k.BaseVelZ[i], ref k.PredictedDZ[i], ref k.SolveDZ[i], invH, h, h2, c, e, g.Z);
            return size;
        }

        /// <summary>
        /// One coordinate of one particle's second-order prediction (x its position, w its velocity, m/s; g of this
        /// coordinate, m/s²; invH = 1/h, h2 = h², c = 4h²/9, e = 2h/3): x_prev = x; a kinematic particle stays (no displacement,
        /// no velocity base, its Δ start mark when <paramref name="markSolveStart"/>); BDF2 predicts
        /// d = (D + DLow)/3 + e·(4v − v_prev)/3 + c·g, backward Euler d = h·v + h²·g, each rounded to float with the velocity base
        /// measured from it; DLow = 0, v_prev = v, d_pred = d.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static void PredictCoordinate(bool kinematic, bool bdf2, bool markSolveStart, float x, double w, ref float prev, ref double prevVel,
            ref float d, ref float low, ref double velocityBase, ref float predicted, ref double solveMark,
            double invH, double h, double h2, double c, double e, double g)
        {
            prev = x;
            float o;
            if (kinematic)
            {
                o = 0f;
                velocityBase = 0.0;
                // a kinematic particle's Δ start mark is stored (a pin may move it next, see solveMarksFused)
                if (markSolveStart) solveMark = StartMark(0f, 0f);
            }
            else if (bdf2)
            {
                // d_prev = D + DLow of the substep before
                double m = (4.0 * w - prevVel) / 3.0;
                o = (float)(((double)d + low) / 3.0 + e * m + c * g);
                velocityBase = m + e * g - o * invH;
            }
            else
            {
                o = (float)(h * w + h2 * g);
                velocityBase = w + h * g - o * invH;
            }
            d = o;
            // the prediction's own rounding stays out of DLow: the velocity base above is measured from the float D
            low = 0f;
            prevVel = w;
            predicted = o;
        }

        /// <summary>
        /// The host changed particle i's velocity by (dx, dy, dz) m/s: the same change is applied to its history (v_prev, and
        /// d_prev = x_n − x_{n−1} by h·Δv), a Galilean boost that keeps BDF2's acceleration memory. A moved position needs
        /// nothing: d_prev is a difference.
        /// </summary>
        private void BoostHistory(int i, double dx, double dy, double dz)
        {
            chain.PrevVelX[i] += dx; chain.PrevVelY[i] += dy; chain.PrevVelZ[i] += dz;
            double h = historyStep;
            chain.AddDisplacement(i, dx * h, dy * h, dz * h);
        }

        /// <summary>
        /// Marks the start (sign −1) or the end (+1) of a chain solve: Δ accumulates the displacement it applies.
        /// <paramref name="start"/>: the substep's first mark, where Δ starts from 0 (written, not read: the prediction does
        /// not clear it; 0 + x keeps the bits the cleared sum gave, +0 for a zero displacement).
        /// </summary>
        private void TrackSolveDisplacement(double sign, bool start)
        {
            int n = chain.ParticleCount;
            // spans of exactly n entries (the loop bound): indexed without bounds checks
            ReadOnlySpan<float> dx = ChainState.Exactly(chain.DX, n), dy = ChainState.Exactly(chain.DY, n), dz = ChainState.Exactly(chain.DZ, n);
            ReadOnlySpan<float> lx = ChainState.Exactly(chain.DLowX, n), ly = ChainState.Exactly(chain.DLowY, n), lz = ChainState.Exactly(chain.DLowZ, n);
            Span<double> sx = ChainState.Exactly(chain.SolveDX, n), sy = ChainState.Exactly(chain.SolveDY, n), sz = ChainState.Exactly(chain.SolveDZ, n);
            if (start)
            {
                // the substep's first mark (sign −1)
                for (int i = 0; i < n; i++)
                {
                    sx[i] = StartMark(dx[i], lx[i]); sy[i] = StartMark(dy[i], ly[i]); sz[i] = StartMark(dz[i], lz[i]);
                }
                return;
            }
            for (int i = 0; i < n; i++)
            {
                sx[i] += sign * ((double)dx[i] + lx[i]); sy[i] += sign * ((double)dy[i] + ly[i]); sz[i] += sign * ((double)dz[i] + lz[i]);
            }
        }

        /// <summary>
        /// The end mark of a substep's first iteration when it is not the last and its start mark is implied (see
        /// <see cref="solveMarksFused"/>): Δ = start + 1·(D + DLow), the start being a free particle's 0 − (PredictedD + 0).
        /// </summary>
        private void TrackSolveEndFromPrediction()
        {
            int n = chain.ParticleCount;
            // spans of exactly n entries (the loop bound): indexed without bounds checks
            ReadOnlySpan<float> dx = ChainState.Exactly(chain.DX, n), dy = ChainState.Exactly(chain.DY, n), dz = ChainState.Exactly(chain.DZ, n);
            ReadOnlySpan<float> lx = ChainState.Exactly(chain.DLowX, n), ly = ChainState.Exactly(chain.DLowY, n), lz = ChainState.Exactly(chain.DLowZ, n);
            ReadOnlySpan<float> qx = ChainState.Exactly(chain.PredictedDX, n), qy = ChainState.Exactly(chain.PredictedDY, n), qz = ChainState.Exactly(chain.PredictedDZ, n);
            ReadOnlySpan<bool> kinematic = ChainState.Exactly(chain.Kinematic, n);
            Span<double> sx = ChainState.Exactly(chain.SolveDX, n), sy = ChainState.Exactly(chain.SolveDY, n), sz = ChainState.Exactly(chain.SolveDZ, n);
            // the blocks of Vector<float> particles without a kinematic one on lanes (the same operations), the others and the
            // tail by the loop below
            int from = 0, width = Vector<float>.Count;
            if (VectorPath.Enabled)
            {
                ReadOnlySpan<int> fixedParticles = chain.KinematicIndices;
                ReadOnlySpan<Vector<float>> vdx = VectorPath.AsLanes(dx), vdy = VectorPath.AsLanes(dy), vdz = VectorPath.AsLanes(dz);
                ReadOnlySpan<Vector<float>> vlx = VectorPath.AsLanes(lx), vly = VectorPath.AsLanes(ly), vlz = VectorPath.AsLanes(lz);
                ReadOnlySpan<Vector<float>> vqx = VectorPath.AsLanes(qx), vqy = VectorPath.AsLanes(qy), vqz = VectorPath.AsLanes(qz);
                Span<Vector<double>> vsx = VectorPath.AsLanes(sx), vsy = VectorPath.AsLanes(sy), vsz = VectorPath.AsLanes(sz);
                int q = 0, blocks = vdx.Length;
                for (int b = 0; b < blocks; b++)
                {
                    int start = b * width, end = start + width;
                    while (q < fixedParticles.Length && fixedParticles[q] < start) q++;
                    if (q < fixedParticles.Length && fixedParticles[q] < end)
                    {
                        EndFromPrediction(start, end, dx, dy, dz, lx, ly, lz, qx, qy, qz, kinematic, sx, sy, sz);
                        continue;
                    }
                    EndFromPredictionLanes(b, vdx[b], vlx[b], vqx[b], vsx);
                    EndFromPredictionLanes(b, vdy[b], vly[b], vqy[b], vsy);
                    EndFromPredictionLanes(b, vdz[b], vlz[b], vqz[b], vsz);
                }
                from = blocks * width;
            }
            EndFromPrediction(from, n, dx, dy, dz, lx, ly, lz, qx, qy, qz, kinematic, sx, sy, sz);
        }

        /// <summary><see cref="TrackSolveEndFromPrediction"/> of particles from … to − 1 (the spans: the chain's arrays of n entries).</summary>
        private static void EndFromPrediction(int from, int to, ReadOnlySpan<float> dx, ReadOnlySpan<float> dy, ReadOnlySpan<float> dz,
            ReadOnlySpan<float> lx, ReadOnlySpan<float> ly, ReadOnlySpan<float> lz, ReadOnlySpan<float> qx, ReadOnlySpan<float> qy, ReadOnlySpan<float> qz,
            ReadOnlySpan<bool> kinematic, Span<double> sx, Span<double> sy, Span<double> sz)
        {
            for (int i = from; i < to; i++)
            {
                if (!kinematic[i]) { sx[i] = StartMark(qx[i], 0f); sy[i] = StartMark(qy[i], 0f); sz[i] = StartMark(qz[i], 0f); }
                sx[i] += 1.0 * ((double)dx[i] + lx[i]); sy[i] += 1.0 * ((double)dy[i] + ly[i]); sz[i] += 1.0 * ((double)dz[i] + lz[i]);
            }
        }

        /// <summary>
        /// One axis of <see cref="TrackSolveEndFromPrediction"/> for block b of free particles on lanes: Δ = (0 − (PredictedD +
        /// 0)) + 1·(D + DLow) per lane (<see cref="StartMarks"/>), as the loop forms it.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static void EndFromPredictionLanes(int b, Vector<float> d, Vector<float> low, Vector<float> predicted, Span<Vector<double>> marks)
        {
            ChainState.Widen(d, out Vector<double> d0, out Vector<double> d1);
            ChainState.Widen(low, out Vector<double> l0, out Vector<double> l1);
            ChainState.Widen(predicted, out Vector<double> q0, out Vector<double> q1);
            marks[2 * b] = StartMarks(q0) + new Vector<double>(1.0) * (d0 + l0);
            marks[2 * b + 1] = StartMarks(q1) + new Vector<double>(1.0) * (d1 + l1);
        }

        /// <summary>Velocities from Δ as stored (<see cref="SecondOrderVelocities{TMark}"/>).</summary>
        private struct StoredMarks { }

        /// <summary>Velocities that take the solve's last end mark, Δ = stored + 1·d (see <see cref="solveMarksFused"/>).</summary>
        private struct PendingEndMark { }

        /// <summary>Velocities that take the last end mark onto a free particle's implied start mark (a substep of one iteration, see <see cref="solveMarksFused"/>).</summary>
        private struct ImpliedStartMark { }

        /// <summary>
        /// The velocity loop of <see cref="UpdateVelocitiesSecondOrder"/>; TMark (<see cref="StoredMarks"/>,
        /// <see cref="PendingEndMark"/>, <see cref="ImpliedStartMark"/>) says where Δ comes from: the JIT compiles one body
        /// each and folds the tests. Δ is not read after this pass, so a mark taken here is not stored.
        /// </summary>
        private void SecondOrderVelocities<TMark>(TimeIntegrator scheme, double h) where TMark : struct
        {
            // on lanes where VectorPath.Enabled (Rope.Lanes)
            if (VectorPath.Enabled) SecondOrderVelocityLanes<TMark>(scheme, h);
            else SecondOrderVelocitiesRange<TMark>(scheme, h, 0, chain.ParticleCount);
        }

        /// <summary><see cref="SecondOrderVelocities{TMark}"/> for the particles from … from + n − 1.</summary>
        private void SecondOrderVelocitiesRange<TMark>(TimeIntegrator scheme, double h, int from, int n) where TMark : struct
        {
            // spans of exactly n entries (the loop bound): indexed without bounds checks
            ReadOnlySpan<float> dx = ChainState.Range(chain.DX, from, n), dy = ChainState.Range(chain.DY, from, n), dz = ChainState.Range(chain.DZ, from, n);
            ReadOnlySpan<float> lx = ChainState.Range(chain.DLowX, from, n), ly = ChainState.Range(chain.DLowY, from, n), lz = ChainState.Range(chain.DLowZ, from, n);
            ReadOnlySpan<double> bx = ChainState.Range(chain.BaseVelX, from, n), by = ChainState.Range(chain.BaseVelY, from, n), bz = ChainState.Range(chain.BaseVelZ, from, n);
            ReadOnlySpan<double> sx = ChainState.Range(chain.SolveDX, from, n), sy = ChainState.Range(chain.SolveDY, from, n), sz = ChainState.Range(chain.SolveDZ, from, n);
            Span<double> wx = ChainState.Range(chain.PrevVelX, from, n), wy = ChainState.Range(chain.PrevVelY, from, n), wz = ChainState.Range(chain.PrevVelZ, from, n);
            ReadOnlySpan<float> qx = ChainState.Range(chain.PredictedDX, from, n), qy = ChainState.Range(chain.PredictedDY, from, n), qz = ChainState.Range(chain.PredictedDZ, from, n);
            Span<double> vx = ChainState.Range(chain.VelX, from, n), vy = ChainState.Range(chain.VelY, from, n), vz = ChainState.Range(chain.VelZ, from, n);
            ReadOnlySpan<bool> kinematic = ChainState.Range(chain.Kinematic, from, n);
            double invH = 1.0 / h, k = scheme == TimeIntegrator.Bdf2 ? 0.5 * invH : 0.0;
            for (int i = 0; i < n; i++)
            {
                bool fixedParticle = kinematic[i];
                double cx = VelocityCoordinate<TMark>(fixedParticle, dx[i], lx[i], qx[i], sx[i], bx[i], ref vx[i], invH, k, out double mx);
                double cy = VelocityCoordinate<TMark>(fixedParticle, dy[i], ly[i], qy[i], sy[i], by[i], ref vy[i], invH, k, out double my);
                double cz = VelocityCoordinate<TMark>(fixedParticle, dz[i], lz[i], qz[i], sz[i], bz[i], ref vz[i], invH, k, out double mz);
                Boost(fixedParticle, mx, my, mz, cx, cy, cz, invH, ref wx[i], ref wy[i], ref wz[i]);
            }
        }

        /// <summary>
        /// <see cref="SecondOrderVelocitiesRange{TMark}"/> of the one particle i (the lanes' tail of a chain of 8k + 1
        /// particles), on the arrays: without the range's twenty-two span set-ups.
        /// </summary>
        private void SecondOrderVelocityParticle<TMark>(TimeIntegrator scheme, double h, int i) where TMark : struct
        {
            ChainState c = chain;
            double invH = 1.0 / h, k = scheme == TimeIntegrator.Bdf2 ? 0.5 * invH : 0.0;
            bool fixedParticle = c.Kinematic[i];
            double cx = VelocityCoordinate<TMark>(fixedParticle, c.DX[i], c.DLowX[i], c.PredictedDX[i], c.SolveDX[i], c.BaseVelX[i], ref c.VelX[i], invH, k, out double mx);
            double cy = VelocityCoordinate<TMark>(fixedParticle, c.DY[i], c.DLowY[i], c.PredictedDY[i], c.SolveDY[i], c.BaseVelY[i], ref c.VelY[i], invH, k, out double my);
            double cz = VelocityCoordinate<TMark>(fixedParticle, c.DZ[i], c.DLowZ[i], c.PredictedDZ[i], c.SolveDZ[i], c.BaseVelZ[i], ref c.VelZ[i], invH, k, out double mz);
            Boost(fixedParticle, mx, my, mz, cx, cy, cz, invH, ref c.PrevVelX[i], ref c.PrevVelY[i], ref c.PrevVelZ[i]);
        }

        /// <summary>
        /// One coordinate of a particle's second-order velocity: d = D + DLow (out m), Δ (stored, or as TMark marks it), the
        /// velocity v = base + d/h + κ·Δ (κ = k); returns the push c = d − d_pred − Δ.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static double VelocityCoordinate<TMark>(bool kinematic, float d, float low, float predicted, double stored, double velocityBase,
            ref double velocity, double invH, double k, out double m) where TMark : struct
        {
            // d = D + DLow (ChainState.Displacement)
            m = (double)d + low;
            // Δ: stored, or TrackSolveDisplacement's last end mark Δ += 1·d taken here (onto a free particle's implied
            // start mark 0 − (PredictedD + 0) after a single iteration)
            double e = typeof(TMark) == typeof(ImpliedStartMark) && !kinematic ? StartMark(predicted, 0f) : stored;
            if (typeof(TMark) != typeof(StoredMarks)) e += 1.0 * m;
            velocity = velocityBase + m * invH + k * e;
            return m - predicted - e;
        }

        /// <summary>
        /// The velocity history of a particle after its second-order velocity (m: its d, c: its push, per coordinate): what
        /// moved the particle besides the prediction and the chain solve (collider push-out, friction, a pin target) is a
        /// velocity kick c/h, as in backward Euler; boosting the history by it too (v_prev += c/h) makes the next prediction
        /// carry it exactly once instead of 11/9 times. A kinematic particle's history is d/h.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static void Boost(bool kinematic, double mx, double my, double mz, double cx, double cy, double cz, double invH,
            ref double wx, ref double wy, ref double wz)
        {
            if (kinematic)
            {
                wx = mx * invH; wy = my * invH; wz = mz * invH;
            }
            else if (cx != 0.0 || cy != 0.0 || cz != 0.0)
            {
                wx += cx * invH; wy += cy * invH; wz += cz * invH;
            }
        }

        /// <summary>Δ's start mark of one coordinate, 0 − (D + DLow), as the substep's first <see cref="TrackSolveDisplacement"/> writes it.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static double StartMark(float d, float low) => 0.0 + -1.0 * ((double)d + low);

        /// <summary>
        /// After a BDF2 substep's velocities (invH = 1/h, 1/s; <paramref name="bdf2"/>: the substep ran BDF2): every dynamic
        /// particle resting on a collider (the collision passes pushed it out in this substep and the one before,
        /// <see cref="ChainState.ContactLoad"/> &gt; 0, <see cref="ChainState.ContactResting"/>) with a contact of the current set loses the part of its
        /// velocity into the contact's surface, relative to the surface (v·n &lt; u·n; n: the contact's normal, u: the
        /// surface's velocity at the contact), the inelastic contact at the velocity level, with the history boosted by the same change
        /// (<see cref="BoostHistory"/>; after the positions are committed). The push-out enters the velocity as a backward-Euler kick
        /// c/h, so BDF2's velocity v = (4v_n − v_{n−1})/3 + … of a particle held at rest on a surface converges to
        /// h·g_n/2 into it (g_n: its acceleration onto the surface) while its position stands still: 6.5 mm/s at h = 1/720 s
        /// under gravity, 9·10⁻⁷ J on a 45 g particle that never decays. Backward Euler's velocity d/h of a particle on the
        /// surface has no such part. A new contact (an impact) is left alone: its kick c/h already ends it inelastically.
        /// Every substep of a second-order run with colliders records which particles the passes pushed (the next one's
        /// <see cref="ChainState.ContactResting"/>).
        /// </summary>
        private void RemoveVelocityIntoSurface(double invH, bool bdf2)
        {
            bool[] resting = chain.ContactResting;
            float[] load = chain.ContactLoad;
            // a backward-Euler substep has no BDF2 history to clamp: it only records the pushed particles (below)
            int clamped = bdf2 ? chain.ContactCount : 0;
            for (int k = 0; k < clamped; k++)
            {
                int i = chain.ContactList[k];
                if (chain.Kinematic[i] || !(load[i] > 0f) || !resting[i]) continue;
                double nx = chain.ContactNX[i], ny = chain.ContactNY[i], nz = chain.ContactNZ[i];
                double into = (chain.VelX[i] - chain.ContactSurfaceX[i] * invH) * nx + (chain.VelY[i] - chain.ContactSurfaceY[i] * invH) * ny
                    + (chain.VelZ[i] - chain.ContactSurfaceZ[i] * invH) * nz;
                if (!(into < 0.0)) continue;
                chain.VelX[i] -= into * nx; chain.VelY[i] -= into * ny; chain.VelZ[i] -= into * nz;
                // the history takes the same change (a Galilean boost): without it BDF2's memory v − v_prev would carry the
                // removed part back out, and a particle that hit the surface at 1 m/s would leave it at 6 cm/s
                BoostHistory(i, -into * nx, -into * ny, -into * nz);
            }
            bool[] near = chain.ContactNear;
            int[] collider = chain.ContactCollider;
            for (int i = 0; i < chain.ParticleCount; i++) { resting[i] = load[i] > 0f; near[i] = collider[i] >= 0; }
        }

        /// <summary>Δ's start mark of every particle <see cref="MovePins"/> placed (the rigid pins; see <see cref="solveMarksFused"/>).</summary>
        private void MarkPinnedSolveStarts()
        {
            // the particles of the unbroken rigid pins are exactly the kinematic ones (RefreshKinematic): their list, each
            // once (a particle two pins hold took the same mark twice)
            ReadOnlySpan<int> pinned = chain.KinematicIndices;
            for (int q = 0; q < pinned.Length; q++)
            {
                int i = pinned[q];
                chain.SolveDX[i] = StartMark(chain.DX[i], chain.DLowX[i]);
                chain.SolveDY[i] = StartMark(chain.DY[i], chain.DLowY[i]);
                chain.SolveDZ[i] = StartMark(chain.DZ[i], chain.DLowZ[i]);
            }
        }

        /// <summary>
        /// Velocities of a second-order run: v = base + d/h + κ·Δ/h (κ = 1/2 for BDF2, 0 for a backward-Euler substep),
        /// x = x_prev + d (h s); violent: the next substep restarts with backward Euler. A non-finite result falls back to the last good position at rest.
        /// <para>With colliders (<paramref name="contacts"/>), a BDF2 substep then takes from each particle the collision passes
        /// moved (push-out) the part of its velocity that points into its contact's surface, relative to the surface
        /// (<see cref="RemoveVelocityIntoSurface"/>).</para>
        /// </summary>
        private void UpdateVelocitiesSecondOrder(TimeIntegrator scheme, double h, bool violent, bool contacts)
        {
            // Δ as stored, or with the solve's last end mark taken here (see solveMarksFused): one loop body for each
            if (!solveEndPending) SecondOrderVelocities<StoredMarks>(scheme, h);
            else if (solveStartImplied) SecondOrderVelocities<ImpliedStartMark>(scheme, h);
            else SecondOrderVelocities<PendingEndMark>(scheme, h);
            solveEndPending = false;
            solveStartImplied = false;
            CommitPositions();
            // a violent substep (see ViolentStrain) restarts the history: the next substep is backward Euler
            historyValid = !violent;
            historyStep = h;
            if (contacts) RemoveVelocityIntoSurface(1.0 / h, scheme == TimeIntegrator.Bdf2);
        }
    }
}
