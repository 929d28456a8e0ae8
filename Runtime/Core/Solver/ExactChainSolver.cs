using System;

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
            int s = c.SegmentCount;
            double invH2 = 1.0 / (h * h);
            double gammaAll = beta / h; // γ = α̃·β̃/h with β̃ = h²·β·k, k = 1/α
            float[] w = c.InverseMass, rest = c.RestLength, compliance = c.Compliance, length = c.Length;
            float[] px = c.PrevX, py = c.PrevY, pz = c.PrevZ, dx = c.DX, dy = c.DY, dz = c.DZ;
            float[] nxs = c.DirX, nys = c.DirY, nzs = c.DirZ;
            double[] fd = c.FullDiagonal, fl = c.FullLower, fu = c.FullUpper, fr = c.FullRhs;
            double[] lambda = c.Lambda;
            bool[] active = c.Active, broken = c.Broken;
            bool poor = false;
            float pnx = 0f, pny = 0f, pnz = 0f;
            double previousScale = 0.0;

            for (int j = 0; j < s; j++)
            {
                if (broken[j])
                {
                    fd[j] = 0.0; fr[j] = 0.0; fl[j] = 0.0; fu[j] = 0.0; active[j] = false;
                    if (j > 0) fu[j - 1] = 0.0;
                    continue;
                }
                float ddx = dx[j + 1] - dx[j], ddy = dy[j + 1] - dy[j], ddz = dz[j + 1] - dz[j];
                float ex = (px[j + 1] - px[j]) + ddx, ey = (py[j + 1] - py[j]) + ddy, ez = (pz[j + 1] - pz[j]) + ddz;
                float len = MathF.Sqrt(ex * ex + ey * ey + ez * ez);
                float nx, ny, nz;
                if (len > 1e-12f && len <= float.MaxValue)
                {
                    float inv = 1f / len;
                    nx = ex * inv; ny = ey * inv; nz = ez * inv;
                    nxs[j] = nx; nys[j] = ny; nzs[j] = nz;
                }
                else
                {
                    nx = nxs[j]; ny = nys[j]; nz = nzs[j];
                    if (!(len <= float.MaxValue)) len = 0f;
                }
                length[j] = len;
                double alpha = compliance[j];
                double alphaTilde = alpha * invH2;
                double g = alpha > 0.0 ? gammaAll : 0.0;
                double rel = g > 0.0 ? nx * ddx + ny * ddy + nz * ddz : 0.0;
                double constraint = (double)len - rest[j];
                float wa = w[j], wb = w[j + 1];
                double diagonal = (1.0 + g) * ((double)wa + wb) + alphaTilde;
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
                    fl[j] = -scale * wa * cos;
                    fu[j - 1] = -previousScale * wa * cos;
                }
                else
                {
                    fl[j] = 0.0;
                    if (j > 0) fu[j - 1] = 0.0;
                }
                fu[j] = 0.0;
                pnx = nx; pny = ny; pnz = nz;
                previousScale = scale;
            }

            bool contacts = c.ContactCount > 0;
            if (contacts)
            {
                for (int k = 0; k < c.ContactCount; k++)
                {
                    int i = c.ContactList[k];
                    if (c.ContactActive[i]) RebuildAround(c, i, invH2, gammaAll);
                }
            }

            double[] delta = c.Delta;
            int passes = 0;
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
                        if (lambda[j] + delta[j] > 0.0) { active[j] = false; changed = true; }
                    }
                    else
                    {
                        double residual = fr[j] - fd[j] * delta[j]
                            - (j > 0 ? fl[j] * delta[j - 1] : 0.0)
                            - (j + 1 < s ? fu[j] * delta[j + 1] : 0.0);
                        if (residual < 0.0) { active[j] = true; changed = true; }
                    }
                }
                if (!changed) break;
            }

            float wLeft = w[0];
            for (int j = 0; j < s; j++)
            {
                float wRight = w[j + 1];
                double d = delta[j];
                if (tensionOnly && lambda[j] + d > 0.0) d = -lambda[j];
                if (d != 0.0)
                {
                    lambda[j] += d;
                    float nx = nxs[j], ny = nys[j], nz = nzs[j];
                    float a = (float)(wLeft * d), b = (float)(wRight * d);
                    dx[j] -= nx * a; dy[j] -= ny * a; dz[j] -= nz * a;
                    dx[j + 1] += nx * b; dy[j + 1] += ny * b; dz[j + 1] += nz * b;
                }
                if (contacts) delta[j] = d;
                wLeft = wRight;
            }
            if (contacts) HoldContacts(c);
            return poor || passes > 1;
        }

        /// <summary>
        /// Effective inverse mass (1/kg) of particle i along unit direction n: w, or w(1 − (c·n)²) while the particle is in
        /// an active contact with normal c (tangent-plane inverse mass W = w(I − c cᵀ)).
        /// </summary>
        private static double EffectiveInverseMass(ChainState c, int i, float nx, float ny, float nz)
        {
            double w = c.InverseMass[i];
            if (!c.ContactActive[i]) return w;
            double cn = (double)c.ContactNX[i] * nx + (double)c.ContactNY[i] * ny + (double)c.ContactNZ[i] * nz;
            return w * (1.0 - cn * cn);
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
                if ((left < 0.0 || right < 0.0) && c.ContactActive[i])
                {
                    c.ContactActive[i] = false; // the contact would leave a segment with no mobility
                    continue;
                }
                break;
            }
            if (left > 0.0) fd[i - 1] = left;
            if (right > 0.0) fd[i] = right;
            if (i <= 0 || i >= s || c.Broken[i - 1] || c.Broken[i] || !(fd[i - 1] > 0.0) || !(fd[i] > 0.0)) return;
            double coupling;
            float ax = c.DirX[i - 1], ay = c.DirY[i - 1], az = c.DirZ[i - 1], bx = c.DirX[i], by = c.DirY[i], bz = c.DirZ[i];
            double cos = (double)ax * bx + (double)ay * by + (double)az * bz;
            double w = c.InverseMass[i];
            if (c.ContactActive[i])
            {
                double ca = (double)c.ContactNX[i] * ax + (double)c.ContactNY[i] * ay + (double)c.ContactNZ[i] * az;
                double cb = (double)c.ContactNX[i] * bx + (double)c.ContactNY[i] * by + (double)c.ContactNZ[i] * bz;
                coupling = w * (cos - ca * cb);
            }
            else
            {
                coupling = w * cos;
            }
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
            double masses = EffectiveInverseMass(c, j, nx, ny, nz) + EffectiveInverseMass(c, j + 1, nx, ny, nz);
            double diagonal = (1.0 + g) * masses + alpha * invH2;
            double full = (1.0 + g) * ((double)c.InverseMass[j] + c.InverseMass[j + 1]) + alpha * invH2;
            return diagonal > 1e-9 * full ? diagonal : -1.0;
        }

        /// <summary>
        /// Normal component c·f of the chain's pull on contact particle i for the multiplier changes in Delta
        /// (f = n_{i−1}Δλ_{i−1} − n_iΔλ_i, N·s²; the particle would move by w·f). Negative = into the surface.
        /// </summary>
        private static double NormalPull(ChainState c, int i, bool tensionOnly, bool clamp)
        {
            int s = c.SegmentCount;
            double[] delta = c.Delta, lambda = c.Lambda;
            double f = 0.0;
            if (i > 0 && !c.Broken[i - 1])
            {
                double d = delta[i - 1];
                if (clamp && tensionOnly && lambda[i - 1] + d > 0.0) d = -lambda[i - 1];
                f += d * ((double)c.ContactNX[i] * c.DirX[i - 1] + (double)c.ContactNY[i] * c.DirY[i - 1] + (double)c.ContactNZ[i] * c.DirZ[i - 1]);
            }
            if (i < s && !c.Broken[i])
            {
                double d = delta[i];
                if (clamp && tensionOnly && lambda[i] + d > 0.0) d = -lambda[i];
                f -= d * ((double)c.ContactNX[i] * c.DirX[i] + (double)c.ContactNY[i] * c.DirY[i] + (double)c.ContactNZ[i] * c.DirZ[i]);
            }
            return f;
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
                double pull = NormalPull(c, i, tensionOnly, true);
                if (c.ContactActive[i])
                {
                    if (pull > 0.0)
                    {
                        c.ContactActive[i] = false;
                        RebuildAround(c, i, invH2, gammaAll);
                        changed = true;
                    }
                }
                else if (-c.InverseMass[i] * pull > c.ContactGap[i])
                {
                    c.ContactActive[i] = true;
                    RebuildAround(c, i, invH2, gammaAll);
                    changed |= c.ContactActive[i];
                }
            }
            return changed;
        }

        /// <summary>
        /// Applies the tangent-plane inverse mass to the held contacts after the plain position update: removes the
        /// normal part of the chain's push into the surface beyond the contact's gap and records it as the contact's
        /// normal load (friction limit). Delta holds the applied multiplier changes.
        /// </summary>
        private static void HoldContacts(ChainState c)
        {
            for (int k = 0; k < c.ContactCount; k++)
            {
                int i = c.ContactList[k];
                if (!c.ContactActive[i]) continue;
                double inward = -c.InverseMass[i] * NormalPull(c, i, false, false);
                double held = inward - c.ContactGap[i];
                if (!(held > 0.0)) continue;
                float push = (float)held;
                c.DX[i] += c.ContactNX[i] * push; c.DY[i] += c.ContactNY[i] * push; c.DZ[i] += c.ContactNZ[i] * push;
                c.ContactLoad[i] += push;
            }
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
    }
}
