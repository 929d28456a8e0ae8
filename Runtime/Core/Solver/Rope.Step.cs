using System;
using System.Numerics;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    public sealed partial class Rope
    {
        /// <summary>Largest host step in seconds that <see cref="Step"/> accepts.</summary>
        public const float MaxHostDeltaTime = 1f;

        /// <summary>
        /// Advances the rope by one host step (s, in (0, 1]): <see cref="RopeSettings.Substeps"/> substeps of
        /// h = Δt/substeps, each in four phases: predict (gravity, drag, rigid pins), collide (push out, detect contacts),
        /// solve (<see cref="RopeSettings.Iterations"/> constraint iterations: chain, compliant pins, colliders) and
        /// finish (velocities, tensions, pin forces and pin breaks). The positions at the start of the step are kept for
        /// <see cref="Interpolate"/>. Allocation-free.
        /// </summary>
        public StepReport Step(float hostDeltaTime)
        {
            if (!(hostDeltaTime > 0f && hostDeltaTime <= MaxHostDeltaTime))
                throw new ArgumentOutOfRangeException(nameof(hostDeltaTime), hostDeltaTime, "hostDeltaTime must be in (0, 1] s");
            if (settings.Version != appliedVersion) ApplySettings();
            // the opt-in fused single-precision Gauss–Seidel step, for the ropes it serves (Rope.FusedStep.cs)
            if (settings.GaussSeidelKernel == GaussSeidelKernel.FusedSingle && FusedStepApplies()) return StepFused(hostDeltaTime);

            int substeps = settings.Substeps;
            int iterations = settings.Iterations;
            float h = hostDeltaTime / substeps;
            double hd = (double)hostDeltaTime / substeps;
            double beta = settings.Damping;
            bool tensionOnly = settings.Tension == TensionModel.TensionOnly;
            bool exact = settings.Solver == ConstraintSolverKind.ExactChain;
            Float3 g = settings.Gravity;
            bool hasColliders = colliders.Count > 0;
            int compliantPins = CountCompliantPins();
            // the interpolation start and the loads' start state (shared with the fused step, Rope.FusedStep.cs)
            BeginStep();

            reportIterations = 0; reportSolves = 0; reportViolent = 0; reportShortened = 0; reportUnconverged = 0;
            TimeIntegrator integrator = settings.Integrator;
            bool secondOrder = integrator != TimeIntegrator.BackwardEuler;
            bool drag = settings.HasDrag, viscousDrag = drag && settings.ViscousDrag > 0f;
            if (drag) PrepareDrag();
            // the exact solve's lane views of the chain (assembly, particle moves, convergence, tension-only set, blocks), once
            // for every iteration of the step's substeps
            var views = new ExactChainSolver.StepViews(chain, exact && VectorPath.Enabled);
            for (int k = 0; k < substeps; k++)
            {
                float t = (float)(k + 1) / substeps;
                TimeIntegrator scheme = SubstepScheme(integrator, hd);
                // friction in contact: backward Euler (see HeldWithFriction)
                if (scheme == TimeIntegrator.Bdf2 && exact && chain.HeldWithFriction) scheme = TimeIntegrator.BackwardEuler;
                double hEff = BeginSubstep(scheme, hd);
                // nothing moves a particle between the prediction and the solve but the rigid pins: the prediction (and the
                // pins) write the solve's start mark, and the last iteration leaves its end mark to the velocity pass
                solveMarksFused = secondOrder && !drag && !hasColliders;
                // the colliders' poses of this substep (a backward-Euler re-run below keeps them)
                if (hasColliders) colliders.PrepareSubstep(t, hostDeltaTime);
                PredictAndCollide(t, secondOrder, scheme, h, hd, hEff, g, drag);
                bool impact = scheme == TimeIntegrator.Bdf2 && hasColliders && NewImpact();
                // what the solve hands on to the solve after it, as the substep starts (a re-run below starts from it again)
                double normalScale = chain.ContactNormalScale;
                if (impact) chain.Plasticity?.KeepBranches();
                int unconvergedBefore = reportUnconverged;
                // (tests only: the probe re-runs every impact substep, with or without its BDF2 solve)
                bool probed = impact && ImpactRerunProbe != ImpactRerun.WhenUnconverged;
                bool violentSolve = !(probed && ImpactRerunProbe == ImpactRerun.WithoutFirstSolve)
                    && SolveWithViscousDrag(in views, h, hd, hEff, t, beta, tensionOnly, exact, iterations, compliantPins > 0, secondOrder, viscousDrag);
                if (probed || impact && violentSolve && reportUnconverged > unconvergedBefore)
                {
                    // an impact left the BDF2 solve violent and unconverged: the substep runs again as backward Euler from
                    // its start (x_n and v_n are not written before the velocities; see NewImpact); the report counts both solves
                    scheme = TimeIntegrator.BackwardEuler;
                    ForgetFailedSolve(normalScale);
                    hEff = BeginSubstep(scheme, hd);
                    PredictAndCollide(t, secondOrder, scheme, h, hd, hEff, g, drag);
                    violentSolve = SolveWithViscousDrag(in views, h, hd, hEff, t, beta, tensionOnly, exact, iterations, compliantPins > 0, secondOrder, viscousDrag);
                }
                if (secondOrder) UpdateVelocitiesSecondOrder(scheme, hd, violentSolve || Violent(), hasColliders);
                else UpdateVelocities(hd);
                if (drag) AccumulateDragWork();
                FinishPhase(hd, hEff, g, k == 0);
                if (loadCount > 0) TrackLoadPeaks(1f / h, g);
            }
            ScaleMeanTensions(1f / substeps);
            RefreshLengths();
            if (hasColliders) colliders.EndStep();
            // the pins' targets reached and the loads' forces over the step (shared with the fused step)
            EndStep(hostDeltaTime, g);

            return new StepReport
            {
                Residual = ComputeResidual(), Iterations = iterations, Substeps = substeps, SolveIterations = reportIterations, LinearSolves = reportSolves,
                ViolentSubsteps = reportViolent, ShortenedSteps = reportShortened, UnconvergedSubsteps = reportUnconverged,
            };
        }

        /// <summary>
        /// Sets the chain up for substep hd (s) under scheme (its flag, the substep, the contact impulse scale (h_eff/h)²) and
        /// returns the scheme's effective step h_eff (s).
        /// </summary>
        private double BeginSubstep(TimeIntegrator scheme, double hd)
        {
            double hEff = EffectiveStep(scheme, hd);
            chain.Bdf2Substep = scheme == TimeIntegrator.Bdf2;
            chain.Substep = hd;
            chain.ContactImpulseScale = (hEff / hd) * (hEff / hd);
            return hEff;
        }

        /// <summary>
        /// Phases 1 and 2 of a substep under scheme (h s, hd the same in double, h_eff s): the prediction (<see cref="PredictPhase"/>,
        /// with the drag's when <paramref name="drag"/>), then the collision pass that pushes it out of the colliders and finds
        /// the contacts the chain solve folds in.
        /// </summary>
        private void PredictAndCollide(float t, bool secondOrder, TimeIntegrator scheme, float h, double hd, double hEff, Float3 g, bool drag)
        {
            PredictPhase(t, secondOrder, scheme, h, hd, g);
            if (drag) PredictDrag(secondOrder, scheme == TimeIntegrator.Bdf2, h, hd, hEff, g);
            CollidePhase(h, ContactPass.StartOfSubstep);
        }

        /// <summary><see cref="SolvePhase"/> with the viscous drag folded into the solve around it when <paramref name="viscousDrag"/>. Returns true for a violent substep.</summary>
        private bool SolveWithViscousDrag(in ExactChainSolver.StepViews views, float h, double hd, double hEff, float t, double beta, bool tensionOnly, bool exact, int iterations, bool hasCompliantPins, bool trackSolve, bool viscousDrag)
        {
            if (viscousDrag) FoldViscousDrag(hEff);
            bool violent = SolvePhase(in views, h, hd, hEff, t, beta, tensionOnly, exact, iterations, hasCompliantPins, trackSolve);
            if (viscousDrag) UnfoldViscousDrag();
            return violent;
        }

        /// <summary>
        /// Phase 1 of a substep (fraction t of the host step, h s; hd the same in double; the colliders' poses are set before it): prediction under
        /// gravity (a second-order run: the scheme's, <see cref="PredictSecondOrder"/>), rigid pins on their targets, the
        /// pins' multipliers cleared and, for the Gauss–Seidel sweep, the segments' (the exact solve writes its own).
        /// </summary>
        private void PredictPhase(float t, bool secondOrder, TimeIntegrator scheme, float h, double hd, Float3 g)
        {
            // solveMarksFused: the prediction writes the first iteration's start mark of the solve displacement Δ (BDF2)
            // the largest coordinate (ChainState.Size) is the exact solve's round-off floor: the Gauss–Seidel sweep skips it
            if (settings.Solver == ConstraintSolverKind.ExactChain)
            {
                if (secondOrder) PredictSecondOrder<Sized>(scheme, hd, g, solveMarksFused);
                else Predict<Sized>(hd, g);
            }
            else if (secondOrder) PredictSecondOrder<Unsized>(scheme, hd, g, solveMarksFused);
            else Predict<Unsized>(hd, g);
            MovePins(t);
            if (solveMarksFused) MarkPinnedSolveStarts();
            // cleared in loops: for the short arrays of a rope a call to Array.Clear costs more than the stores. The exact
            // solve writes every λ in each of its iterations (ExactChainSolver.Apply, at least one per substep) and nothing
            // reads λ before: only the Gauss–Seidel sweep accumulates it from 0
            if (settings.Solver != ConstraintSolverKind.ExactChain)
            {
                Span<double> lambda = ChainState.Exactly(chain.Lambda, chain.SegmentCount);
                for (int j = 0; j < lambda.Length; j++) lambda[j] = 0.0;
            }
            for (int b = 0; b < pinCount * 3; b++) pinLambda[b] = 0.0;
        }

        /// <summary>Phase 2 (and the end of each iteration): push the particles out of the colliders; the pass decides contact detection and friction.</summary>
        private void CollidePhase(float h, ContactPass pass)
        {
            if (colliders.Count > 0) colliders.Project(chain, h, pass, settings.Solver == ConstraintSolverKind.ExactChain);
        }

        /// <summary>
        /// Most Newton iterations of the exact chain solve in a substep. Beyond <see cref="RopeSettings.Iterations"/>, the
        /// solve adds one iteration at a time, up to this total, while the last one was not to be trusted: its geometric
        /// stiffness used a tension far below the one it found (a rope snatched taut, the first substep of a loaded rope),
        /// or it moved segments across themselves so far that the linearisation was off (a whipping end), or the length
        /// errors it left would store energy that matters (a stiff rope bent around a collider: 3 µm on a 4 mm steel segment
        /// is 0.02 J). A rope that hangs, swings or stretches smoothly needs none. A violent substep may run up to
        /// <see cref="MaxViolentNewtonIterations"/>.
        /// </summary>
        public const int MaxNewtonIterations = 4;

        /// <summary>
        /// Most Newton iterations of the exact chain solve in a violent substep: one whose linearisation was off by more than
        /// 10⁻³ of a rest length (a rope released 10× stretched, an anchor teleported 1 km), or that left a released
        /// tension-only segment stretched that much. Its iterations go through a backtracking line search on the implicit
        /// step's objective Φ(x) = ½|x − x̃|²_M/h² + U(x), so each one makes progress, and it keeps iterating until converged
        /// or this many. A second-order integrator restarts with backward Euler after it.
        /// </summary>
        public const int MaxViolentNewtonIterations = 32;

        // what the solve did in this host step (StepReport)
        private int reportIterations, reportSolves, reportViolent, reportShortened, reportUnconverged;

        /// <summary>
        /// Phase 3: the constraint iterations. Each folds in the compliant pins, solves the chain (one Newton iteration of
        /// the exact solve, or a Gauss–Seidel sweep), releases the pins and runs a collision pass. The exact solve adds
        /// iterations, up to <see cref="MaxNewtonIterations"/> (<see cref="MaxViolentNewtonIterations"/> in a violent
        /// substep), while it is unconverged. Returns true for a violent substep. <paramref name="views"/>: the chain's views
        /// for the exact solve's lane kernels, built once per host step (<see cref="ExactChainSolver.StepViews"/>).
        /// </summary>
        private bool SolvePhase(in ExactChainSolver.StepViews views, float h, double hd, double hEff, float t, double beta, bool tensionOnly, bool exact, int iterations, bool hasCompliantPins, bool trackSolve)
        {
            // the solve runs with α̃ = α/h_eff² (the integrator's effective step) and keeps the dashpot γ = β/h
            double solveBeta = beta * (hEff / hd);
            int total = iterations, cap = MaxNewtonIterations;
            bool unconverged = false;
            solveEndPending = false;
            solveStartImplied = trackSolve && solveMarksFused;
            for (int it = 0; it < total; it++)
            {
                // the first start mark is implied by the prediction when the marks are fused (see solveMarksFused)
                if (trackSolve && !(it == 0 && solveMarksFused)) TrackSolveDisplacement(-1.0, it == 0);
                bool softPins = hasCompliantPins && ProjectCompliantPins(hEff, t);
                if (exact)
                {
                    unconverged = ExactChainSolver.Iterate(chain, in views, hEff, solveBeta, tensionOnly, it == 0, out bool violent, out bool shortened, out int solves);
                    reportSolves += solves;
                    if (violent) cap = MaxViolentNewtonIterations;
                    if (shortened) reportShortened++;
                    if (unconverged && it == total - 1 && total < cap) total++;
                }
                else
                {
                    GaussSeidelSolver.Iterate(chain, hEff, solveBeta, tensionOnly);
                }
                // the last iteration's end mark: in the velocity pass when nothing moves the particles after it (solveMarksFused)
                if (trackSolve && solveMarksFused && it == total - 1) solveEndPending = true;
                else if (trackSolve && solveStartImplied) { TrackSolveEndFromPrediction(); solveStartImplied = false; }
                else if (trackSolve) TrackSolveDisplacement(1.0, false);
                if (softPins) ReleaseCompliantPins(hEff, t);
                CollidePhase(h, it == total - 1 ? ContactPass.LastIteration : ContactPass.BetweenIterations);
            }
            // the exact solve's friction for the next substep, from this one's contact impulses
            if (exact && chain.ContactCount > 0) ChainContacts.DecideFriction(chain);
            else chain.HeldWithFriction = false;
            if (!exact) return false;
            reportIterations += total;
            if (unconverged) reportUnconverged++;
            bool violentSubstep = cap == MaxViolentNewtonIterations;
            if (violentSubstep) reportViolent++;
            return violentSubstep;
        }

        /// <summary>Phase 4 (after the velocities): time, tensions T = −λ/h_eff², the plastic return mapping, pin forces (and pin breaks). The segment lengths are refreshed once, after the last substep.</summary>
        private void FinishPhase(double hd, double hEff, Float3 g, bool firstSubstep)
        {
            time += hd;
            UpdateTensions(hEff, firstSubstep);
            // the return mapping of the plastic segments on the committed positions (γ = β/h: the solve's damping fold)
            if (chain.Plasticity != null) chain.Plasticity.ReturnMap(chain, settings.Damping / hd);
            if (pinCount > 0) UpdatePinForces(hEff, g);
        }

        /// <summary>A prediction that measures <see cref="ChainState.Size"/> (the exact solve's round-off floor).</summary>
        private struct Sized { }

        /// <summary>A prediction that leaves <see cref="ChainState.Size"/> alone (the Gauss–Seidel sweep does not read it).</summary>
        private struct Unsized { }

        /// <summary>
        /// Backward Euler's prediction v += h·g, D + DLow = h·v (h s, g m/s²); kinematic particles do not move here. TSize is
        /// <see cref="Sized"/> or <see cref="Unsized"/>: the JIT compiles one body for each and folds the size test away.
        /// </summary>
        private void Predict<TSize>(double h, Float3 g) where TSize : struct
        {
            bool measureSize = typeof(TSize) == typeof(Sized);
            double gx = g.X * h, gy = g.Y * h, gz = g.Z * h;
            int n = chain.ParticleCount;
            // spans of exactly n entries (the loop bound): indexed without bounds checks
            ReadOnlySpan<float> x = ChainState.Exactly(chain.X, n), y = ChainState.Exactly(chain.Y, n), z = ChainState.Exactly(chain.Z, n);
            Span<float> px = ChainState.Exactly(chain.PrevX, n), py = ChainState.Exactly(chain.PrevY, n), pz = ChainState.Exactly(chain.PrevZ, n);
            Span<double> vx = ChainState.Exactly(chain.VelX, n), vy = ChainState.Exactly(chain.VelY, n), vz = ChainState.Exactly(chain.VelZ, n);
            Span<float> dx = ChainState.Exactly(chain.DX, n), dy = ChainState.Exactly(chain.DY, n), dz = ChainState.Exactly(chain.DZ, n);
            Span<float> lx = ChainState.Exactly(chain.DLowX, n), ly = ChainState.Exactly(chain.DLowY, n), lz = ChainState.Exactly(chain.DLowZ, n);
            ReadOnlySpan<bool> kinematic = ChainState.Exactly(chain.Kinematic, n);
            float size = 0f;
            for (int i = 0; i < n; i++)
            {
                px[i] = x[i]; py[i] = y[i]; pz[i] = z[i];
                if (measureSize) size = Larger(size, x[i], y[i], z[i]);
                if (kinematic[i]) { dx[i] = 0f; dy[i] = 0f; dz[i] = 0f; lx[i] = 0f; ly[i] = 0f; lz[i] = 0f; continue; }
                double ux = vx[i] + gx, uy = vy[i] + gy, uz = vz[i] + gz;
                vx[i] = ux; vy[i] = uy; vz[i] = uz;
                // D + DLow = v·h exactly (ChainState.SetDisplacement)
                ChainState.Set(ref dx[i], ref lx[i], ux * h); ChainState.Set(ref dy[i], ref ly[i], uy * h); ChainState.Set(ref dz[i], ref lz[i], uz * h);
            }
            chain.Size = size;
        }

        /// <summary>The larger of size and the magnitudes of x, y, z (plain compares: MathF.Max's NaN and −0 rules cost far more).</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static float Larger(float size, float x, float y, float z)
        {
            if (x < 0f) x = -x;
            if (y < 0f) y = -y;
            if (z < 0f) z = -z;
            if (x > size) size = x;
            if (y > size) size = y;
            if (z > size) size = z;
            return size;
        }

        private void MovePins(float t)
        {
            for (int p = 0; p < pinCount; p++)
            {
                if (pinBroken[p] || pinCompliance[p] != 0f) continue;
                int i = pinParticle[p];
                Float3 target = PinTarget(p, t);
                chain.SetDisplacement(i, (double)target.X - chain.PrevX[i] - chain.LowX[i], (double)target.Y - chain.PrevY[i] - chain.LowY[i],
                    (double)target.Z - chain.PrevZ[i] - chain.LowZ[i]);
            }
        }

        private int CountCompliantPins()
        {
            int count = 0;
            for (int p = 0; p < pinCount; p++) if (!pinBroken[p] && pinCompliance[p] != 0f) count++;
            return count;
        }

        /// <summary>
        /// Compliant pins are zero-length linear springs, so they can be folded into the chain solve exactly:
        /// project each pin alone (XPBD Gauss–Seidel step), then give its particle the effective inverse mass
        /// w·α̃/(w + α̃) — the particle's mass plus the spring's implicit mass 1/α̃ — for the chain solve.
        /// <see cref="ReleaseCompliantPins"/> restores the masses and reads the pin multipliers back.
        /// Returns true when some pin was folded in.
        /// </summary>
        private bool ProjectCompliantPins(double h, float t)
        {
            double invH2 = 1.0 / (h * h);
            bool any = false;
            for (int p = 0; p < pinCount; p++)
            {
                if (pinBroken[p] || pinCompliance[p] == 0f) continue;
                int i = pinParticle[p];
                double w = chain.InverseMass[i];
                if (w == 0.0) continue;
                double alphaTilde = pinCompliance[p] * invH2;
                double denominator = w + alphaTilde;
                Float3 target = PinTarget(p, t);
                int b = 3 * p;
                PinOffset(i, target, out double cx, out double cy, out double cz);
                double dx = (-cx - alphaTilde * pinLambda[b]) / denominator;
                double dy = (-cy - alphaTilde * pinLambda[b + 1]) / denominator;
                double dz = (-cz - alphaTilde * pinLambda[b + 2]) / denominator;
                chain.AddDisplacement(i, w * dx, w * dy, w * dz);
                chain.InverseMass[i] = (float)(w * alphaTilde / denominator);
                any = true;
            }
            return any;
        }

        private void ReleaseCompliantPins(double h, float t)
        {
            double invH2 = 1.0 / (h * h);
            for (int p = 0; p < pinCount; p++)
            {
                if (pinBroken[p] || pinCompliance[p] == 0f) continue;
                int i = pinParticle[p];
                if (chain.Kinematic[i]) continue;
                chain.InverseMass[i] = SolveInverseMass(i);
                double alphaTilde = pinCompliance[p] * invH2;
                Float3 target = PinTarget(p, t);
                int b = 3 * p;
                // compliance-consistent multiplier: C + α̃·λ = 0
                PinOffset(i, target, out double cx, out double cy, out double cz);
                pinLambda[b] = -cx / alphaTilde;
                pinLambda[b + 1] = -cy / alphaTilde;
                pinLambda[b + 2] = -cz / alphaTilde;
            }
        }

        /// <summary>Target (rope-local m) of pin p at substep fraction t of the host step.</summary>
        private Float3 PinTarget(int p, float t) => Float3.Lerp(pinStart[p], pinEnd[p], t);

        /// <summary>Pin constraint C = x_i − target (m, double) from particle i's live position Prev + Low + D + DLow.</summary>
        private void PinOffset(int i, Float3 target, out double cx, out double cy, out double cz)
        {
            chain.Displacement(i, out double dx, out double dy, out double dz);
            cx = (double)chain.PrevX[i] - target.X + chain.LowX[i] + dx;
            cy = (double)chain.PrevY[i] - target.Y + chain.LowY[i] + dy;
            cz = (double)chain.PrevZ[i] - target.Z + chain.LowZ[i] + dz;
        }

        private void UpdateVelocities(double h)
        {
            double invH = 1.0 / h;
            int n = chain.ParticleCount;
            ReadOnlySpan<float> dx = ChainState.Exactly(chain.DX, n), dy = ChainState.Exactly(chain.DY, n), dz = ChainState.Exactly(chain.DZ, n);
            ReadOnlySpan<float> lx = ChainState.Exactly(chain.DLowX, n), ly = ChainState.Exactly(chain.DLowY, n), lz = ChainState.Exactly(chain.DLowZ, n);
            Span<double> vx = ChainState.Exactly(chain.VelX, n), vy = ChainState.Exactly(chain.VelY, n), vz = ChainState.Exactly(chain.VelZ, n);
            for (int i = 0; i < n; i++)
            {
                // v = (D + DLow)/h
                vx[i] = ((double)dx[i] + lx[i]) * invH; vy[i] = ((double)dy[i] + ly[i]) * invH; vz[i] = ((double)dz[i] + lz[i]) * invH;
            }
            CommitPositions();
        }

        /// <summary>
        /// Ends every particle's substep at x = x_prev + Low + d, with the velocity the integrator just wrote (m/s). The sum is
        /// formed in double and split into the float position and its new remainder Low, so no part of d is rounded away. Never
        /// lets a non-finite value into the state: then the particle falls back to its last good position, at rest, with no
        /// displacement (<see cref="RestoreParticle"/>).
        /// </summary>
        private void CommitPositions()
        {
            // on lanes where VectorPath.Enabled (Rope.Lanes)
            if (VectorPath.Enabled) CommitLanes();
            else CommitRange(0, chain.ParticleCount);
        }

        /// <summary><see cref="CommitPositions"/> for the particles from … from + n − 1.</summary>
        private void CommitRange(int from, int n)
        {
            // spans of exactly n entries (the loop bound): indexed without bounds checks
            Span<float> x = ChainState.Range(chain.X, from, n), y = ChainState.Range(chain.Y, from, n), z = ChainState.Range(chain.Z, from, n);
            ReadOnlySpan<float> px = ChainState.Range(chain.PrevX, from, n), py = ChainState.Range(chain.PrevY, from, n), pz = ChainState.Range(chain.PrevZ, from, n);
            ReadOnlySpan<float> dx = ChainState.Range(chain.DX, from, n), dy = ChainState.Range(chain.DY, from, n), dz = ChainState.Range(chain.DZ, from, n);
            ReadOnlySpan<float> dlx = ChainState.Range(chain.DLowX, from, n), dly = ChainState.Range(chain.DLowY, from, n), dlz = ChainState.Range(chain.DLowZ, from, n);
            Span<float> lx = ChainState.Range(chain.LowX, from, n), ly = ChainState.Range(chain.LowY, from, n), lz = ChainState.Range(chain.LowZ, from, n);
            ReadOnlySpan<double> vx = ChainState.Range(chain.VelX, from, n), vy = ChainState.Range(chain.VelY, from, n), vz = ChainState.Range(chain.VelZ, from, n);
            for (int i = 0; i < n; i++)
            {
                // x = x_prev + Low + (D + DLow)
                double ex = (double)px[i] + lx[i] + ((double)dx[i] + dlx[i]), ey = (double)py[i] + ly[i] + ((double)dy[i] + dly[i]);
                double ez = (double)pz[i] + lz[i] + ((double)dz[i] + dlz[i]);
                float nx = (float)ex, ny = (float)ey, nz = (float)ez;
                if (double.IsFinite(vx[i] + vy[i] + vz[i]) && float.IsFinite(nx + ny + nz))
                {
                    x[i] = nx; y[i] = ny; z[i] = nz;
                    lx[i] = (float)(ex - nx); ly[i] = (float)(ey - ny); lz[i] = (float)(ez - nz);
                }
                else RestoreParticle(from + i);
            }
        }

        /// <summary>A non-finite substep end of particle i: back to its last good position, at rest, with no displacement.</summary>
        private void RestoreParticle(int i)
        {
            chain.X[i] = chain.PrevX[i]; chain.Y[i] = chain.PrevY[i]; chain.Z[i] = chain.PrevZ[i];
            chain.VelX[i] = 0.0; chain.VelY[i] = 0.0; chain.VelZ[i] = 0.0;
            chain.SetDisplacement(i, 0.0, 0.0, 0.0);
        }

        /// <summary>
        /// Tensions T = −λ/h² (N) from the multipliers of the substep (h: the integrator's effective step, s); 0 for a broken
        /// segment. Also the largest and the summed substep tension of the host step (restarted on its first substep).
        /// </summary>
        private void UpdateTensions(double h, bool firstSubstep)
        {
            double invH2 = 1.0 / (h * h);
            // on lanes where VectorPath.Enabled and no segment is broken (Rope.Lanes)
            if (VectorPath.Enabled && chain.BrokenCount == 0) TensionLanes(invH2, firstSubstep);
            else TensionRange(invH2, firstSubstep, 0, chain.SegmentCount);
        }

        /// <summary><see cref="UpdateTensions"/> for the segments from … from + s − 1 (invH2 = 1/h², 1/s²).</summary>
        private void TensionRange(double invH2, bool firstSubstep, int from, int s)
        {
            // spans of exactly s entries (the loop bound): indexed without bounds checks
            ReadOnlySpan<double> lambda = ChainState.Range(chain.Lambda, from, s);
            Span<float> tension = ChainState.Range(chain.Tension, from, s), peak = ChainState.Range(chain.PeakTension, from, s), sum = ChainState.Range(chain.MeanTension, from, s);
            ReadOnlySpan<bool> broken = ChainState.Range(chain.Broken, from, s);
            // a broken segment reads 0 (skipped while none is broken); the host step's largest and summed substep tension
            // restart on its first substep
            bool intact = chain.BrokenCount == 0;
            if (firstSubstep)
            {
                for (int j = 0; j < s; j++)
                {
                    float value = Tension(intact || !broken[j] ? lambda[j] : 0.0, invH2);
                    tension[j] = value; peak[j] = value; sum[j] = value;
                }
                return;
            }
            for (int j = 0; j < s; j++)
            {
                float value = Tension(intact || !broken[j] ? lambda[j] : 0.0, invH2);
                tension[j] = value;
                if (value > peak[j]) peak[j] = value;
                sum[j] += value;
            }
        }

        /// <summary>Tension T = −λ/h² (N, float; non-finite reads float.MaxValue) of a multiplier λ (N·s²), invH2 = 1/h².</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static float Tension(double lambda, double invH2)
        {
            float value = (float)(-lambda * invH2);
            return float.IsFinite(value) ? value : float.MaxValue;
        }

        /// <summary>Raises each load's <see cref="GetLoadPeakForce"/> to this substep's |M·(Δv/h − g)| (invH = 1/h in 1/s).</summary>
        private void TrackLoadPeaks(float invH, Float3 g)
        {
            for (int l = 0; l < loadCount; l++)
            {
                int i = loadParticle[l];
                var v = new Float3((float)chain.VelX[i], (float)chain.VelY[i], (float)chain.VelZ[i]);
                float force = (((v - loadSubstepVelocity[l]) * invH - g) * loadMass[l]).Length;
                if (force > loadPeakForce[l]) loadPeakForce[l] = force;
                loadSubstepVelocity[l] = v;
            }
        }

        /// <summary>Turns the summed substep tensions into their mean (factor = 1/substeps).</summary>
        private void ScaleMeanTensions(float factor)
        {
            int s = chain.SegmentCount, from = 0;
            Span<float> mean = ChainState.Exactly(chain.MeanTension, s);
            if (VectorPath.Enabled)
            {
                // runs of Vector<float> segments (the same products), the rest below
                Span<Vector<float>> lanes = VectorPath.AsLanes(mean);
                for (int k = 0; k < lanes.Length; k++) lanes[k] *= factor;
                from = lanes.Length * Vector<float>.Count;
            }
            for (int j = from; j < s; j++) mean[j] *= factor;
        }

        private void UpdatePinForces(double h, Float3 g)
        {
            double invH2 = 1.0 / (h * h);
            bool released = false;
            for (int p = 0; p < pinCount; p++)
            {
                if (pinBroken[p]) continue;
                int i = pinParticle[p];
                Float3 force;
                if (pinCompliance[p] != 0f)
                {
                    int b = 3 * p;
                    force = new Float3((float)(-pinLambda[b] * invH2), (float)(-pinLambda[b + 1] * invH2), (float)(-pinLambda[b + 2] * invH2));
                }
                else
                {
                    force = g * (chain.Mass[i]);
                    if (i < chain.SegmentCount && !chain.Broken[i])
                        force += new Float3(chain.DirX[i], chain.DirY[i], chain.DirZ[i]) * chain.Tension[i];
                    if (i > 0 && !chain.Broken[i - 1])
                        force -= new Float3(chain.DirX[i - 1], chain.DirY[i - 1], chain.DirZ[i - 1]) * chain.Tension[i - 1];
                }
                if (SetPinForce(p, force)) released = true;
            }
            if (released) RefreshKinematic();
        }

        private float ComputeResidual()
        {
            double worst = 0.0;
            bool tensionOnly = settings.Tension == TensionModel.TensionOnly;
            // spans of exactly the loop bound (indexed without bounds checks)
            int s = chain.SegmentCount;
            ReadOnlySpan<bool> broken = ChainState.Exactly(chain.Broken, s);
            ReadOnlySpan<float> restLength = ChainState.Exactly(chain.RestLength, s), length = ChainState.Exactly(chain.Length, s);
            ReadOnlySpan<float> tensions = ChainState.Exactly(chain.Tension, s), compliance = ChainState.Exactly(chain.Compliance, s);
            SegmentPlasticity plasticity = chain.Plasticity;
            // an unbroken chain without plasticity on lanes first (the same largest error), the rows the rest
            int from = 0;
            if (VectorPath.Enabled && plasticity == null && chain.BrokenCount == 0) worst = ResidualLanes(tensionOnly, out from);
            for (int j = from; j < s; j++)
            {
                if (broken[j]) continue;
                double rest = restLength[j];
                double c = length[j] - chain.CurrentRest(j);
                double tension = tensions[j];
                if (tensionOnly && tension <= 0.0 && c <= 0.0) continue; // slack: no constraint to meet
                double error = Math.Abs(c - compliance[j] * tension) / rest;
                if (error > worst) worst = error;
            }
            return (float)worst;
        }
    }
}
