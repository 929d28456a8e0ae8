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
            // a rope without contacts or plasticity runs the sweep compiled without their branches: no call in the loop, so
            // nothing the loop keeps in registers is spilled around one (every XMM register is caller-saved)
            if (c.ContactCount == 0 && c.Plasticity == null) Sweep<Plain>(c, h, beta, tensionOnly);
            else Sweep<Featured>(c, h, beta, tensionOnly);
        }

        /// <summary>The sweep compiled for ropes without contacts and plasticity (their branches folded away).</summary>
        private struct Plain { }

        /// <summary>The sweep compiled with the contact and plastic branches.</summary>
        private struct Featured { }

        /// <summary>
        /// The sweep; T is <see cref="Plain"/> or <see cref="Featured"/>. The JIT compiles one body per struct type argument and
        /// folds typeof(T) == typeof(Featured) to a constant, so the plain body has neither branch.
        /// </summary>
        private static void Sweep<T>(ChainState c, double h, double beta, bool tensionOnly) where T : struct
        {
            bool featured = typeof(T) == typeof(Featured);
            double invH2 = 1.0 / (h * h);
            double gamma = beta / h; // γ = α̃·β̃/h with β̃ = h²·β·k, k = 1/α
            int s = c.SegmentCount;
            // every array as spans of exactly s entries, the segment's first particle (A, index j) and its second (B, index
            // j + 1): spans of one known length, the loop bound, index without bounds checks (arrays indexed j + 1 would not)
            ReadOnlySpan<float> wA = ChainState.Exactly(c.InverseMass, s), wB = ChainState.Shifted(c.InverseMass, s);
            Span<float> dxA = ChainState.Exactly(c.DX, s), dyA = ChainState.Exactly(c.DY, s), dzA = ChainState.Exactly(c.DZ, s);
            Span<float> dxB = ChainState.Shifted(c.DX, s), dyB = ChainState.Shifted(c.DY, s), dzB = ChainState.Shifted(c.DZ, s);
            // the sub-float parts DLow of the displacements (live position = Prev + Low + D + DLow)
            Span<float> dlxA = ChainState.Exactly(c.DLowX, s), dlyA = ChainState.Exactly(c.DLowY, s), dlzA = ChainState.Exactly(c.DLowZ, s);
            Span<float> dlxB = ChainState.Shifted(c.DLowX, s), dlyB = ChainState.Shifted(c.DLowY, s), dlzB = ChainState.Shifted(c.DLowZ, s);
            ReadOnlySpan<float> pxA = ChainState.Exactly(c.PrevX, s), pyA = ChainState.Exactly(c.PrevY, s), pzA = ChainState.Exactly(c.PrevZ, s);
            ReadOnlySpan<float> pxB = ChainState.Shifted(c.PrevX, s), pyB = ChainState.Shifted(c.PrevY, s), pzB = ChainState.Shifted(c.PrevZ, s);
            ReadOnlySpan<float> lxA = ChainState.Exactly(c.LowX, s), lyA = ChainState.Exactly(c.LowY, s), lzA = ChainState.Exactly(c.LowZ, s);
            ReadOnlySpan<float> lxB = ChainState.Shifted(c.LowX, s), lyB = ChainState.Shifted(c.LowY, s), lzB = ChainState.Shifted(c.LowZ, s);
            ReadOnlySpan<float> rest = ChainState.Exactly(c.RestLength, s), compliance = ChainState.Exactly(c.Compliance, s);
            ReadOnlySpan<bool> broken = ChainState.Exactly(c.Broken, s);
            Span<double> lambda = ChainState.Exactly(c.Lambda, s);
            Span<float> dirX = ChainState.Exactly(c.DirX, s), dirY = ChainState.Exactly(c.DirY, s), dirZ = ChainState.Exactly(c.DirZ, s);
            bool contacts = featured && c.ContactCount > 0;
            SegmentPlasticity plastic = featured ? c.Plasticity : null;
            // particle a = j is carried from the projection before (its displacement as that projection left it): each
            // particle's displacement is loaded and stored once per sweep
            float wa = wA[0], dxa = dxA[0], dya = dyA[0], dza = dzA[0], dlxa = dlxA[0], dlya = dlyA[0], dlza = dlzA[0];
            for (int j = 0; j < s; j++)
            {
                float wb = wB[j], dxb = dxB[j], dyb = dyB[j], dzb = dzB[j], dlxb = dlxB[j], dlyb = dlyB[j], dlzb = dlzB[j];
                double alpha = compliance[j];
                double wSum = (double)wa + wb;
                if (!broken[j] && (wSum != 0.0 || alpha != 0.0))
                {
                    double ddx = ChainState.Change(dxa, dxb, dlxa, dlxb), ddy = ChainState.Change(dya, dyb, dlya, dlyb), ddz = ChainState.Change(dza, dzb, dlza, dlzb);
                    double len = ChainState.Normalise(j, ChainState.Component(pxA[j], pxB[j], lxA[j], lxB[j], ddx), ChainState.Component(pyA[j], pyB[j], lyA[j], lyB[j], ddy),
                        ChainState.Component(pzA[j], pzB[j], lzA[j], lzB[j], ddz), dirX, dirY, dirZ, out double ex, out double ey, out double ez);
                    float nx = (float)ex, ny = (float)ey, nz = (float)ez;
                    double alphaTilde = alpha * invH2;
                    double g = alpha > 0.0 ? gamma : 0.0;
                    double rel = g > 0.0 ? nx * ddx + ny * ddy + nz * ddz : 0.0;
                    double restJ = !featured || plastic == null ? rest[j] : plastic.Rest(j); // a plastic segment's force is measured from L_p
                    double lambdaJ = lambda[j];
                    double numerator = -((double)len - restJ) - alphaTilde * lambdaJ - g * rel;
                    if (featured && plastic != null)
                    {
                        numerator = ChooseBranch(plastic, j, lambdaJ, g, wSum, invH2, numerator, alphaTilde, out double branchCompliance);
                        alphaTilde = branchCompliance;
                    }
                    if (featured && contacts && (c.ContactActive[j] || c.ContactActive[j + 1]))
                    {
                        dxA[j] = dxa; dyA[j] = dya; dzA[j] = dza; dxB[j] = dxb; dyB[j] = dyb; dzB[j] = dzb;
                        dlxA[j] = dlxa; dlyA[j] = dlya; dlzA[j] = dlza; dlxB[j] = dlxb; dlyB[j] = dlyb; dlzB[j] = dlzb;
                        ProjectWithContacts(c, j, nx, ny, nz, numerator, g, alphaTilde, tensionOnly);
                        dxa = dxA[j]; dya = dyA[j]; dza = dzA[j]; dxb = dxB[j]; dyb = dyB[j]; dzb = dzB[j];
                        dlxa = dlxA[j]; dlya = dlyA[j]; dlza = dlzA[j]; dlxb = dlxB[j]; dlyb = dlyB[j]; dlzb = dlzB[j];
                    }
                    else
                    {
                        double d = numerator / ((1.0 + g) * wSum + alphaTilde);
                        d = ChainState.LimitToPulling(lambdaJ, d, tensionOnly);
                        if (d != 0.0)
                        {
                            lambda[j] = lambdaJ + d;
                            // D + DLow moved exactly (ChainState.AddDisplacement on the carried copies); end a by n·(−w_a·d), the
                            // same product as (−n)·(w_a·d), with one negation instead of three
                            double ma = -(wa * d), mb = wb * d;
                            ChainState.Add(ref dxa, ref dlxa, nx * ma); ChainState.Add(ref dya, ref dlya, ny * ma); ChainState.Add(ref dza, ref dlza, nz * ma);
                            ChainState.Add(ref dxb, ref dlxb, nx * mb); ChainState.Add(ref dyb, ref dlyb, ny * mb); ChainState.Add(ref dzb, ref dlzb, nz * mb);
                        }
                    }
                }
                dxA[j] = dxa; dyA[j] = dya; dzA[j] = dza; dlxA[j] = dlxa; dlyA[j] = dlya; dlzA[j] = dlza;
                wa = wb; dxa = dxb; dya = dyb; dza = dzb; dlxa = dlxb; dlya = dlyb; dlza = dlzb;
            }
            c.DX[s] = dxa; c.DY[s] = dya; c.DZ[s] = dza; c.DLowX[s] = dlxa; c.DLowY[s] = dlya; c.DLowZ[s] = dlza;
        }

        /// <summary>
        /// <see cref="SegmentPlasticity.ChooseBranch"/> on copies (returns the numerator, the compliance α̃ in branchCompliance),
        /// so the sweep's own numerator and compliance are not address-exposed: they stay in registers.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        private static double ChooseBranch(SegmentPlasticity plastic, int j, double lambda, double g, double wSum, double invH2, double numerator, double alphaTilde, out double branchCompliance)
        {
            plastic.ChooseBranch(j, lambda, g, wSum, invH2, ref numerator, ref alphaTilde);
            branchCompliance = alphaTilde;
            return numerator;
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
            c.AddDisplacement(j, -ax, -ay, -az);
            c.AddDisplacement(j + 1, bx, by, bz);
        }
    }
}
