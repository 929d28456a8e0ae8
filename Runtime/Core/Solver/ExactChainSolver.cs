using System;
using System.Numerics;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// One Newton iteration of the implicit step of the whole chain, exact in the segment forces. The unknowns are the
    /// segment force vectors Λ_j = h²·F_j (N·s²): particle i moves by W_i (Λ_i − Λ_{i−1}) (W the inverse mass, projected
    /// onto the tangent plane of a held contact), and each segment's force must match its stretch, d_j = (L_j + α̃_j|Λ_j|)·ê_j.
    /// Linearised, that is the block-tridiagonal system (D W Dᵀ + Q̃_j⁻¹) δΛ = R with the segment compliance
    /// Q̃_j⁻¹ = α̃_j n nᵀ + (l_j/(T_j h²))(I − n nᵀ): the material compliance along the segment and the geometric
    /// (rotational) compliance across it, so the chain's transverse response under tension is implicit too — exactly, not
    /// lumped — and a taut chain neither zig-zags nor loses its slow swing (<see cref="SegmentForceSystem"/> solves it in
    /// O(n) with 3×3 blocks). The transverse compliance needs the tension, which the first iteration of a substep takes
    /// from the substep before; <see cref="Iterate"/> says when that estimate was too low for the result to be trusted.
    /// Tension-only segments and contacts are complementarity conditions, handled by active-set passes on the same
    /// linearisation (release a segment whose force would push, re-admit one the new solution stretches; release a
    /// contact the chain lifts off, hold one it drives into the surface).
    /// </summary>
    internal static partial class ExactChainSolver
    {
        /// <summary>
        /// Smallest cosine between the accumulated force of a segment beside a held contact and its direction for the force's
        /// direction to set the residual (about 25°): a converged force lies along its segment, and one far off it comes
        /// from a segment that was slack or held sideways by the contact in an earlier iteration; taking its direction as
        /// the target would ask for a correction of the order of the segment's length.
        /// </summary>
        public const double MinForceAlignment = 0.9;

        /// <summary>Largest number of active-set passes per iteration.</summary>
        public const int MaxPasses = 8;

        /// <summary>
        /// Largest number of active-set passes per iteration while the friction of some contact is still moving to its cone:
        /// many contacts sliding together converge slowly (each one's damping changes the slip of all), and friction cut
        /// short at 8 passes was up to 7 % above its cone at the light end of a wrap (box edges μ 0.3: capstan
        /// acceleration −95 % at 8 passes, −5 % at 32).
        /// </summary>
        public const int MaxFrictionPasses = 64;

        /// <summary>
        /// Largest transverse compliance of a segment as a multiple of its ends' mobility w_j + w_{j+1}: a slack or
        /// barely loaded segment has (almost) no geometric stiffness, and its force stays along it to 1e-6.
        /// </summary>
        public const double MaxTransverseComplianceRatio = 1e6;

        /// <summary>
        /// Largest second-order length error of an iteration, as a fraction of the rest length, that needs no further
        /// iteration: a segment whose ends moved by Δ across it in this iteration is longer than the linearisation assumed
        /// by about |Δ_⊥|²/(2l). Beyond it the linearisation is off and the iteration's step goes through
        /// <see cref="ChainLineSearch"/>.
        /// </summary>
        public const double NonlinearTolerance = 1e-3;

        /// <summary>
        /// Largest energy a converged iteration may leave in its segments' length errors, Σ(|F|·e + ½e²/α), as a fraction of
        /// the chain's kinetic and elastic energy: a stiff segment stores ½e²/α for a length error e (steel: 0.02 J for
        /// 3 µm on a 4 mm segment), so its error must be small in energy, not only against its length.
        /// </summary>
        public const double EnergyTolerance = 1e-6;

        /// <summary>
        /// Length error (as a multiple of the largest coordinate of the rope, <see cref="ChainState.Size"/>, m/m) below which
        /// an iteration cannot improve a segment: 4·2⁻²³, four float32 ulps of the positions it is stored in.
        /// </summary>
        public const double RoundOffFloor = 4.0 / 8388608.0;

        /// <summary>
        /// Runs one iteration (h: the integrator's effective substep, s; beta: damping β, s; first: the substep's first
        /// iteration, whose accumulated forces start at zero). Returns true when another iteration should follow: the
        /// tension the geometric stiffness was estimated with was less than half the tension found on some segment whose
        /// transverse response it governs (4·T·h²·w/l &gt; 1); the iteration moved some segment's ends across it by so
        /// much that its length is off the linearisation by more than a converged chain allows (<see cref="Apply"/>); a
        /// released tension-only segment ended stretched; the step went through the line search; a plastic segment changed
        /// branch; or a contact released in this substep was driven back into its surface
        /// (<see cref="ChainContacts.ReleasedInside"/>). <paramref name="violent"/>: the linearisation was off by more than
        /// <see cref="NonlinearTolerance"/> (its step went through <see cref="ChainLineSearch"/>), or a released segment ended
        /// stretched by more than that; <paramref name="shortened"/>: the line search took a step below 1;
        /// <paramref name="solves"/>: the linear solves of the iteration's active-set passes (<see cref="SolveActiveSet"/>).
        /// <paramref name="views"/>: this chain's lane views of the host step (<see cref="StepViews"/>, built with the vector
        /// paths on; the lane kernels read them and run only then).
        /// </summary>
        public static bool Iterate(ChainState c, in StepViews views, double h, double beta, bool tensionOnly, bool first, out bool violent, out bool shortened, out int solves)
        {
            System.Diagnostics.Debug.Assert(!VectorPath.Enabled || views.Chain == c, "the lane kernels read this chain's StepViews");
            double invH2 = 1.0 / (h * h);
            if (first) ClearForces(c);
            Assemble(c, in views, invH2, beta / h, first, tensionOnly);
            bool contacts = c.ContactCount > 0;
            if (contacts)
            {
                ChainContacts.Prepare(c);
                ChainContacts.DropContactsWithoutMobility(c);
            }
            solves = SolveActiveSet(c, in views, tensionOnly, contacts, first);
            // a contact released in this substep stays free in its active-set passes; if the solution drives it back into the
            // surface, another iteration follows, whose detection holds it where the collision pass put it
            bool reentered = contacts && ChainContacts.ReleasedInside(c);
            double nonlinear = Apply(c, in views, contacts, tensionOnly, invH2, out bool unconverged, out bool estimateTooLow);
            violent = nonlinear > NonlinearTolerance;
            shortened = false;
            // an iteration with friction in it takes the same tests as any other: the energy its length errors leave, and
            // the line search when violent, whose objective then holds the friction dampers' ½ζ|s|² (ChainContacts.FrictionChange)
            // and whose shortened step shortens the contacts' impulses and friction with it (ChainContacts.Shorten)
            if (violent)
            {
                double step = ChainLineSearch.Backtrack(c, tensionOnly, out bool friction);
                shortened = step < 1.0;
                if (shortened) ChainLineSearch.Shorten(c, step, friction);
                unconverged = true;
            }
            bool branches = c.Plasticity != null && c.Plasticity.UpdateBranches(c, invH2);
            // estimateTooLow is Apply's; a shortened step changed the forces after it, but then unconverged is true anyway
            return estimateTooLow || unconverged || branches || reentered;
        }

        private static void ClearForces(ChainState c)
        {
            int s = c.SegmentCount;
            // one loop: for the short arrays of a rope three calls to Array.Clear cost more than the stores; on lanes the
            // forces take one store per VectorPath.DoubleLanes segments (goal lanyard: 609 → 150 instructions per call)
            Span<double> fx = ChainState.Exactly(c.ForceX, s), fy = ChainState.Exactly(c.ForceY, s), fz = ChainState.Exactly(c.ForceZ, s);
            int from = 0;
            if (VectorPath.Enabled)
            {
                Span<Vector<double>> lx = VectorPath.AsLanes(fx), ly = VectorPath.AsLanes(fy), lz = VectorPath.AsLanes(fz);
                for (int k = 0; k < lx.Length; k++)
                {
                    lx[k] = Vector<double>.Zero; ly[k] = Vector<double>.Zero; lz[k] = Vector<double>.Zero;
                }
                from = lx.Length * VectorPath.DoubleLanes;
            }
            for (int j = from; j < s; j++)
            {
                fx[j] = 0.0; fy[j] = 0.0; fz[j] = 0.0;
            }
            ChainState.Exactly(c.Active, s).Fill(true);
        }

        /// <summary>
        /// Per segment: direction n and length l of the live positions, the compliances (damping folded in as XPBD's
        /// eq. 26: α̃' = α̃/(1 + γ), rest length shifted by the substep's stretch rate), the tension estimate of the
        /// geometric stiffness and the residual R = d − (L' + α̃'|Λ|)·ê of the accumulated force Λ (ê its direction, signed
        /// along n; n while Λ = 0, and n for a bilateral segment with no geometric stiffness in the system). A segment with
        /// no mobility and no compliance is not in the system.
        /// </summary>
        private static void Assemble(ChainState c, in StepViews views, double invH2, double gammaAll, bool first, bool tensionOnly)
        {
            c.RigidInSolve = false;
            // the lanes path takes whole runs of VectorPath.FloatLanes segments of an unbroken, non-plastic chain (and falls
            // back to the rows below for a run with an unusual segment); the rows take the rest
            int from = 0;
            if (VectorPath.Enabled && c.Plasticity == null && c.BrokenCount == 0)
                from = AssembleLanes(c, in views, invH2, gammaAll, first, tensionOnly);
            if (from < c.SegmentCount) AssembleRows(c, from, c.SegmentCount, invH2, gammaAll, first, tensionOnly);
        }

        /// <summary>The scalar <see cref="Assemble"/> of segments from … to − 1.</summary>
        private static void AssembleRows(ChainState c, int from, int to, double invH2, double gammaAll, bool first, bool tensionOnly)
        {
            int s = to;
            // spans of exactly s = to entries (the loop bound) index without bounds checks; B spans are particle j + 1's
            ReadOnlySpan<float> wA = ChainState.Exactly(c.InverseMass, s), wB = ChainState.Shifted(c.InverseMass, s);
            ReadOnlySpan<float> dxA = ChainState.Exactly(c.DX, s), dyA = ChainState.Exactly(c.DY, s), dzA = ChainState.Exactly(c.DZ, s);
            ReadOnlySpan<float> dxB = ChainState.Shifted(c.DX, s), dyB = ChainState.Shifted(c.DY, s), dzB = ChainState.Shifted(c.DZ, s);
            ReadOnlySpan<float> dlxA = ChainState.Exactly(c.DLowX, s), dlyA = ChainState.Exactly(c.DLowY, s), dlzA = ChainState.Exactly(c.DLowZ, s);
            ReadOnlySpan<float> dlxB = ChainState.Shifted(c.DLowX, s), dlyB = ChainState.Shifted(c.DLowY, s), dlzB = ChainState.Shifted(c.DLowZ, s);
            ReadOnlySpan<float> pxA = ChainState.Exactly(c.PrevX, s), pyA = ChainState.Exactly(c.PrevY, s), pzA = ChainState.Exactly(c.PrevZ, s);
            ReadOnlySpan<float> pxB = ChainState.Shifted(c.PrevX, s), pyB = ChainState.Shifted(c.PrevY, s), pzB = ChainState.Shifted(c.PrevZ, s);
            ReadOnlySpan<float> lxA = ChainState.Exactly(c.LowX, s), lyA = ChainState.Exactly(c.LowY, s), lzA = ChainState.Exactly(c.LowZ, s);
            ReadOnlySpan<float> lxB = ChainState.Shifted(c.LowX, s), lyB = ChainState.Shifted(c.LowY, s), lzB = ChainState.Shifted(c.LowZ, s);
            ReadOnlySpan<float> rest = ChainState.Exactly(c.RestLength, s), compliance = ChainState.Exactly(c.Compliance, s), lastTension = ChainState.Exactly(c.Tension, s);
            Span<float> length = ChainState.Exactly(c.Length, s);
            ReadOnlySpan<double> fx = ChainState.Exactly(c.ForceX, s), fy = ChainState.Exactly(c.ForceY, s), fz = ChainState.Exactly(c.ForceZ, s);
            Span<double> rx = ChainState.Exactly(c.ResidualX, s), ry = ChainState.Exactly(c.ResidualY, s), rz = ChainState.Exactly(c.ResidualZ, s);
            Span<double> axial = ChainState.Exactly(c.AxialCompliance, s), transverse = ChainState.Exactly(c.TransverseCompliance, s), estimate = ChainState.Exactly(c.EstimatedTension, s);
            ReadOnlySpan<bool> broken = ChainState.Exactly(c.Broken, s);
            Span<bool> active = ChainState.Exactly(c.Active, s);
            Span<float> dirX = ChainState.Exactly(c.DirX, s), dirY = ChainState.Exactly(c.DirY, s), dirZ = ChainState.Exactly(c.DirZ, s);
            Span<bool> assembled = ChainState.Exactly(c.Assembled, s);
            Span<double> effectiveRest = ChainState.Exactly(c.EffectiveRest, s);
            SegmentPlasticity plastic = c.Plasticity;
            for (int j = from; j < to; j++)
            {
                assembled[j] = false;
                if (broken[j]) { active[j] = false; continue; }
                // ChainState.LiveSpan and Normalise on the spans
                double ddx = ChainState.Change(dxA[j], dxB[j], dlxA[j], dlxB[j]), ddy = ChainState.Change(dyA[j], dyB[j], dlyA[j], dlyB[j]);
                double ddz = ChainState.Change(dzA[j], dzB[j], dlzA[j], dlzB[j]);
                double len = ChainState.Normalise(j, ChainState.Component(pxA[j], pxB[j], lxA[j], lxB[j], ddx), ChainState.Component(pyA[j], pyB[j], lyA[j], lyB[j], ddy),
                    ChainState.Component(pzA[j], pzB[j], lzA[j], lzB[j], ddz), dirX, dirY, dirZ, out double nx, out double ny, out double nz);
                length[j] = (float)len;
                double alpha = compliance[j];
                double mobility = (double)wA[j] + wB[j];
                if (mobility == 0.0 && alpha == 0.0) { active[j] = false; continue; }
                if (alpha == 0.0) c.RigidInSolve = true;
                double g = alpha > 0.0 ? gammaAll : 0.0;
                double restJ = plastic == null ? rest[j] : plastic.Rest(j); // a plastic segment's force is measured from L_p
                double restEffective = restJ, alphaTilde = alpha * invH2;
                if (g > 0.0)
                {
                    // the substep's stretch, m: along n (XPBD's linearised ∇C·Δx) on a tension-only rope; on a bilateral one
                    // the exact length change l − l₀ (BilateralDamping), so len − rate is the length at the substep's start
                    double rate = tensionOnly ? nx * ddx + ny * ddy + nz * ddz : len - StartLength(pxA[j], pxB[j], lxA[j], lxB[j], pyA[j], pyB[j], lyA[j], lyB[j], pzA[j], pzB[j], lzA[j], lzB[j]);
                    restEffective = (restJ + g * (len - rate)) / (1.0 + g);
                    alphaTilde /= 1.0 + g;
                }
                if (plastic != null && plastic.IsYielding(j))
                {
                    restEffective = FlowRow(plastic, j, invH2, restEffective, alphaTilde, out double flowCompliance);
                    alphaTilde = flowCompliance;
                }
                double magnitude = Math.Sqrt(fx[j] * fx[j] + fy[j] * fy[j] + fz[j] * fz[j]);
                double ex = nx, ey = ny, ez = nz, signed = 0.0;
                if (magnitude > 0.0)
                {
                    // a pushing (bilateral) force points against n; its direction ê keeps the segment's sense
                    double sense = fx[j] * nx + fy[j] * ny + fz[j] * nz >= 0.0 ? 1.0 : -1.0;
                    signed = sense * magnitude;
                    double inverse = sense / magnitude;
                    ex = fx[j] * inverse; ey = fy[j] * inverse; ez = fz[j] * inverse;
                    // beside a held contact, a force far off its segment (a nearly slack one held sideways by the contact in
                    // an earlier iteration) is no estimate of where the segment points: the residual is taken along n
                    if (ex * nx + ey * ny + ez * nz < MinForceAlignment && BesideHeldContact(c, j)) { ex = nx; ey = ny; ez = nz; }
                }
                // the geometric stiffness T/l: with the last substep's tension on the first iteration, the accumulated one after
                double tension = first ? Math.Abs(lastTension[j]) : Math.Abs(signed * invH2);
                estimate[j] = tension;
                double target = restEffective + alphaTilde * signed; // the length the accumulated force implies
                double geometric = AtLeast(target, 1e-6 * rest[j]) * invH2;
                double cap = MaxTransverseComplianceRatio * mobility;
                // a pushing (bilateral) segment's exact geometric stiffness is −|T|/l: the implicit step's energy is not convex
                // across it, and the Newton matrix with it is indefinite (it would buckle explicitly). It takes none (pure
                // axial: the transverse compliance at its cap), not +|T|/l, which is off by twice as much the other way and
                // made the pushing rods of the stability grid gain energy (solver.md, "Rods in compression")
                bool pushing = !tensionOnly && (first ? lastTension[j] < 0f : signed < 0.0);
                bool axialOnly = pushing || !(geometric < cap * tension);
                transverse[j] = axialOnly ? cap : geometric / tension;
                // a bilateral segment with (almost) no geometric stiffness in the system, pushing or nearly slack, has no
                // transverse residual the solve corrects: the direction of its force from earlier iterations can lag the
                // segment by θ, and a residual along it asks for the length L·cos θ (a 256-segment rod's free end converged
                // 0.27 mm short of 3.9 mm at +0.025 N: 0.73 J). Its residual is taken along the segment (solver.md, "Rods in
                // compression"); a tension-only one keeps it along its force
                if (axialOnly && !tensionOnly) { ex = nx; ey = ny; ez = nz; }
                axial[j] = alphaTilde;
                effectiveRest[j] = restEffective;
                assembled[j] = true;
                rx[j] = len * nx - target * ex; ry[j] = len * ny - target * ey; rz[j] = len * nz - target * ez;
            }
        }

        /// <summary>
        /// Length (m) of a segment at the start of the substep, |(P_b − P_a) + (Low_b − Low_a)|, from its ends' previous
        /// positions and remainders.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        private static double StartLength(float pxA, float pxB, float lxA, float lxB, float pyA, float pyB, float lyA, float lyB, float pzA, float pzB, float lzA, float lzB)
        {
            double x = ChainState.Component(pxA, pxB, lxA, lxB, 0.0), y = ChainState.Component(pyA, pyB, lyA, lyB, 0.0), z = ChainState.Component(pzA, pzB, lzA, lzB, 0.0);
            return Math.Sqrt(x * x + y * y + z * z);
        }

        /// <summary>
        /// <see cref="SegmentPlasticity.FlowRow"/> on copies (returns the effective rest length, the compliance in flowCompliance),
        /// so the assembly's own locals are not address-exposed and stay in registers.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        private static double FlowRow(SegmentPlasticity plastic, int j, double invH2, double restEffective, double alphaTilde, out double flowCompliance)
        {
            plastic.FlowRow(j, invH2, ref restEffective, ref alphaTilde);
            flowCompliance = alphaTilde;
            return restEffective;
        }

        /// <summary>True when an end of segment j is a held contact.</summary>
        private static bool BesideHeldContact(ChainState c, int j) => c.ContactCount > 0 && (c.ContactActive[j] || c.ContactActive[j + 1]);

        /// <summary>
        /// Solves for δΛ, then repeats on the same linearisation while the active set changes (at most
        /// <see cref="MaxPasses"/> solves, or <see cref="MaxFrictionPasses"/> while contact friction is still moving to its
        /// cone): a tension-only segment whose total force would push is released (its force returns to zero), a released
        /// one the solution stretches is re-admitted; a held contact the chain pulls off the surface is released, a released
        /// one it drives deeper than its gap is held; friction follows its cone (<see cref="ChainContacts"/>). Returns the
        /// number of solves (1 when the set holds). A fresh hanging rope, released at its rest length, takes up to
        /// <see cref="MaxPasses"/> while its tension front runs down it: the chain below the front falls free, its segments
        /// at zero force either way, and each pass moves the released set (solver.md, "The exact solve against the segment count").
        /// </summary>
        private static int SolveActiveSet(ChainState c, in StepViews views, bool tensionOnly, bool contacts, bool first)
        {
            bool frictionMoving = false;
            // the first row the forward sweep must redo: between passes without contacts only the tension-only flags change,
            // and the rows before the first changed one keep their pivots and reduced right-hand sides bit for bit
            int from = 0;
            // the free blocks depend only on this linearisation: on wide lanes built once for every pass
            SegmentForceSystem.PrepareBlocks(c, in views);
            for (int pass = 1; ; pass++)
            {
                SegmentForceSystem.Solve(c, from);
                if ((!tensionOnly && !contacts) || pass >= MaxFrictionPasses || (pass >= MaxPasses && !frictionMoving)) return pass;
                // from: the tension-only pass's first changed row, 0 once the contacts may have changed (without tensionOnly
                // there are contacts, so every path past the return above sets it)
                bool changed = tensionOnly && UpdateTensionOnlySet(c, in views, out from);
                if (contacts)
                {
                    changed |= ChainContacts.Update(c, first, out frictionMoving);
                    from = 0;
                }
                if (!changed) return pass;
            }
        }

        /// <summary>Releases and re-admits tension-only segments (see <see cref="SolveActiveSet"/>); <paramref name="firstChanged"/>: the first row whose flag changed (SegmentCount when none).</summary>
        private static bool UpdateTensionOnlySet(ChainState c, in StepViews views, out int firstChanged)
        {
            int s = c.SegmentCount;
            bool changed = false;
            int first = s;
            // the lanes skip the runs of active segments that all still pull (on the host step's views); the rows take the
            // rest, in order
            int from = !VectorPath.Enabled || c.BrokenCount != 0 ? 0 : UpdateTensionOnlyLanes(c, in views, ref changed, ref first);
            if (from < s) UpdateTensionOnlyRows(c, from, s, ref changed, ref first);
            firstChanged = first;
            return changed;
        }

        /// <summary><see cref="UpdateTensionOnlySet"/> on segments from … to − 1 (changed and first: so far, updated).</summary>
        private static void UpdateTensionOnlyRows(ChainState c, int from, int to, ref bool anyChanged, ref int firstChanged)
        {
            int s = to;
            // spans of exactly s = to entries (the loop bound): indexed without bounds checks
            ReadOnlySpan<double> fx = ChainState.Exactly(c.ForceX, s), fy = ChainState.Exactly(c.ForceY, s), fz = ChainState.Exactly(c.ForceZ, s);
            ReadOnlySpan<double> dx = ChainState.Exactly(c.StepX, s), dy = ChainState.Exactly(c.StepY, s), dz = ChainState.Exactly(c.StepZ, s);
            ReadOnlySpan<float> dirX = ChainState.Exactly(c.DirX, s), dirY = ChainState.Exactly(c.DirY, s), dirZ = ChainState.Exactly(c.DirZ, s);
            Span<bool> active = ChainState.Exactly(c.Active, s);
            ReadOnlySpan<bool> broken = ChainState.Exactly(c.Broken, s);
            bool changed = anyChanged;
            int first = firstChanged;
            for (int j = from; j < s; j++)
            {
                if (broken[j]) continue;
                if (active[j])
                {
                    double along = (fx[j] + dx[j]) * dirX[j] + (fy[j] + dy[j]) * dirY[j] + (fz[j] + dz[j]) * dirZ[j];
                    if (along >= 0.0) continue;
                    active[j] = false;
                }
                else if (Restores(c, j)) active[j] = true;
                else continue;
                if (!changed) first = j;
                changed = true;
            }
            anyChanged = changed;
            firstChanged = first;
        }

        /// <summary>
        /// True when released segment j rejoins the system: it may (<see cref="IsRestorable"/>) and this solution stretches it
        /// (<see cref="StretchAfter"/> along its stored direction). Not inlined: the pass over the active rows keeps its
        /// values in registers.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        private static bool Restores(ChainState c, int j) => c.ContactCount == 0 && c.BrokenCount == 0
            ? FreeRestores(c, j) : IsRestorable(c, j) && StretchAfter(c, j, c.DirX[j], c.DirY[j], c.DirZ[j]) > 0.0;

        /// <summary>
        /// <see cref="Restores"/> of a chain without contacts or broken segments: <see cref="IsRestorable"/> and
        /// <see cref="StretchAfter"/> with the ends' motions w_i·pull written out, operation for operation (the same bits;
        /// goal lanyard: 200 → 75 instructions per released segment and pass).
        /// </summary>
        private static bool FreeRestores(ChainState c, int j)
        {
            float[] w = c.InverseMass;
            double wa = w[j], wb = w[j + 1];
            if (!(wa + wb > 0.0 || c.Compliance[j] > 0f)) return false;
            int s = c.SegmentCount;
            double x = FreeStretchAlong(c.StepX, c.ResidualX[j], j, s, wa, wb);
            double y = FreeStretchAlong(c.StepY, c.ResidualY[j], j, s, wa, wb);
            double z = FreeStretchAlong(c.StepZ, c.ResidualZ[j], j, s, wa, wb);
            return (double)c.DirX[j] * x + (double)c.DirY[j] * y + (double)c.DirZ[j] * z > 0.0;
        }

        /// <summary>
        /// One axis of <see cref="FreeRestores"/>: the residual plus the relative motion of segment j's ends, (R + w_b·pull_b)
        /// − w_a·pull_a, the pulls as <see cref="SegmentForceSystem.Pull"/> forms them (step: δΛ of that axis).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static double FreeStretchAlong(double[] step, double residual, int j, int s, double wa, double wb)
        {
            double pullA = j > 0 ? step[j] - step[j - 1] : step[j];
            double pullB = (j + 1 < s ? step[j + 1] : 0.0) - step[j];
            return residual + wb * pullB - wa * pullA;
        }

        /// <summary>A released segment that may rejoin the system (it has mobility or compliance, unlike an invalid row).</summary>
        private static bool IsRestorable(ChainState c, int j) => (double)c.InverseMass[j] + c.InverseMass[j + 1] > 0.0 || c.Compliance[j] > 0f;

        /// <summary>Stretch (m) segment j would have after this solution: n·(R + its ends' relative motion).</summary>
        private static double StretchAfter(ChainState c, int j, double nx, double ny, double nz)
        {
            // inlined, with its no-contact return (the motion is W_i·pull alone)
            ChainContacts.Motion(c, j, out double ax, out double ay, out double az);
            ChainContacts.Motion(c, j + 1, out double bx, out double by, out double bz);
            return nx * (c.ResidualX[j] + bx - ax) + ny * (c.ResidualY[j] + by - ay) + nz * (c.ResidualZ[j] + bz - az);
        }

        /// <summary>
        /// Moves every particle by its mobility times this iteration's pull (a held contact also by the displacement it
        /// prescribes, exactly as the system assumed: <see cref="ChainContacts"/>), records it as the particle's motion,
        /// accumulates the forces and writes the scalar multipliers λ_j = −Λ_j·n_j the tension read-outs use. Then the
        /// convergence test: returns the largest length error over the rest length of a pulling segment — its second-order
        /// error e = |Δ_⊥|²/(2l) from this iteration's relative motion Δ of its ends (see <see cref="NonlinearTolerance"/>),
        /// or a released (tension-only) segment's stretch beyond its rest length — and sets <paramref name="unconverged"/>
        /// when some active segment's error exceeds NonlinearTolerance·L, a released one is stretched by that much, or the
        /// energy the errors above round-off leave in the segments is too large (<see cref="Mismatched"/>).
        /// <paramref name="estimateTooLow"/>: the tension-estimate test of <see cref="Iterate"/> failed on some active segment
        /// (<see cref="EstimateTooLow"/>, on the forces of the full step; invH2 = 1/h², 1/s²).
        /// </summary>
        private static double Apply(ChainState c, in StepViews views, bool contacts, bool tensionOnly, double invH2, out bool unconverged, out bool estimateTooLow)
        {
            // the particle pass on lanes leaves the length errors to ApplyLanes, which computes them per run of segments
            bool lanes = !contacts && VectorPath.Enabled && c.BrokenCount == 0 && c.SegmentCount > VectorPath.FloatLanes;
            if (contacts) MoveParticles<SegmentForceSystem.WithContacts>(c);
            else if (lanes) MoveParticlesLanes(c, in views);
            else MoveParticles<SegmentForceSystem.NoContacts>(c);
            int s = c.SegmentCount;
            var tests = new ConvergenceTests { Floor = RoundOffFloor * c.Size };
            // the lanes take the runs of active segments whose tests all pass quietly; the rows the rest, in order (on the
            // chain's views of the host step, StepViews, or views built for the call)
            int from = !VectorPath.Enabled ? 0 : ApplyLanes(c, in views, tensionOnly, invH2, lanes, ref tests);
            if (from < s) ApplyRows(c, from, s, tensionOnly, invH2, ref tests);
            unconverged = tests.Unconverged;
            estimateTooLow = tests.EstimateTooLow;
            if (!unconverged && tests.Mismatched) unconverged = Mismatched(c, tensionOnly, tests.Floor);
            return tests.Worst;
        }

        /// <summary>The convergence tests of <see cref="Apply"/> as they accumulate over the segments.</summary>
        private struct ConvergenceTests
        {
            /// <summary>Round-off floor of the length errors (m); the largest error over rest length so far.</summary>
            public double Floor, Worst;
            public bool Mismatched, Unconverged, EstimateTooLow;
        }

        /// <summary>
        /// <see cref="Apply"/>'s segment pass on segments from … to − 1: accumulates the forces, writes λ and runs the
        /// convergence tests into <paramref name="tests"/>.
        /// </summary>
        private static void ApplyRows(ChainState c, int from, int to, bool tensionOnly, double invH2, ref ConvergenceTests tests)
        {
            int s = to; // spans of exactly the loop bound: indexed without bounds checks
            ReadOnlySpan<float> dirX = ChainState.Exactly(c.DirX, s), dirY = ChainState.Exactly(c.DirY, s), dirZ = ChainState.Exactly(c.DirZ, s);
            ReadOnlySpan<float> rest = ChainState.Exactly(c.RestLength, s);
            Span<double> error = ChainState.Exactly(c.LengthError, s);
            ReadOnlySpan<double> sx = ChainState.Exactly(c.StepX, s), sy = ChainState.Exactly(c.StepY, s), sz = ChainState.Exactly(c.StepZ, s);
            ReadOnlySpan<bool> active = ChainState.Exactly(c.Active, s);
            Span<double> fx = ChainState.Exactly(c.ForceX, s), fy = ChainState.Exactly(c.ForceY, s), fz = ChainState.Exactly(c.ForceZ, s);
            Span<double> lambda = ChainState.Exactly(c.Lambda, s);
            ReadOnlySpan<bool> assembled = ChainState.Exactly(c.Assembled, s);
            ReadOnlySpan<double> estimate = ChainState.Exactly(c.EstimatedTension, s);
            double floor = tests.Floor, worst = tests.Worst;
            bool mismatched = tests.Mismatched, unconverged = tests.Unconverged, estimateTooLow = tests.EstimateTooLow;
            for (int j = from; j < s; j++)
            {
                double gx = fx[j] + sx[j], gy = fy[j] + sy[j], gz = fz[j] + sz[j];
                fx[j] = gx; fy[j] = gy; fz[j] = gz;
                double l = active[j] ? -(gx * dirX[j] + gy * dirY[j] + gz * dirZ[j]) : 0.0;
                lambda[j] = l;
                double e;
                if (active[j])
                {
                    // the tension-estimate test (see Iterate): the found tension −λ/h² above twice the estimate
                    double found = -l * invH2;
                    if (found > 2.0 * estimate[j] && EstimateTooLow(c, j, found, invH2)) estimateTooLow = true;
                    e = error[j];
                    // a pushing (bilateral) segment has no geometric stiffness in the system (see Assemble): it may add
                    // iterations, but it is not a violent linearisation and keeps no energy test (counting it in either was
                    // measured: more pushing rods of the stability grid gained energy, solver.md "Rods in compression")
                    if (l > 0.0)
                    {
                        if (e > NonlinearTolerance * rest[j]) unconverged = true;
                        continue;
                    }
                }
                else if (tensionOnly && assembled[j])
                {
                    e = StretchBeyondRest(c, j);
                    error[j] = e;
                }
                else continue;
                if (e <= floor) continue;
                double r = rest[j];
                if (e > worst * r) worst = e / r;
                if (e > NonlinearTolerance * r) unconverged = true;
                else mismatched = true;
            }
            tests.Worst = worst; tests.Mismatched = mismatched; tests.Unconverged = unconverged; tests.EstimateTooLow = estimateTooLow;
        }

        /// <summary>
        /// The particle pass of <see cref="Apply"/>: moves every particle by its mobility times this iteration's pull (at a
        /// contact through <see cref="Move"/>), records its motion and each active segment's second-order length error.
        /// Specialised on contacts (<see cref="SegmentForceSystem.WithContacts"/>): without them the loop calls nothing, so
        /// its motion and carried segment stay in registers.
        /// </summary>
        private static void MoveParticles<T>(ChainState c) where T : struct
        {
            int s = c.SegmentCount;
            // spans of exactly s entries (the loop bound) index without bounds checks; particle s is moved after the loop.
            // Particle i is pulled by segment i (index i) and segment i − 1, whose values are carried from the pass before.
            ReadOnlySpan<float> w = ChainState.Exactly(c.InverseMass, s), dirX = ChainState.Exactly(c.DirX, s), dirY = ChainState.Exactly(c.DirY, s), dirZ = ChainState.Exactly(c.DirZ, s);
            ReadOnlySpan<float> length = ChainState.Exactly(c.Length, s), rest = ChainState.Exactly(c.RestLength, s);
            Span<float> dx = ChainState.Exactly(c.DX, s), dy = ChainState.Exactly(c.DY, s), dz = ChainState.Exactly(c.DZ, s);
            Span<float> dlx = ChainState.Exactly(c.DLowX, s), dly = ChainState.Exactly(c.DLowY, s), dlz = ChainState.Exactly(c.DLowZ, s);
            Span<double> motionX = ChainState.Exactly(c.MotionX, s), motionY = ChainState.Exactly(c.MotionY, s), motionZ = ChainState.Exactly(c.MotionZ, s);
            Span<double> error = ChainState.Exactly(c.LengthError, s);
            ReadOnlySpan<double> sx = ChainState.Exactly(c.StepX, s), sy = ChainState.Exactly(c.StepY, s), sz = ChainState.Exactly(c.StepZ, s);
            ReadOnlySpan<bool> broken = ChainState.Exactly(c.Broken, s), active = ChainState.Exactly(c.Active, s);
            double qx = 0, qy = 0, qz = 0, mx, my, mz;
            // segment i − 1: its step (0 when broken or before the first particle), active flag, direction and length
            double ax = 0, ay = 0, az = 0;
            bool before = false;
            float ex = 0f, ey = 0f, ez = 0f, el = 0f, er = 0f;
            for (int i = 0; i < s; i++)
            {
                double px = 0, py = 0, pz = 0;
                if (!broken[i]) { px = sx[i]; py = sy[i]; pz = sz[i]; }
                if (typeof(T) == typeof(SegmentForceSystem.WithContacts)) Move(c, i, w[i], px - ax, py - ay, pz - az, true, out mx, out my, out mz);
                else
                {
                    double wi = w[i];
                    mx = wi * (px - ax); my = wi * (py - ay); mz = wi * (pz - az);
                }
                ChainState.Add(ref dx[i], ref dlx[i], mx); ChainState.Add(ref dy[i], ref dly[i], my); ChainState.Add(ref dz[i], ref dlz[i], mz);
                motionX[i] = mx; motionY[i] = my; motionZ[i] = mz;
                if (before) error[i - 1] = LengthError(mx - qx, my - qy, mz - qz, ex, ey, ez, el, er);
                qx = mx; qy = my; qz = mz;
                if (broken[i]) { ax = 0; ay = 0; az = 0; } else { ax = sx[i]; ay = sy[i]; az = sz[i]; }
                before = active[i]; ex = dirX[i]; ey = dirY[i]; ez = dirZ[i]; el = length[i]; er = rest[i];
            }
            Move(c, s, c.InverseMass[s], -ax, -ay, -az, typeof(T) == typeof(SegmentForceSystem.WithContacts), out mx, out my, out mz);
            c.AddDisplacement(s, mx, my, mz);
            c.MotionX[s] = mx; c.MotionY[s] = my; c.MotionZ[s] = mz;
            if (before) error[s - 1] = LengthError(mx - qx, my - qy, mz - qz, ex, ey, ez, el, er);
        }

        /// <summary>How much longer (m) released segment j now is than its effective rest length (≤ 0: not stretched).</summary>
        private static double StretchBeyondRest(ChainState c, int j)
        {
            c.LiveSpan(j, out double dx, out double dy, out double dz, out _, out _, out _);
            return Math.Sqrt(dx * dx + dy * dy + dz * dz) - c.EffectiveRest[j];
        }

        /// <summary>
        /// True when the length errors above round-off (<paramref name="floor"/>, m) of the pulling and released segments
        /// (<see cref="ChainState.LengthError"/>) leave more energy in them, Σ (|F|·e + ½e²/α), than
        /// <see cref="EnergyTolerance"/> of the chain's kinetic (over the substep) and elastic energy. A stiff segment stores
        /// ½e²/α for a length error e, so its error must be small in energy, not only against its length; a floppy one
        /// (a light free end) may keep a larger one.
        /// </summary>
        private static bool Mismatched(ChainState c, bool tensionOnly, double floor)
        {
            double mismatch = 0.0, reference = 0.0;
            // spans of exactly the loop bounds: indexed without bounds checks, each array's reference loaded once
            int s = c.SegmentCount, n = c.ParticleCount;
            ReadOnlySpan<bool> assembled = ChainState.Exactly(c.Assembled, s), active = ChainState.Exactly(c.Active, s);
            ReadOnlySpan<double> axial = ChainState.Exactly(c.AxialCompliance, s), lambda = ChainState.Exactly(c.Lambda, s), error = ChainState.Exactly(c.LengthError, s);
            ReadOnlySpan<double> fx = ChainState.Exactly(c.ForceX, s), fy = ChainState.Exactly(c.ForceY, s), fz = ChainState.Exactly(c.ForceZ, s);
            for (int j = 0; j < s; j++)
            {
                if (!assembled[j]) continue;
                double alpha = axial[j], squared = fx[j] * fx[j] + fy[j] * fy[j] + fz[j] * fz[j];
                if (active[j]) reference += 0.5 * alpha * squared;
                bool counted = active[j] ? lambda[j] <= 0.0 : tensionOnly;
                double e = error[j];
                if (!counted || e <= floor || alpha == 0.0) continue;
                mismatch += (active[j] ? Math.Sqrt(squared) * e : 0.0) + 0.5 * e * e / alpha;
            }
            ReadOnlySpan<float> inverseMass = ChainState.Exactly(c.InverseMass, n);
            ReadOnlySpan<float> dx = ChainState.Exactly(c.DX, n), dy = ChainState.Exactly(c.DY, n), dz = ChainState.Exactly(c.DZ, n);
            for (int i = 0; i < n; i++)
            {
                double w = inverseMass[i];
                if (w > 0.0) reference += 0.5 * ((double)dx[i] * dx[i] + (double)dy[i] * dy[i] + (double)dz[i] * dz[i]) / w;
            }
            return mismatch > EnergyTolerance * reference;
        }

        /// <summary>
        /// Particle i's motion (m) under the pull (px, py, pz) (N·s²) with inverse mass wi: wi·pull, less the normal motion a
        /// held contact withholds (which it records as the contact's normal load; the contact may still close its gap).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static void Move(ChainState c, int i, double wi, double px, double py, double pz, bool contacts, out double mx, out double my, out double mz)
        {
            mx = wi * px; my = wi * py; mz = wi * pz;
            if (contacts && c.ContactCollider[i] >= 0) MoveAtContact(c, i, px, py, pz, out mx, out my, out mz);
        }

        /// <summary>
        /// Motion of a particle at a contact under the pull (px, py, pz): the held motion W_i·pull plus what the contact
        /// prescribes (its shift: the gap allowance and friction), which <see cref="ChainContacts.Finish"/> records.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        private static void MoveAtContact(ChainState c, int i, double px, double py, double pz, out double mx, out double my, out double mz)
        {
            SegmentForceSystem.Mobility(c, i, px, py, pz, out mx, out my, out mz);
            mx += c.ContactShiftX[i]; my += c.ContactShiftY[i]; mz += c.ContactShiftZ[i];
            ChainContacts.Finish(c, i, px, py, pz, mx, my, mz);
        }

        /// <summary>
        /// Second-order length error |Δ_⊥|²/(2l) (m) of a segment (direction e, length l, rest length L, m) whose ends moved
        /// apart by (ux, uy, uz) in this iteration (see <see cref="NonlinearTolerance"/>).
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static double LengthError(double ux, double uy, double uz, float ex, float ey, float ez, float length, float rest)
        {
            double along = ux * ex + uy * ey + uz * ez;
            double perp = ux * ux + uy * uy + uz * uz - along * along;
            return perp / (2.0 * AtLeast(length, 1e-6 * rest));
        }

        /// <summary>
        /// max(value, floor) for a positive floor, as Math.Max gives it (a NaN value stays NaN), without Math.Max's code for
        /// NaN and signed zeros, which the JIT expands to about twenty instructions per call.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private static double AtLeast(double value, double floor) => value < floor ? floor : value;

        /// <summary>
        /// See <see cref="Iterate"/>: active segment j's tension found (N), above twice its estimate, governs its transverse
        /// response, 4·T·h²·max(w)/l &gt; 1 (invH2 = 1/h²). Out of line: <see cref="Apply"/>'s loop calls it only then.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        private static bool EstimateTooLow(ChainState c, int j, double found, double invH2)
        {
            double w = Math.Max(c.InverseMass[j], c.InverseMass[j + 1]);
            return 4.0 * found * w > invH2 * Math.Max(c.Length[j], 1e-6 * c.RestLength[j]);
        }
    }
}
