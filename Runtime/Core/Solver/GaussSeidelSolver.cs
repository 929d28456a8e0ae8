namespace HookeRope.Solver
{
    /// <summary>
    /// One Gauss–Seidel XPBD iteration over the segments in order (Macklin 2016, with the damping
    /// of eq. 26). Tension-only segments clamp the accumulated λ to the pulling side (λ ≤ 0).
    /// </summary>
    internal static class GaussSeidelSolver
    {
        public static void Iterate(ChainState c, double h, double beta, bool tensionOnly)
        {
            int s = c.SegmentCount;
            double invH2 = 1.0 / (h * h);
            float[] w = c.InverseMass;
            double[] lambda = c.Lambda;
            for (int j = 0; j < s; j++)
            {
                if (c.Broken[j]) continue;
                double alpha = c.Compliance[j];
                double wSum = (double)w[j] + w[j + 1];
                if (wSum == 0.0 && alpha == 0.0) continue;
                float len = c.Direction(j, out float nx, out float ny, out float nz);
                double alphaTilde = alpha * invH2;
                double g = alpha * beta / h;
                double rel = 0.0;
                if (g > 0.0)
                {
                    rel = nx * (c.DX[j + 1] - c.DX[j]) + ny * (c.DY[j + 1] - c.DY[j]) + nz * (c.DZ[j + 1] - c.DZ[j]);
                }
                double constraint = (double)len - c.RestLength[j];
                double d = (-constraint - alphaTilde * lambda[j] - g * rel) / ((1.0 + g) * wSum + alphaTilde);
                if (tensionOnly && lambda[j] + d > 0.0) d = -lambda[j];
                if (d == 0.0) continue;
                lambda[j] += d;
                float a = (float)(w[j] * d), b = (float)(w[j + 1] * d);
                c.DX[j] -= nx * a; c.DY[j] -= ny * a; c.DZ[j] -= nz * a;
                c.DX[j + 1] += nx * b; c.DY[j + 1] += ny * b; c.DZ[j + 1] += nz * b;
            }
        }
    }
}
