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

            double[] delta = c.Delta;
            int passes = 0;
            while (true)
            {
                passes++;
                Solve(c, tensionOnly);
                if (!tensionOnly || passes >= MaxPasses) break;
                bool changed = false;
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
                wLeft = wRight;
            }
            return poor || passes > 1;
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
