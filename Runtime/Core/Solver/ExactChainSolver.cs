using System;
using System.Runtime.CompilerServices;

namespace HookeRope.Solver
{
    /// <summary>
    /// One exact iteration of the whole chain: solves (J W Jᵀ + α̃) Δλ = −C − α̃ λ (with XPBD damping,
    /// Macklin 2016 eq. 26) for every segment at once. For a chain the matrix is tridiagonal, so the
    /// Thomas algorithm solves it in O(n) in double precision. Tension-only segments are handled by
    /// active-set passes on the same linearisation: solve with every segment active, release the
    /// segments whose accumulated λ would end on the pushing side, re-admit released segments that the
    /// new solution stretches, and repeat until nothing changes (at most <see cref="MaxPasses"/>).
    /// </summary>
    internal static class ExactChainSolver
    {
        /// <summary>Largest number of active-set passes per iteration.</summary>
        public const int MaxPasses = 8;

        /// <summary>
        /// Runs one iteration. Returns true when the linearisation was poor somewhere (a fold: neighbouring
        /// segments at more than 90°, a slack (compressed) segment, or a changed active set), so that a nonlinear
        /// Gauss–Seidel sweep should follow.
        /// </summary>
        public static bool Iterate(ChainState c, double h, double beta, bool tensionOnly)
        {
            double invH2 = 1.0 / (h * h);
            double gammaAll = beta / h; // γ = α̃·β̃/h with β̃ = h²·β·k, k = 1/α
            bool contacts = c.ContactCount > 0;
            bool augmented = c.AugmentedCount > 0;
            bool poor = Assemble(c, invH2, gammaAll);
            if (contacts) AssembleContacts(c, invH2, gammaAll);
            int passes = SolveActiveSet(c, tensionOnly, contacts, invH2, gammaAll, out bool activeSetChanged);
            Apply(c, tensionOnly, contacts, augmented);
            // a changed contact set alone does not call for the sweep (it would use the plain masses)
            return poor || (contacts || augmented ? activeSetChanged : passes > 1);
        }

        /// <summary>
        /// Linearises every segment along its current direction and writes the tridiagonal system (Full*) with the plain
        /// or the transversely stabilised masses, without contacts. Returns true when the linearisation is poor somewhere
        /// (a slack segment, or neighbouring segments at more than 90°).
        /// </summary>
        private static bool Assemble(ChainState c, double invH2, double gammaAll)
        {
            int s = c.SegmentCount;
            float[] w = c.InverseMass, rest = c.RestLength, compliance = c.Compliance, length = c.Length;
            double[] fd = c.FullDiagonal, fl = c.FullLower, fu = c.FullUpper, fr = c.FullRhs;
            double[] lambda = c.Lambda;
            bool[] active = c.Active, broken = c.Broken;
            bool augmented = c.AugmentedCount > 0;
            bool poor = false;
            float pnx = 0f, pny = 0f, pnz = 0f;
            double previousScale = 0.0;
            // transverse stabilisation (no contact): particle j's mobility w_t, w − w_t, tangent t, and t·n_{j−1}
            var left = augmented ? TransverseMobility.Of(c, 0) : default;
            double leftAlongPrevious = 0.0;

            for (int j = 0; j < s; j++)
            {
                if (broken[j])
                {
                    fd[j] = 0.0; fr[j] = 0.0; fl[j] = 0.0; fu[j] = 0.0; active[j] = false;
                    if (j > 0) fu[j - 1] = 0.0;
                    if (augmented) left = TransverseMobility.Of(c, j + 1); // the chain restarts at particle j + 1
                    continue;
                }
                float len = c.Direction(j, out float nx, out float ny, out float nz, out float ddx, out float ddy, out float ddz);
                length[j] = len;
                double alpha = compliance[j];
                double alphaTilde = alpha * invH2;
                double g = alpha > 0.0 ? gammaAll : 0.0;
                double rel = g > 0.0 ? nx * ddx + ny * ddy + nz * ddz : 0.0;
                double constraint = (double)len - rest[j];
                float wa = w[j], wb = w[j + 1];
                double diagonal;
                TransverseMobility right = default;
                double leftAlong = 0.0, rightAlong = 0.0; // t_j·n_j, t_{j+1}·n_j
                if (augmented)
                {
                    // n_jᵀ W_i n_j = w_t (n_j·n_j) + (w − w_t)(t_i·n_j)² for particles i = j, j + 1
                    right = TransverseMobility.Of(c, j + 1);
                    leftAlong = left.Along(nx, ny, nz);
                    rightAlong = right.Along(nx, ny, nz);
                    double nn = (double)nx * nx + (double)ny * ny + (double)nz * nz;
                    diagonal = (1.0 + g) * (left.Quadratic(leftAlong, leftAlong, nn) + right.Quadratic(rightAlong, rightAlong, nn)) + alphaTilde;
                }
                else
                {
                    diagonal = (1.0 + g) * ((double)wa + wb) + alphaTilde;
                }
                fr[j] = -constraint - alphaTilde * lambda[j] - g * rel;
                fd[j] = diagonal;
                bool valid = diagonal > 0.0;
                active[j] = valid;
                if (len < rest[j]) poor = true;
                double scale = 1.0 + g;
                if (valid && j > 0 && active[j - 1])
                {
                    double cos = (double)pnx * nx + (double)pny * ny + (double)pnz * nz;
                    if (cos < 0.0) poor = true;
                    if (augmented)
                    {
                        // n_{j−1}ᵀ W_j n_j = w_t (n_{j−1}·n_j) + (w − w_t)(t·n_{j−1})(t·n_j)
                        double coupling = left.Quadratic(leftAlongPrevious, leftAlong, cos);
                        fl[j] = -scale * coupling;
                        fu[j - 1] = -previousScale * coupling;
                    }
                    else
                    {
                        fl[j] = -scale * wa * cos;
                        fu[j - 1] = -previousScale * wa * cos;
                    }
                }
                else
                {
                    fl[j] = 0.0;
                    if (j > 0) fu[j - 1] = 0.0;
                }
                fu[j] = 0.0;
                pnx = nx; pny = ny; pnz = nz;
                previousScale = scale;
                if (augmented)
                {
                    left = right;
                    leftAlongPrevious = rightAlong;
                }
            }
            return poor;
        }

        /// <summary>Held contacts: the general constrained mobility on the rows around each contact particle.</summary>
        private static void AssembleContacts(ChainState c, double invH2, double gammaAll)
        {
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                if (c.ContactActive[i]) RebuildAround(c, i, invH2, gammaAll);
            }
        }

        /// <summary>
        /// Solves the assembled system into Delta, then repeats on the same linearisation while the active set changes
        /// (tension-only segments released or re-admitted, contacts released or held), at most <see cref="MaxPasses"/>
        /// times. Returns the number of passes; activeSetChanged: some segment changed sides.
        /// </summary>
        private static int SolveActiveSet(ChainState c, bool tensionOnly, bool contacts, double invH2, double gammaAll, out bool activeSetChanged)
        {
            int s = c.SegmentCount;
            double[] fd = c.FullDiagonal, fl = c.FullLower, fu = c.FullUpper, fr = c.FullRhs;
            double[] lambda = c.Lambda, delta = c.Delta;
            bool[] active = c.Active;
            int passes = 0;
            activeSetChanged = false;
            while (true)
            {
                passes++;
                Solve(c, tensionOnly);
                if ((!tensionOnly && !contacts) || passes >= MaxPasses) break;
                bool changed = contacts && UpdateContacts(c, tensionOnly, invH2, gammaAll);
                if (!tensionOnly)
                {
                    if (!changed) break;
                    continue;
                }
                for (int j = 0; j < s; j++)
                {
                    if (fd[j] <= 0.0) continue;
                    if (active[j])
                    {
                        if (lambda[j] + delta[j] > 0.0) { active[j] = false; changed = true; activeSetChanged = true; }
                    }
                    else
                    {
                        double residual = fr[j] - fd[j] * delta[j]
                            - (j > 0 ? fl[j] * delta[j - 1] : 0.0)
                            - (j + 1 < s ? fu[j] * delta[j + 1] : 0.0);
                        if (residual < 0.0) { active[j] = true; changed = true; activeSetChanged = true; }
                    }
                }
                if (!changed) break;
            }
            return passes;
        }

        /// <summary>Applies the solved multiplier changes to the multipliers and the particle displacements.</summary>
        private static void Apply(ChainState c, bool tensionOnly, bool contacts, bool augmented)
        {
            if (augmented) ApplyTransverse(c, tensionOnly, contacts);
            else ApplyIsotropic(c, tensionOnly, keepDelta: contacts);
            if (contacts) ApplyContactMobility(c);
        }

        /// <summary>
        /// Applies the multiplier changes in Delta (tension-only: clamped so λ ≤ 0) with isotropic masses: particle j moves
        /// by −w_j n_j Δλ_j, particle j + 1 by +w_{j+1} n_j Δλ_j (m). keepDelta: Delta keeps the applied changes.
        /// </summary>
        private static void ApplyIsotropic(ChainState c, bool tensionOnly, bool keepDelta)
        {
            int s = c.SegmentCount;
            float[] w = c.InverseMass, dx = c.DX, dy = c.DY, dz = c.DZ, nxs = c.DirX, nys = c.DirY, nzs = c.DirZ;
            double[] delta = c.Delta, lambda = c.Lambda;
            float wLeft = w[0];
            for (int j = 0; j < s; j++)
            {
                float wRight = w[j + 1];
                double d = delta[j];
                d = ChainState.LimitToPulling(lambda[j], d, tensionOnly);
                if (d != 0.0)
                {
                    lambda[j] += d;
                    float nx = nxs[j], ny = nys[j], nz = nzs[j];
                    float a = (float)(wLeft * d), b = (float)(wRight * d);
                    dx[j] -= nx * a; dy[j] -= ny * a; dz[j] -= nz * a;
                    dx[j + 1] += nx * b; dy[j + 1] += ny * b; dz[j + 1] += nz * b;
                }
                if (keepDelta) delta[j] = d;
                wLeft = wRight;
            }
        }

        /// <summary>
        /// Applies the multiplier changes in Delta (clamped as in <see cref="ApplyIsotropic"/>) with the transverse
        /// stabilisation, one particle at a time: particle i feels the chain pull f = n_{i−1}Δλ_{i−1} − n_iΔλ_i (N·s²)
        /// and moves by W_i f = w_t f + (w − w_t)(t·f) t (m). A particle with a held contact moves by w f here;
        /// <see cref="ApplyContactMobility"/> corrects it afterwards. Delta keeps the applied changes.
        /// </summary>
        private static void ApplyTransverse(ChainState c, bool tensionOnly, bool contacts)
        {
            int s = c.SegmentCount;
            float[] nxs = c.DirX, nys = c.DirY, nzs = c.DirZ;
            double[] delta = c.Delta, lambda = c.Lambda;
            double px = 0.0, py = 0.0, pz = 0.0; // n_{j−1}Δλ_{j−1}: the pull of the segment before particle j
            for (int j = 0; j < s; j++)
            {
                double d = delta[j];
                d = ChainState.LimitToPulling(lambda[j], d, tensionOnly);
                lambda[j] += d;
                delta[j] = d;
                double qx = nxs[j] * d, qy = nys[j] * d, qz = nzs[j] * d;
                MoveParticle(c, j, px - qx, py - qy, pz - qz, contacts);
                px = qx; py = qy; pz = qz;
            }
            MoveParticle(c, s, px, py, pz, contacts);
        }

        /// <summary>Moves particle i by W_i f (m) for the chain pull f (N·s²), without its contact (see <see cref="ApplyTransverse"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void MoveParticle(ChainState c, int i, double fx, double fy, double fz, bool contacts)
        {
            double rx, ry, rz;
            if (contacts && c.ContactActive[i])
            {
                double w = c.InverseMass[i];
                rx = w * fx; ry = w * fy; rz = w * fz;
            }
            else
            {
                TransverseMobility.Of(c, i).Apply(fx, fy, fz, out rx, out ry, out rz);
            }
            c.DX[i] += (float)rx; c.DY[i] += (float)ry; c.DZ[i] += (float)rz;
        }

        /// <summary>Solves the system of the current active set into Delta (Thomas algorithm; released rows are Δλ = −λ).</summary>
        private static void Solve(ChainState c, bool tensionOnly)
        {
            int s = c.SegmentCount;
            double[] cp = c.Upper, dp = c.Rhs, x = c.Delta, lambda = c.Lambda;
            double[] fd = c.FullDiagonal, fl = c.FullLower, fu = c.FullUpper, fr = c.FullRhs;
            bool[] active = c.Active;
            // forward sweep: cp = c', dp = d'
            double previousC = 0.0, previousD = 0.0;
            for (int j = 0; j < s; j++)
            {
                double lo, di, up, rhs;
                if (active[j])
                {
                    lo = fl[j]; di = fd[j]; up = fu[j]; rhs = fr[j];
                }
                else
                {
                    // released (or broken) row: its λ returns to zero this iteration, Δλ = −λ
                    lo = 0.0; di = 1.0; up = 0.0;
                    rhs = fd[j] > 0.0 && tensionOnly ? -lambda[j] : 0.0;
                }
                double m = di - lo * previousC;
                previousC = up / m;
                previousD = (rhs - lo * previousD) / m;
                cp[j] = previousC;
                dp[j] = previousD;
            }
            double next = dp[s - 1];
            x[s - 1] = next;
            for (int j = s - 2; j >= 0; j--)
            {
                next = dp[j] - cp[j] * next;
                x[j] = next;
            }
        }

        /// <summary>
        /// r = W_i v: the particle's mobility (inverse mass, 1/kg) applied to v. W = w I, or w t tᵀ + w_t (I − t tᵀ) with the
        /// transverse stabilisation (<see cref="ChainState.UpdateTransverseMass"/>); with an active contact (normal c) and
        /// withContact, the constrained mobility W − (W c)(W c)ᵀ/(cᵀ W c), which is w(I − c cᵀ) for an isotropic particle.
        /// </summary>
        private static void Mobility(ChainState c, int i, double vx, double vy, double vz, bool withContact, out double rx, out double ry, out double rz)
        {
            var free = TransverseMobility.Of(c, i);
            free.Apply(vx, vy, vz, out rx, out ry, out rz);
            if (!withContact || c.ContactCollider == null || !c.ContactActive[i]) return;
            double cx = c.ContactNX[i], cy = c.ContactNY[i], cz = c.ContactNZ[i];
            free.Apply(cx, cy, cz, out double ux, out double uy, out double uz);
            double cwc = cx * ux + cy * uy + cz * uz;
            if (!(cwc > 0.0)) return;
            double k = (ux * vx + uy * vy + uz * vz) / cwc;
            rx -= ux * k; ry -= uy * k; rz -= uz * k;
        }

        /// <summary>n_aᵀ W_i n_b for unit directions a, b (1/kg).</summary>
        private static double Quadratic(ChainState c, int i, float ax, float ay, float az, float bx, float by, float bz)
        {
            Mobility(c, i, bx, by, bz, withContact: true, out double rx, out double ry, out double rz);
            return ax * rx + ay * ry + az * rz;
        }

        /// <summary>
        /// Rewrites the matrix entries that depend on particle i's inverse mass: the diagonals of segments i − 1 and i
        /// and their coupling through i, n_{i−1}ᵀ W_i n_i. A contact that would leave a segment with no mobility is dropped.
        /// </summary>
        private static void RebuildAround(ChainState c, int i, double invH2, double gammaAll)
        {
            int s = c.SegmentCount;
            double[] fd = c.FullDiagonal, fl = c.FullLower, fu = c.FullUpper;
            double left = 0.0, right = 0.0;
            for (int attempt = 0; attempt < 2; attempt++)
            {
                left = Diagonal(c, i - 1, invH2, gammaAll);
                right = Diagonal(c, i, invH2, gammaAll);
                if ((left < 0.0 || right < 0.0) && c.ContactCollider != null && c.ContactActive[i])
                {
                    c.ContactActive[i] = false; // the contact would leave a segment with no mobility
                    continue;
                }
                break;
            }
            if (left > 0.0) fd[i - 1] = left;
            if (right > 0.0) fd[i] = right;
            if (i <= 0 || i >= s || c.Broken[i - 1] || c.Broken[i] || !(fd[i - 1] > 0.0) || !(fd[i] > 0.0)) return;
            double coupling = Quadratic(c, i, c.DirX[i - 1], c.DirY[i - 1], c.DirZ[i - 1], c.DirX[i], c.DirY[i], c.DirZ[i]);
            double gLower = c.Compliance[i] > 0f ? gammaAll : 0.0, gUpper = c.Compliance[i - 1] > 0f ? gammaAll : 0.0;
            fl[i] = -(1.0 + gLower) * coupling;
            fu[i - 1] = -(1.0 + gUpper) * coupling;
        }

        /// <summary>
        /// Diagonal (1 + γ)(n_jᵀW_j n_j + n_jᵀW_{j+1}n_j) + α̃_j of segment j with the current contacts; 0 when the row is not
        /// in the system (out of range, broken, or invalid from the start), −1 when the contacts leave it no mobility.
        /// </summary>
        private static double Diagonal(ChainState c, int j, double invH2, double gammaAll)
        {
            if (j < 0 || j >= c.SegmentCount || c.Broken[j] || !(c.FullDiagonal[j] > 0.0)) return 0.0;
            double alpha = c.Compliance[j];
            double g = alpha > 0.0 ? gammaAll : 0.0;
            float nx = c.DirX[j], ny = c.DirY[j], nz = c.DirZ[j];
            double masses = Quadratic(c, j, nx, ny, nz, nx, ny, nz) + Quadratic(c, j + 1, nx, ny, nz, nx, ny, nz);
            double diagonal = (1.0 + g) * masses + alpha * invH2;
            double full = (1.0 + g) * ((double)c.InverseMass[j] + c.InverseMass[j + 1]) + alpha * invH2;
            return diagonal > 1e-9 * full ? diagonal : -1.0;
        }

        /// <summary>
        /// The chain's pull f = n_{i−1}Δλ_{i−1} − n_iΔλ_i on particle i (N·s²) for the multiplier changes in Delta; the
        /// particle moves by W_i f. clamp: tension-only changes as the position update will apply them.
        /// </summary>
        private static void ChainPull(ChainState c, int i, bool tensionOnly, bool clamp, out double fx, out double fy, out double fz)
        {
            int s = c.SegmentCount;
            double[] delta = c.Delta, lambda = c.Lambda;
            fx = 0.0; fy = 0.0; fz = 0.0;
            if (i > 0 && !c.Broken[i - 1])
            {
                double d = delta[i - 1];
                d = ChainState.LimitToPulling(lambda[i - 1], d, clamp && tensionOnly);
                fx += d * c.DirX[i - 1]; fy += d * c.DirY[i - 1]; fz += d * c.DirZ[i - 1];
            }
            if (i < s && !c.Broken[i])
            {
                double d = delta[i];
                d = ChainState.LimitToPulling(lambda[i], d, clamp && tensionOnly);
                fx -= d * c.DirX[i]; fy -= d * c.DirY[i]; fz -= d * c.DirZ[i];
            }
        }

        /// <summary>Normal motion (m, &gt; 0 outward) contact particle i would make without its contact, for the current Delta.</summary>
        private static double FreeNormalMotion(ChainState c, int i, bool tensionOnly, bool clamp)
        {
            ChainPull(c, i, tensionOnly, clamp, out double fx, out double fy, out double fz);
            Mobility(c, i, fx, fy, fz, withContact: false, out double rx, out double ry, out double rz);
            return c.ContactNX[i] * rx + c.ContactNY[i] * ry + c.ContactNZ[i] * rz;
        }

        /// <summary>
        /// Contact complementarity on the current solution: a held contact whose chain pull would lift the particle off the
        /// surface is released; a released one that the chain would drive deeper than its gap is held again.
        /// Rebuilds the affected matrix rows; returns true when the contact set changed.
        /// </summary>
        private static bool UpdateContacts(ChainState c, bool tensionOnly, double invH2, double gammaAll)
        {
            bool changed = false;
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                double outward = FreeNormalMotion(c, i, tensionOnly, clamp: true);
                if (c.ContactActive[i])
                {
                    if (outward > 0.0)
                    {
                        c.ContactActive[i] = false;
                        RebuildAround(c, i, invH2, gammaAll);
                        changed = true;
                    }
                }
                else if (-outward > c.ContactGap[i])
                {
                    c.ContactActive[i] = true;
                    RebuildAround(c, i, invH2, gammaAll);
                    changed |= c.ContactActive[i];
                }
            }
            return changed;
        }

        /// <summary>
        /// Replaces the plain update w·f of the particles with a held contact by W_i f (the constrained mobility, with the
        /// transverse stabilisation where the particle has it). A held contact may still close its gap; the normal motion
        /// it withheld is recorded as its normal load (friction limit). Delta holds the applied multiplier changes.
        /// </summary>
        private static void ApplyContactMobility(ChainState c)
        {
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                if (!c.ContactActive[i]) continue;
                ChainPull(c, i, tensionOnly: false, clamp: false, out double fx, out double fy, out double fz);
                Mobility(c, i, fx, fy, fz, withContact: true, out double rx, out double ry, out double rz);
                Mobility(c, i, fx, fy, fz, withContact: false, out double ux, out double uy, out double uz);
                double inward = -(c.ContactNX[i] * ux + c.ContactNY[i] * uy + c.ContactNZ[i] * uz);
                if (inward > 0.0)
                {
                    double allowed = Math.Min(inward, c.ContactGap[i]);
                    rx -= c.ContactNX[i] * allowed; ry -= c.ContactNY[i] * allowed; rz -= c.ContactNZ[i] * allowed;
                    c.ContactLoad[i] += (float)(inward - allowed);
                }
                double w = c.InverseMass[i];
                c.DX[i] += (float)(rx - w * fx); c.DY[i] += (float)(ry - w * fy); c.DZ[i] += (float)(rz - w * fz);
            }
        }
    }
}
