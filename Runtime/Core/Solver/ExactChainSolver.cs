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
        /// by about |Δ_⊥|²/(2l).
        /// </summary>
        public const double NonlinearTolerance = 1e-3;

        /// <summary>
        /// Runs one iteration (h: the integrator's effective substep, s; beta: damping β, s; first: the substep's first
        /// iteration, whose accumulated forces start at zero). Returns true when another iteration should follow: the
        /// tension the geometric stiffness was estimated with was less than half the tension found on some segment whose
        /// transverse response it governs (4·T·h²·w/l &gt; 1), or the iteration moved some segment's ends across it by so
        /// much that its linearisation is off by more than <see cref="NonlinearTolerance"/> of the rest length.
        /// </summary>
        public static bool Iterate(ChainState c, double h, double beta, bool tensionOnly, bool first)
        {
            double invH2 = 1.0 / (h * h);
            if (first) ClearForces(c);
            Assemble(c, invH2, beta / h, first);
            bool contacts = c.ContactCount > 0;
            if (contacts) DropContactsWithoutMobility(c);
            SolveActiveSet(c, tensionOnly, contacts);
            double nonlinear = Apply(c, contacts);
            bool branches = c.Plasticity != null && c.Plasticity.UpdateBranches(c, invH2);
            return EstimateTooLow(c, invH2) || nonlinear > NonlinearTolerance || branches;
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
            bool[] broken = c.Broken, active = c.Active;
            SegmentPlasticity plastic = c.Plasticity;
            for (int j = 0; j < s; j++)
            {
                if (broken[j]) { active[j] = false; continue; }
                double len = c.Direction(j, out double nx, out double ny, out double nz, out double ddx, out double ddy, out double ddz);
                length[j] = (float)len;
                double alpha = compliance[j];
                double mobility = (double)w[j] + w[j + 1];
                if (mobility == 0.0 && alpha == 0.0) { active[j] = false; continue; }
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
        /// Moves every particle by its mobility times this iteration's pull, accumulates the forces and writes the scalar
        /// multipliers λ_j = −Λ_j·n_j the tension read-outs use. A held contact may still close its gap; the normal motion
        /// it withheld is recorded as its normal load (the friction limit). Returns the largest second-order length error
        /// |Δ_⊥|²/(2l) of a segment over its rest length (see <see cref="NonlinearTolerance"/>).
        /// </summary>
        private static double Apply(ChainState c, bool contacts)
        {
            int s = c.SegmentCount;
            float[] w = c.InverseMass;
            double worst = 0.0, qx = 0, qy = 0, qz = 0;
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
                c.AddDisplacement(i, mx, my, mz);
                if (i > 0 && c.Active[i - 1])
                {
                    double ux = mx - qx, uy = my - qy, uz = mz - qz;
                    double along = ux * c.DirX[i - 1] + uy * c.DirY[i - 1] + uz * c.DirZ[i - 1];
                    double perp = ux * ux + uy * uy + uz * uz - along * along;
                    double e = perp / (2.0 * Math.Max(c.Length[i - 1], 1e-6 * c.RestLength[i - 1]) * c.RestLength[i - 1]);
                    if (e > worst) worst = e;
                }
                qx = mx; qy = my; qz = mz;
            }
            double[] fx = c.ForceX, fy = c.ForceY, fz = c.ForceZ, dx = c.StepX, dy = c.StepY, dz = c.StepZ;
            for (int j = 0; j < s; j++)
            {
                fx[j] += dx[j]; fy[j] += dy[j]; fz[j] += dz[j];
                c.Lambda[j] = c.Active[j] ? -(fx[j] * c.DirX[j] + fy[j] * c.DirY[j] + fz[j] * c.DirZ[j]) : 0.0;
            }
            return worst;
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
