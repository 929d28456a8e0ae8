using System;
using System.Diagnostics;

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
            float[] dx = c.DX, dy = c.DY, dz = c.DZ;
            bool[] broken = c.Broken;
            double[] lambda = c.Lambda;
            // ChainState sizes every particle array from SegmentCount + 1 and every segment array from SegmentCount
            Debug.Assert(w.Length == s + 1 && dx.Length == s + 1 && dy.Length == s + 1 && dz.Length == s + 1
                && rest.Length == s && compliance.Length == s && broken.Length == s && lambda.Length == s, "ChainState arrays sized from SegmentCount");
            bool contacts = c.ContactCount > 0;
            SegmentPlasticity plastic = c.Plasticity;
            float wa = w[0];
            for (int j = 0; j < s; j++)
            {
                float wb = w[j + 1];
                if (broken[j]) { wa = wb; continue; }
                double alpha = compliance[j];
                double wSum = (double)wa + wb;
                if (wSum == 0.0 && alpha == 0.0) { wa = wb; continue; }
                double len = c.Direction(j, out double ex, out double ey, out double ez, out float ddx, out float ddy, out float ddz);
                float nx = (float)ex, ny = (float)ey, nz = (float)ez;
                double alphaTilde = alpha * invH2;
                double g = alpha > 0.0 ? gamma : 0.0;
                double rel = g > 0.0 ? nx * ddx + ny * ddy + nz * ddz : 0.0;
                double restJ = plastic == null ? rest[j] : plastic.Rest(j); // a plastic segment's force is measured from L_p
                double numerator = -((double)len - restJ) - alphaTilde * lambda[j] - g * rel;
                if (plastic != null) plastic.ChooseBranch(j, lambda[j], g, wSum, invH2, ref numerator, ref alphaTilde);
                if (contacts && (c.ContactActive[j] || c.ContactActive[j + 1]))
                {
                    ProjectWithContacts(c, j, nx, ny, nz, numerator, g, alphaTilde, tensionOnly);
                    wa = wb;
                    continue;
                }
                double d = numerator / ((1.0 + g) * wSum + alphaTilde);
                d = ChainState.LimitToPulling(lambda[j], d, tensionOnly);
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

        /// <summary>
        /// Projects segment j (direction n) when an end is in an active contact: that end gets the tangent-plane inverse
        /// mass w(I − c cᵀ), unless the correction would lift it off the surface, in which case it moves freely. The
        /// normal motion a held end did not make is added to its contact load (friction limit).
        /// </summary>
        private static void ProjectWithContacts(ChainState c, int j, float nx, float ny, float nz, double numerator, double g, double alphaTilde, bool tensionOnly)
        {
            double[] lambda = c.Lambda;
            double wa = c.InverseMass[j], wb = c.InverseMass[j + 1];
            // a contact detected with a gap is let the sweep close it (no allowance per projection here)
            bool holdA = c.ContactActive[j] && c.ContactGap[j] <= 0.01f * c.Radius[j];
            bool holdB = c.ContactActive[j + 1] && c.ContactGap[j + 1] <= 0.01f * c.Radius[j + 1];
            double cna = holdA ? (double)c.ContactNX[j] * nx + (double)c.ContactNY[j] * ny + (double)c.ContactNZ[j] * nz : 0.0;
            double cnb = holdB ? (double)c.ContactNX[j + 1] * nx + (double)c.ContactNY[j + 1] * ny + (double)c.ContactNZ[j + 1] * nz : 0.0;
            double d = 0.0;
            for (int attempt = 0; attempt < 3; attempt++)
            {
                double wae = holdA ? wa * (1.0 - cna * cna) : wa;
                double wbe = holdB ? wb * (1.0 - cnb * cnb) : wb;
                double denominator = (1.0 + g) * (wae + wbe) + alphaTilde;
                d = denominator > 0.0 ? numerator / denominator : 0.0;
                d = ChainState.LimitToPulling(lambda[j], d, tensionOnly);
                // end a moves by −wa·n·d, end b by +wb·n·d: a held end whose normal motion would be outward is let go
                if (holdA && -cna * d > 0.0) { holdA = false; continue; }
                if (holdB && cnb * d > 0.0) { holdB = false; continue; }
                break;
            }
            if (d == 0.0) return;
            lambda[j] += d;
            double a = wa * d, b = wb * d;
            double ax = nx * a, ay = ny * a, az = nz * a, bx = nx * b, by = ny * b, bz = nz * b;
            if (holdA)
            {
                double normal = -cna * a; // normal motion of end a, ≤ 0 (into the surface)
                ax += c.ContactNX[j] * normal; ay += c.ContactNY[j] * normal; az += c.ContactNZ[j] * normal;
                c.ContactLoad[j] -= (float)normal;
            }
            if (holdB)
            {
                double normal = cnb * b;
                bx -= c.ContactNX[j + 1] * normal; by -= c.ContactNY[j + 1] * normal; bz -= c.ContactNZ[j + 1] * normal;
                c.ContactLoad[j + 1] -= (float)normal;
            }
            c.DX[j] -= (float)ax; c.DY[j] -= (float)ay; c.DZ[j] -= (float)az;
            c.DX[j + 1] += (float)bx; c.DY[j + 1] += (float)by; c.DZ[j + 1] += (float)bz;
        }
    }
}
