using System;

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
    internal static class ExactChainSolver
    {
        /// <summary>Largest number of active-set passes per iteration.</summary>
        public const int MaxPasses = 8;

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
        /// released tension-only segment ended stretched; or the line search shortened the step. <paramref name="violent"/>: the linearisation was off by more than <see cref="NonlinearTolerance"/> (its
        /// step went through <see cref="ChainLineSearch"/>), or a released segment ended stretched by more than that.
        /// </summary>
        public static bool Iterate(ChainState c, double h, double beta, bool tensionOnly, bool first, out bool violent, out bool shortened)
        {
            double invH2 = 1.0 / (h * h);
            if (first) ClearForces(c);
            Assemble(c, invH2, beta / h, first);
            bool contacts = c.ContactCount > 0;
            if (contacts) DropContactsWithoutMobility(c);
            SolveActiveSet(c, tensionOnly, contacts);
            double nonlinear = Apply(c, contacts, tensionOnly, out bool unconverged);
            violent = nonlinear > NonlinearTolerance;
            shortened = false;
            if (violent)
            {
                double step = ChainLineSearch.Backtrack(c, tensionOnly);
                shortened = step < 1.0;
                if (shortened) ChainLineSearch.Shorten(c, step);
                unconverged = true;
            }
            bool branches = c.Plasticity != null && c.Plasticity.UpdateBranches(c, invH2);
            return EstimateTooLow(c, invH2) || unconverged || branches;
        }

        private static void ClearForces(ChainState c)
        {
            int s = c.SegmentCount;
            Array.Clear(c.ForceX, 0, s);
            Array.Clear(c.ForceY, 0, s);
            Array.Clear(c.ForceZ, 0, s);
            for (int j = 0; j < s; j++) c.Active[j] = true;
        }

        /// <summary>
        /// Per segment: direction n and length l of the live positions, the compliances (damping folded in as XPBD's
        /// eq. 26: α̃' = α̃/(1 + γ), rest length shifted by the substep's stretch rate), the tension estimate of the
        /// geometric stiffness and the residual R = d − (L' + α̃'|Λ|)·ê of the accumulated force Λ (ê its direction, signed
        /// along n; n while Λ = 0). A segment with no mobility and no compliance is not in the system.
        /// </summary>
        private static void Assemble(ChainState c, double invH2, double gammaAll, bool first)
        {
            int s = c.SegmentCount;
            float[] w = c.InverseMass, rest = c.RestLength, compliance = c.Compliance, length = c.Length;
            double[] fx = c.ForceX, fy = c.ForceY, fz = c.ForceZ, rx = c.ResidualX, ry = c.ResidualY, rz = c.ResidualZ;
            double[] axial = c.AxialCompliance, transverse = c.TransverseCompliance, estimate = c.EstimatedTension;
            bool[] broken = c.Broken, active = c.Active, assembled = c.Assembled;
            c.RigidInSolve = false;
            SegmentPlasticity plastic = c.Plasticity;
            for (int j = 0; j < s; j++)
            {
                assembled[j] = false;
                if (broken[j]) { active[j] = false; continue; }
                double len = c.Direction(j, out double nx, out double ny, out double nz, out float ddx, out float ddy, out float ddz);
                length[j] = (float)len;
                double alpha = compliance[j];
                double mobility = (double)w[j] + w[j + 1];
                if (mobility == 0.0 && alpha == 0.0) { active[j] = false; continue; }
                if (alpha == 0.0) c.RigidInSolve = true;
                double g = alpha > 0.0 ? gammaAll : 0.0;
                double restJ = plastic == null ? rest[j] : plastic.Rest(j); // a plastic segment's force is measured from L_p
                double restEffective = restJ, alphaTilde = alpha * invH2;
                if (g > 0.0)
                {
                    double rate = nx * ddx + ny * ddy + nz * ddz; // the substep's stretch along n, m
                    restEffective = (restJ + g * (len - rate)) / (1.0 + g);
                    alphaTilde /= 1.0 + g;
                }
                if (plastic != null && plastic.IsYielding(j)) plastic.FlowRow(j, invH2, ref restEffective, ref alphaTilde);
                double magnitude = Math.Sqrt(fx[j] * fx[j] + fy[j] * fy[j] + fz[j] * fz[j]);
                double ex = nx, ey = ny, ez = nz, signed = 0.0;
                if (magnitude > 0.0)
                {
                    // a pushing (bilateral) force points against n; its direction ê keeps the segment's sense
                    double sense = fx[j] * nx + fy[j] * ny + fz[j] * nz >= 0.0 ? 1.0 : -1.0;
                    signed = sense * magnitude;
                    double inverse = sense / magnitude;
                    ex = fx[j] * inverse; ey = fy[j] * inverse; ez = fz[j] * inverse;
                }
                // the geometric stiffness T/l: with the last substep's tension on the first iteration, the accumulated one after;
                // a pushing (bilateral) segment's is −|T|/l, which would let it buckle explicitly, so it takes |T| and the
                // buckling is damped instead
                double tension = first ? Math.Abs(c.Tension[j]) : Math.Abs(signed * invH2);
                estimate[j] = tension;
                double target = restEffective + alphaTilde * signed; // the length the accumulated force implies
                double geometric = Math.Max(target, 1e-6 * rest[j]) * invH2;
                double cap = MaxTransverseComplianceRatio * mobility;
                transverse[j] = geometric < cap * tension ? geometric / tension : cap;
                axial[j] = alphaTilde;
                c.EffectiveRest[j] = restEffective;
                assembled[j] = true;
                rx[j] = len * nx - target * ex; ry[j] = len * ny - target * ey; rz[j] = len * nz - target * ez;
            }
        }

        /// <summary>
        /// A held contact that would leave one of its segments with no mobility along it (the other end pinned, the normal
        /// along the segment, and no compliance) is dropped: the row would be singular.
        /// </summary>
        private static void DropContactsWithoutMobility(ChainState c)
        {
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                if (!c.ContactActive[i]) continue;
                if ((i > 0 && !AxialMobilityLeft(c, i - 1)) || (i < c.SegmentCount && !AxialMobilityLeft(c, i)))
                    c.ContactActive[i] = false;
            }
        }

        /// <summary>True when segment j keeps mobility (or compliance) along its direction with its ends' contacts held.</summary>
        private static bool AxialMobilityLeft(ChainState c, int j)
        {
            if (c.Broken[j] || c.Compliance[j] > 0f) return true;
            double nx = c.DirX[j], ny = c.DirY[j], nz = c.DirZ[j];
            double along = SegmentForceSystem.AlongMobility(c, j, nx, ny, nz) + SegmentForceSystem.AlongMobility(c, j + 1, nx, ny, nz);
            return along > 1e-9 * ((double)c.InverseMass[j] + c.InverseMass[j + 1]);
        }

        /// <summary>
        /// Solves for δΛ, then repeats on the same linearisation while the active set changes (at most
        /// <see cref="MaxPasses"/> solves): a tension-only segment whose total force would push is released (its force
        /// returns to zero), a released one the solution stretches is re-admitted; a held contact the chain pulls off the
        /// surface is released, a released one it drives deeper than its gap is held.
        /// </summary>
        private static void SolveActiveSet(ChainState c, bool tensionOnly, bool contacts)
        {
            for (int pass = 1; ; pass++)
            {
                SegmentForceSystem.Solve(c);
                if ((!tensionOnly && !contacts) || pass >= MaxPasses) return;
                bool changed = tensionOnly && UpdateTensionOnlySet(c);
                if (contacts) changed |= UpdateContacts(c);
                if (!changed) return;
            }
        }

        private static bool UpdateTensionOnlySet(ChainState c)
        {
            int s = c.SegmentCount;
            double[] fx = c.ForceX, fy = c.ForceY, fz = c.ForceZ, dx = c.StepX, dy = c.StepY, dz = c.StepZ;
            bool[] active = c.Active, broken = c.Broken;
            bool changed = false;
            for (int j = 0; j < s; j++)
            {
                if (broken[j]) continue;
                double nx = c.DirX[j], ny = c.DirY[j], nz = c.DirZ[j];
                if (active[j])
                {
                    double along = (fx[j] + dx[j]) * nx + (fy[j] + dy[j]) * ny + (fz[j] + dz[j]) * nz;
                    if (along < 0.0) { active[j] = false; changed = true; }
                }
                else if (IsRestorable(c, j) && StretchAfter(c, j, nx, ny, nz) > 0.0)
                {
                    active[j] = true;
                    changed = true;
                }
            }
            return changed;
        }

        /// <summary>A released segment that may rejoin the system (it has mobility or compliance, unlike an invalid row).</summary>
        private static bool IsRestorable(ChainState c, int j) => (double)c.InverseMass[j] + c.InverseMass[j + 1] > 0.0 || c.Compliance[j] > 0f;

        /// <summary>Stretch (m) segment j would have after this solution: n·(R + its ends' relative motion).</summary>
        private static double StretchAfter(ChainState c, int j, double nx, double ny, double nz)
        {
            SegmentForceSystem.Motion(c, j, out double ax, out double ay, out double az);
            SegmentForceSystem.Motion(c, j + 1, out double bx, out double by, out double bz);
            return nx * (c.ResidualX[j] + bx - ax) + ny * (c.ResidualY[j] + by - ay) + nz * (c.ResidualZ[j] + bz - az);
        }

        private static bool UpdateContacts(ChainState c)
        {
            bool changed = false;
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                double outward = FreeNormalMotion(c, i);
                if (c.ContactActive[i])
                {
                    if (outward > 0.0) { c.ContactActive[i] = false; changed = true; }
                }
                else if (-outward > c.ContactGap[i])
                {
                    c.ContactActive[i] = true;
                    changed = true;
                }
            }
            if (changed) DropContactsWithoutMobility(c);
            return changed;
        }

        /// <summary>Normal motion (m, &gt; 0 outward) contact particle i would make without its contact under this solution's pull.</summary>
        private static double FreeNormalMotion(ChainState c, int i)
        {
            SegmentForceSystem.Pull(c, i, out double px, out double py, out double pz);
            double w = c.InverseMass[i];
            return w * (c.ContactNX[i] * px + c.ContactNY[i] * py + c.ContactNZ[i] * pz);
        }

        /// <summary>
        /// Moves every particle by its mobility times this iteration's pull (recorded as its motion), accumulates the forces
        /// and writes the scalar multipliers λ_j = −Λ_j·n_j the tension read-outs use. A held contact may still close its
        /// gap; the normal motion it withheld is recorded as its normal load (the friction limit). Then the convergence test:
        /// returns the largest length error over the rest length of a pulling segment — its second-order error
        /// e = |Δ_⊥|²/(2l) from this iteration's relative motion Δ of its ends (see <see cref="NonlinearTolerance"/>), or a
        /// released (tension-only) segment's stretch beyond its rest length — and sets <paramref name="unconverged"/> when
        /// some active segment's error exceeds NonlinearTolerance·L, a released one is stretched by that much, or the energy
        /// the errors above round-off leave in the segments is too large (<see cref="Mismatched"/>).
        /// </summary>
        private static double Apply(ChainState c, bool contacts, bool tensionOnly, out bool unconverged)
        {
            int s = c.SegmentCount;
            float[] w = c.InverseMass;
            double[] error = c.LengthError;
            double qx = 0, qy = 0, qz = 0;
            for (int i = 0; i <= s; i++)
            {
                SegmentForceSystem.Pull(c, i, out double px, out double py, out double pz);
                double wi = w[i];
                double mx = wi * px, my = wi * py, mz = wi * pz;
                if (contacts && c.ContactActive[i])
                {
                    double nx = c.ContactNX[i], ny = c.ContactNY[i], nz = c.ContactNZ[i];
                    double normal = nx * mx + ny * my + nz * mz;
                    double allowed = normal < 0.0 ? Math.Max(normal, -c.ContactGap[i]) : 0.0;
                    double withheld = normal - allowed;
                    mx -= nx * withheld; my -= ny * withheld; mz -= nz * withheld;
                    if (normal < 0.0) c.ContactLoad[i] += (float)(-withheld);
                }
                c.DX[i] += (float)mx; c.DY[i] += (float)my; c.DZ[i] += (float)mz;
                c.MotionX[i] = mx; c.MotionY[i] = my; c.MotionZ[i] = mz;
                if (i > 0 && c.Active[i - 1])
                {
                    double ux = mx - qx, uy = my - qy, uz = mz - qz;
                    double along = ux * c.DirX[i - 1] + uy * c.DirY[i - 1] + uz * c.DirZ[i - 1];
                    double perp = ux * ux + uy * uy + uz * uz - along * along;
                    error[i - 1] = perp / (2.0 * Math.Max(c.Length[i - 1], 1e-6 * c.RestLength[i - 1]));
                }
                qx = mx; qy = my; qz = mz;
            }
            double[] fx = c.ForceX, fy = c.ForceY, fz = c.ForceZ, dx = c.StepX, dy = c.StepY, dz = c.StepZ;
            double floor = RoundOffFloor * c.Size, worst = 0.0;
            bool mismatched = false;
            unconverged = false;
            for (int j = 0; j < s; j++)
            {
                fx[j] += dx[j]; fy[j] += dy[j]; fz[j] += dz[j];
                double lambda = c.Active[j] ? -(fx[j] * c.DirX[j] + fy[j] * c.DirY[j] + fz[j] * c.DirZ[j]) : 0.0;
                c.Lambda[j] = lambda;
                double e;
                if (c.Active[j])
                {
                    e = error[j];
                    // a pushing (bilateral) segment's transverse response is damped buckling by design (see Assemble): it
                    // may add iterations, as before, but it is not a violent linearisation and keeps no energy test
                    if (lambda > 0.0)
                    {
                        if (e > NonlinearTolerance * c.RestLength[j]) unconverged = true;
                        continue;
                    }
                }
                else if (tensionOnly && c.Assembled[j])
                {
                    e = StretchBeyondRest(c, j);
                    error[j] = e;
                }
                else continue;
                if (e <= floor) continue;
                double rest = c.RestLength[j];
                if (e > worst * rest) worst = e / rest;
                if (e > NonlinearTolerance * rest) unconverged = true;
                else mismatched = true;
            }
            if (!unconverged && mismatched) unconverged = Mismatched(c, tensionOnly, floor);
            return worst;
        }

        /// <summary>How much longer (m) released segment j now is than its effective rest length (≤ 0: not stretched).</summary>
        private static double StretchBeyondRest(ChainState c, int j)
        {
            double dx = ((double)c.PrevX[j + 1] - c.PrevX[j]) + (((double)c.LowX[j + 1] - c.LowX[j]) + ((double)c.DX[j + 1] - c.DX[j]));
            double dy = ((double)c.PrevY[j + 1] - c.PrevY[j]) + (((double)c.LowY[j + 1] - c.LowY[j]) + ((double)c.DY[j + 1] - c.DY[j]));
            double dz = ((double)c.PrevZ[j + 1] - c.PrevZ[j]) + (((double)c.LowZ[j + 1] - c.LowZ[j]) + ((double)c.DZ[j + 1] - c.DZ[j]));
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
            for (int j = 0; j < c.SegmentCount; j++)
            {
                if (!c.Assembled[j]) continue;
                double alpha = c.AxialCompliance[j], squared = c.ForceX[j] * c.ForceX[j] + c.ForceY[j] * c.ForceY[j] + c.ForceZ[j] * c.ForceZ[j];
                if (c.Active[j]) reference += 0.5 * alpha * squared;
                bool counted = c.Active[j] ? c.Lambda[j] <= 0.0 : tensionOnly;
                double e = c.LengthError[j];
                if (!counted || e <= floor || alpha == 0.0) continue;
                mismatch += (c.Active[j] ? Math.Sqrt(squared) * e : 0.0) + 0.5 * e * e / alpha;
            }
            for (int i = 0; i < c.ParticleCount; i++)
            {
                double w = c.InverseMass[i];
                if (w > 0.0) reference += 0.5 * ((double)c.DX[i] * c.DX[i] + (double)c.DY[i] * c.DY[i] + (double)c.DZ[i] * c.DZ[i]) / w;
            }
            return mismatch > EnergyTolerance * reference;
        }

        /// <summary>See <see cref="Iterate"/>: the estimated tension was below half the result where 4·T·h²·max(w)/l &gt; 1.</summary>
        private static bool EstimateTooLow(ChainState c, double invH2)
        {
            int s = c.SegmentCount;
            for (int j = 0; j < s; j++)
            {
                if (!c.Active[j]) continue;
                double found = -c.Lambda[j] * invH2;
                if (!(found > 2.0 * c.EstimatedTension[j])) continue;
                double w = Math.Max(c.InverseMass[j], c.InverseMass[j + 1]);
                if (4.0 * found * w > invH2 * Math.Max(c.Length[j], 1e-6 * c.RestLength[j])) return true;
            }
            return false;
        }
    }
}
