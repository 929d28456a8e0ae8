using System;

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
            double gamma = beta / h; // γ = α̃·β̃/h with β̃ = h²·β·k, k = 1/α
            float[] w = c.InverseMass, rest = c.RestLength, compliance = c.Compliance;
            float[] px = c.PrevX, py = c.PrevY, pz = c.PrevZ, dx = c.DX, dy = c.DY, dz = c.DZ;
            float[] nxs = c.DirX, nys = c.DirY, nzs = c.DirZ;
            bool[] broken = c.Broken;
            double[] lambda = c.Lambda;
            if (w.Length < s + 1 || px.Length < s + 1 || dx.Length < s + 1 || dy.Length < s + 1 || dz.Length < s + 1 || py.Length < s + 1 || pz.Length < s + 1) return;
            if (rest.Length < s || compliance.Length < s || nxs.Length < s || nys.Length < s || nzs.Length < s || broken.Length < s || lambda.Length < s) return;
            float wa = w[0];
            for (int j = 0; j < s; j++)
            {
                float wb = w[j + 1];
                if (broken[j]) { wa = wb; continue; }
                double alpha = compliance[j];
                double wSum = (double)wa + wb;
                if (wSum == 0.0 && alpha == 0.0) { wa = wb; continue; }
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
                double alphaTilde = alpha * invH2;
                double g = alpha > 0.0 ? gamma : 0.0;
                double rel = g > 0.0 ? nx * ddx + ny * ddy + nz * ddz : 0.0;
                double d = (-((double)len - rest[j]) - alphaTilde * lambda[j] - g * rel) / ((1.0 + g) * wSum + alphaTilde);
                if (tensionOnly && lambda[j] + d > 0.0) d = -lambda[j];
                if (d != 0.0)
                {
                    lambda[j] += d;
                    float a = (float)(wa * d), b = (float)(wb * d);
                    dx[j] -= nx * a; dy[j] -= ny * a; dz[j] -= nz * a;
                    dx[j + 1] += nx * b; dy[j + 1] += ny * b; dz[j + 1] += nz * b;
                }
                wa = wb;
            }
        }
    }
}
