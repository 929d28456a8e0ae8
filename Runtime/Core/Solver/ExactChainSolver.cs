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

        /// <summary>Runs one iteration; returns the number of active-set passes used.</summary>
        public static int Iterate(ChainState c, double h, double beta, bool tensionOnly)
        {
            int s = c.SegmentCount;
            double invH2 = 1.0 / (h * h);
            float[] w = c.InverseMass;
            double[] fd = c.FullDiagonal, fl = c.FullLower, fu = c.FullUpper, fr = c.FullRhs, gamma = c.Scratch;
            double[] lambda = c.Lambda;
            bool[] active = c.Active;

            for (int j = 0; j < s; j++)
            {
                if (c.Broken[j])
                {
                    fd[j] = 0.0; fr[j] = 0.0; gamma[j] = 0.0; active[j] = false;
                    continue;
                }
                float len = c.Direction(j, out float nx, out float ny, out float nz);
                c.Length[j] = len;
                double alpha = c.Compliance[j];
                double alphaTilde = alpha * invH2;
                double g = alpha * beta / h;
                double rel = 0.0;
                if (g > 0.0)
                {
                    rel = nx * (c.DX[j + 1] - c.DX[j]) + ny * (c.DY[j + 1] - c.DY[j]) + nz * (c.DZ[j + 1] - c.DZ[j]);
                }
                double constraint = (double)len - c.RestLength[j];
                fr[j] = -constraint - alphaTilde * lambda[j] - g * rel;
                fd[j] = (1.0 + g) * ((double)w[j] + w[j + 1]) + alphaTilde;
                gamma[j] = g;
                active[j] = fd[j] > 0.0;
            }

            for (int j = 0; j < s; j++)
            {
                if (!active[j]) { fl[j] = 0.0; fu[j] = 0.0; continue; }
                double scale = 1.0 + gamma[j];
                fl[j] = j > 0 && active[j - 1]
                    ? -scale * w[j] * ((double)c.DirX[j - 1] * c.DirX[j] + (double)c.DirY[j - 1] * c.DirY[j] + (double)c.DirZ[j - 1] * c.DirZ[j])
                    : 0.0;
                fu[j] = j + 1 < s && fd[j + 1] > 0.0 && !c.Broken[j + 1]
                    ? -scale * w[j + 1] * ((double)c.DirX[j] * c.DirX[j + 1] + (double)c.DirY[j] * c.DirY[j + 1] + (double)c.DirZ[j] * c.DirZ[j + 1])
                    : 0.0;
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

            for (int j = 0; j < s; j++)
            {
                double d = delta[j];
                if (tensionOnly && lambda[j] + d > 0.0) d = -lambda[j];
                if (d == 0.0) continue;
                lambda[j] += d;
                float nx = c.DirX[j], ny = c.DirY[j], nz = c.DirZ[j];
                float a = (float)(w[j] * d), b = (float)(w[j + 1] * d);
                c.DX[j] -= nx * a; c.DY[j] -= ny * a; c.DZ[j] -= nz * a;
                c.DX[j + 1] += nx * b; c.DY[j + 1] += ny * b; c.DZ[j + 1] += nz * b;
            }
            return passes;
        }

        /// <summary>Builds the system of the current active set into Lower/Diagonal/Upper/Rhs and solves it into Delta (Thomas algorithm).</summary>
        private static void Solve(ChainState c, bool tensionOnly)
        {
            int s = c.SegmentCount;
            double[] lo = c.Lower, di = c.Diagonal, up = c.Upper, rhs = c.Rhs, x = c.Delta;
            double[] fd = c.FullDiagonal, fl = c.FullLower, fu = c.FullUpper, fr = c.FullRhs;
            bool[] active = c.Active;
            for (int j = 0; j < s; j++)
            {
                if (active[j])
                {
                    lo[j] = fl[j]; di[j] = fd[j]; up[j] = fu[j]; rhs[j] = fr[j];
                }
                else
                {
                    // released (or broken) row: its λ returns to zero this iteration, Δλ = −λ
                    lo[j] = 0.0; di[j] = 1.0; up[j] = 0.0;
                    rhs[j] = fd[j] > 0.0 && tensionOnly ? -c.Lambda[j] : 0.0;
                }
            }
            // forward sweep (in place: up becomes c', rhs becomes d')
            double m = di[0];
            up[0] /= m;
            rhs[0] /= m;
            for (int j = 1; j < s; j++)
            {
                m = di[j] - lo[j] * up[j - 1];
                up[j] /= m;
                rhs[j] = (rhs[j] - lo[j] * rhs[j - 1]) / m;
            }
            x[s - 1] = rhs[s - 1];
            for (int j = s - 2; j >= 0; j--) x[j] = rhs[j] - up[j] * x[j + 1];
        }
    }
}
