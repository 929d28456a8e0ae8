using System;

namespace HookeRope.Solver
{
    /// <summary>
    /// The plastic state of a rope's segments and their law (issue 15; Documentation~/solver.md, "Material law").
    /// Each segment keeps a plastic rest length L_p (starts at its rest length L; ε_p = L_p/L − 1) and carries
    /// T = E·A·(l − L_p)/L while elastic: the solvers read L_p where they read the rest length, with the unchanged compliance
    /// α = L/(E·A), so the elastic part of the solve stays exact. A segment yields when its force reaches the yield force
    /// T_y(ε_p):
    /// <list type="bullet">
    /// <item>rope segments of the elastic–plastic material: T_y = E·A·ε_y + H·ε_p (H ≥ 0, 0 = a plateau);</item>
    /// <item>the neck segment (the radius model's defect) past the neck onset ε_pn = (ε_n − ε_y)/(1 + H/(E·A)): the softening
    /// T_y = F_n·(ε_u − ε_p)/(ε_u − ε_pn), F_n = E·A·ε_y + H·ε_pn, zero at the ultimate strain ε_u;</item>
    /// <item>the energy absorber (the last segment): T_y = F_p while the deployment L_p − L is below its length, then
    /// never again (the webbing's elasticity takes over).</item>
    /// </list>
    /// While yielding, the segment's row in the solve is the elastic row in series with a plastic element of tangent
    /// H_t (H, or <see cref="TangentFloor"/>·T_ref for a plateau or the softening neck): rest − L·T_y/H_t and compliance
    /// + L/H_t, so its force is T_y + H_t·Δε_p within the substep; the branch (elastic or yielding) is an active set the exact
    /// solve corrects between Newton iterations and Gauss–Seidel per projection. After each substep the return mapping
    /// on the positions, Δε_p = ((l − L_p) + γ(l − l₀) − α·T_y)/(L·(1 + γ) + α·H_t) for Δε_p &gt; 0 (γ = β/h the damping of
    /// XPBD's eq. 26, in series with the elastic part only), updates L_p; the plastic work T·ΔL_p is summed.
    /// Allocation-free after construction.
    /// </summary>
    internal sealed class SegmentPlasticity
    {
        /// <summary>
        /// Tangent (N per unit plastic strain) of a plateau or a softening segment in the solve, as a fraction of its reference
        /// yield force: within one substep its force rises by at most this fraction of the yield force per unit plastic strain
        /// (1e-4 of T_y for a substep that flows by 10 %), and the plateau itself does not drift, since each substep starts from
        /// the yield force again.
        /// </summary>
        public const double TangentFloor = 1e-3;

        /// <summary>Relative band around the yield force inside which the exact solve keeps a segment's branch (no switch on round-off).</summary>
        public const double BranchTolerance = 1e-9;


        private readonly double[] plasticRest;
        private readonly double[] reference;
        private readonly bool[] yielding;
        private readonly bool[] keptYielding;
        private double axialStiffness;
        private bool plastic;
        private double yieldForce;
        private double hardening;
        private double neckPlasticStrain;
        private double ultimateStrain;
        private double neckForce;
        private int neckSegment = -1;
        private int absorberSegment = -1;
        private double absorberForce;
        private double absorberDeployment;

        public SegmentPlasticity(int segmentCount)
        {
            plasticRest = new double[segmentCount];
            reference = new double[segmentCount];
            yielding = new bool[segmentCount];
            keptYielding = new bool[segmentCount];
        }

        /// <summary>Keeps every segment's branch (yielding or elastic) for <see cref="RestoreBranches"/>: the start of a substep that may run again.</summary>
        public void KeepBranches() => Array.Copy(yielding, keptYielding, yielding.Length);

        /// <summary>Puts back the branches of the last <see cref="KeepBranches"/> (the solve changes them as it iterates, <see cref="UpdateBranches"/>).</summary>
        public void RestoreBranches() => Array.Copy(keptYielding, yielding, yielding.Length);

        /// <summary>Plastic work ∫T dL_p (J) since the state was created: energy the rope turned into permanent set (and the absorber tore).</summary>
        public double PlasticWork;

        /// <summary>The segment that necks (−1: none; the absorber's segment does not neck).</summary>
        public int NeckSegment => neckSegment;

        /// <summary>The absorber's segment (−1: no absorber).</summary>
        public int AbsorberSegment => absorberSegment;

        /// <summary>True with the elastic–plastic material (and a finite E·A: an inextensible rope has no yield strain).</summary>
        public bool RopePlastic => plastic;

        /// <summary>Plastic rest length L_p of segment j (m).</summary>
        public double Rest(int j) => plasticRest[j];

        /// <summary>True when segment j takes the yielding branch in the current solve.</summary>
        public bool IsYielding(int j) => yielding[j];

        /// <summary>
        /// Reads the law from <paramref name="settings"/> (E·A, yield strain, hardening, necking and ultimate strains, the
        /// absorber) for the chain's rest lengths; a segment whose rest length changed starts again from L_p = L. The neck is
        /// <paramref name="neck"/> (−1: the segment at the middle of the rest length).
        /// </summary>
        public void Configure(RopeSettings settings, ChainState c, int neck)
        {
            int s = plasticRest.Length;
            for (int j = 0; j < s; j++)
            {
                double rest = c.RestLength[j];
                if (rest == reference[j]) continue;
                reference[j] = rest;
                plasticRest[j] = rest;
                yielding[j] = false;
            }
            axialStiffness = settings.AxialStiffness;
            plastic = settings.MaterialModel == MaterialModel.ElasticPlastic && double.IsFinite(axialStiffness);
            yieldForce = axialStiffness * settings.YieldStrain;
            hardening = settings.HardeningModulus;
            neckPlasticStrain = (settings.NeckingStrain - (double)settings.YieldStrain) / (1.0 + hardening / axialStiffness);
            ultimateStrain = settings.UltimateStrain;
            neckForce = yieldForce + hardening * neckPlasticStrain;
            absorberSegment = settings.EnergyAbsorber ? s - 1 : -1;
            absorberForce = settings.AbsorberForce;
            absorberDeployment = settings.AbsorberDeployment;
            SetNeck(neck);
        }

        /// <summary>
        /// Puts the neck at segment <paramref name="neck"/> (−1: the middle one). Ignored once the present neck has passed its
        /// onset (a neck does not move); no neck without the plastic material or on the absorber's segment.
        /// </summary>
        public void SetNeck(int neck)
        {
            int s = plasticRest.Length;
            if (neckSegment >= 0 && neckSegment < s && PlasticStrain(neckSegment) >= neckPlasticStrain && plastic) return;
            if (neck < 0 || neck >= s) neck = s / 2;
            neckSegment = plastic && neck != absorberSegment ? neck : -1;
        }

        /// <summary>Plastic strain ε_p = L_p/L − 1 of segment j.</summary>
        public double PlasticStrain(int j) => plasticRest[j] / reference[j] - 1.0;

        /// <summary>Yield force T_y (N) of segment j at its present plastic strain; +∞ where it cannot flow (elastic, absorber used up).</summary>
        public double YieldForce(int j)
        {
            if (j == absorberSegment)
                return plasticRest[j] - reference[j] < absorberDeployment ? absorberForce : double.PositiveInfinity;
            if (!plastic) return double.PositiveInfinity;
            double strain = PlasticStrain(j);
            if (j == neckSegment && strain >= neckPlasticStrain)
            {
                double remaining = (ultimateStrain - strain) / (ultimateStrain - neckPlasticStrain);
                return remaining > 0.0 ? neckForce * remaining : 0.0;
            }
            return yieldForce + hardening * strain;
        }

        /// <summary>Tangent H_t (N per unit plastic strain) of segment j's plastic element in the solve.</summary>
        public double Tangent(int j)
        {
            if (j == absorberSegment) return TangentFloor * absorberForce;
            double floor = TangentFloor * yieldForce;
            if (j == neckSegment && PlasticStrain(j) >= neckPlasticStrain) return floor;
            return Math.Max(hardening, floor);
        }

        /// <summary>
        /// Softening progress of the neck segment, in [0, 1] (0 at the neck onset, 1 at the ultimate strain: no force left), or
        /// −1 while no neck has formed (or there is none).
        /// </summary>
        public float NeckSoftening
        {
            get
            {
                if (neckSegment < 0) return -1f;
                double strain = PlasticStrain(neckSegment);
                if (strain < neckPlasticStrain) return -1f;
                double s = (strain - neckPlasticStrain) / (ultimateStrain - neckPlasticStrain);
                return s < 1.0 ? (float)s : 1f;
            }
        }

        /// <summary>
        /// Exact solve, yielding branch of segment j: the elastic row (damped rest <paramref name="rest"/>, m, and compliance
        /// <paramref name="alphaTilde"/>, m per N·s²) in series with the plastic element: rest − L·T_y/H_t, compliance + L/(H_t·h²).
        /// </summary>
        public void FlowRow(int j, double invH2, ref double rest, ref double alphaTilde)
        {
            double flexibility = reference[j] / Tangent(j);
            rest -= flexibility * YieldForce(j);
            alphaTilde += flexibility * invH2;
        }

        /// <summary>
        /// Gauss–Seidel: the projection of segment j takes the yielding branch when its elastic update (numerator over the
        /// denominator with <paramref name="mobility"/>, 1/kg) would pull harder than the yield force: then the numerator
        /// −C − α̃λ − γ·Δl and compliance <paramref name="alphaTilde"/> become those of the elastic part in series with the
        /// plastic element (rest − (1 + γ)·L·T_y/H_t, compliance + (1 + γ)·L/(H_t·h²)).
        /// </summary>
        public void ChooseBranch(int j, double lambda, double gamma, double mobility, double invH2, ref double numerator, ref double alphaTilde)
        {
            double ty = YieldForce(j);
            if (double.IsPositiveInfinity(ty)) return;
            double trial = numerator / ((1.0 + gamma) * mobility + alphaTilde);
            if (!(-(lambda + trial) * invH2 > ty)) return;
            double flexibility = (1.0 + gamma) * reference[j] / Tangent(j);
            numerator -= flexibility * ty + flexibility * invH2 * lambda;
            alphaTilde += flexibility * invH2;
        }

        /// <summary>
        /// Exact solve, after an iteration: a segment whose solved force (−λ/h², N) passed its yield force takes the yielding
        /// branch, a yielding one whose force fell below it (it unloads) the elastic one. Returns true when a branch changed
        /// (the next Newton iteration solves with it) or a yielding segment's force is off its direction by more than
        /// <see cref="MisalignmentTolerance"/>.
        /// </summary>
        public bool UpdateBranches(ChainState c, double invH2)
        {
            bool changed = false;
            bool[] broken = c.Broken;
            double[] lambda = c.Lambda;
            for (int j = 0; j < plasticRest.Length; j++)
            {
                if (broken[j]) continue;
                double ty = YieldForce(j);
                if (double.IsPositiveInfinity(ty)) { if (yielding[j]) { yielding[j] = false; changed = true; } continue; }
                double t = -lambda[j] * invH2;
                if (yielding[j] && Misaligned(c, j) > MisalignmentTolerance) changed = true;
                if (!yielding[j])
                {
                    if (t > ty * (1.0 + BranchTolerance) && t > 0.0) { yielding[j] = true; changed = true; }
                }
                else if (t < ty * (1.0 - BranchTolerance))
                {
                    yielding[j] = false;
                    changed = true;
                }
            }
            return changed;
        }

        /// <summary>
        /// Largest sine of the angle between a yielding segment's force and its direction after an exact-solve iteration
        /// that needs no further iteration. A yielding segment's length no longer constrains its force (it carries T_y at
        /// any length), so a single linearised iteration can leave its force pointing where the segment was: a sideways
        /// force of T_y·sin θ that does work. Left unchecked on a rope whipping taut (a 100 kg fall with the rope starting
        /// above its anchor), it grew a sideways mode that gained 2.9 kJ in the arrest with BDF2.
        /// </summary>
        public const double MisalignmentTolerance = 1e-3;

        /// <summary>
        /// Sine of the angle between yielding segment j's accumulated force vector Λ_j and its live direction (after the
        /// iteration's motion): a plastic element carries T_y along itself whatever its length, so only the direction of its
        /// force is left to converge.
        /// </summary>
        private static double Misaligned(ChainState c, int j)
        {
            double fx = c.ForceX[j], fy = c.ForceY[j], fz = c.ForceZ[j];
            // the live segment vector Prev + Low + D + DLow, exact (ChainState.LiveSpan)
            c.LiveSpan(j, out double dx, out double dy, out double dz, out _, out _, out _);
            double cx = fy * dz - fz * dy, cy = fz * dx - fx * dz, cz = fx * dy - fy * dx;
            double norms = Math.Sqrt((fx * fx + fy * fy + fz * fz) * (dx * dx + dy * dy + dz * dz));
            return norms > 0.0 ? Math.Sqrt(cx * cx + cy * cy + cz * cz) / norms : 0.0;
        }

        /// <summary>
        /// The return mapping at the end of a substep (positions committed; <paramref name="gamma"/> = β/h, the damping
        /// fold of the substep): every intact segment whose trial force passes its yield force flows by
        /// ΔL_p = ((l − L_p) + γ(l − l₀) − α·T_y)/(1 + γ + α·H_t/L), capped by the absorber's remaining deployment; the work
        /// (T_y + ½H_t·Δε_p)·ΔL_p is added to <see cref="PlasticWork"/>; the segment starts the next substep in the branch it
        /// ended in.
        /// </summary>
        public void ReturnMap(ChainState c, double gamma)
        {
            bool[] broken = c.Broken;
            for (int j = 0; j < plasticRest.Length; j++)
                yielding[j] = Flow(c, j, gamma, broken[j]) && !double.IsPositiveInfinity(YieldForce(j));
        }

        /// <summary>The return mapping of segment j; true when it flowed.</summary>
        private bool Flow(ChainState c, int j, double gamma, bool broken)
        {
            if (broken) return false;
            double ty = YieldForce(j);
            if (double.IsPositiveInfinity(ty)) return false;
            double alpha = c.Compliance[j];
            double g = alpha > 0.0 ? gamma : 0.0;
            // exact committed length, and the length at the start of the substep (the committed vector less the substep's D)
            c.Span(j, out double ex, out double ey, out double ez);
            double l = Math.Sqrt(ex * ex + ey * ey + ez * ez);
            c.SubstepChange(j, out double ddx, out double ddy, out double ddz);
            ex -= ddx; ey -= ddy; ez -= ddz;
            double l0 = Math.Sqrt(ex * ex + ey * ey + ez * ez);
            double lp = plasticRest[j], rest = reference[j];
            double excess = (l - lp) + g * (l - l0) - alpha * ty;
            // a rigid (α = 0) segment's length is its rest length up to round-off: it flows only where the solve pulled at the yield force
            if (!(excess > 0.0) || (alpha == 0.0 && c.Tension[j] < ty)) return false;
            double tangent = Tangent(j);
            double flow = excess / (1.0 + g + alpha * tangent / rest);
            if (j == absorberSegment) flow = Math.Min(flow, absorberDeployment - (lp - rest));
            if (!(flow > 0.0)) return false;
            plasticRest[j] = lp + flow;
            PlasticWork += flow * (ty + 0.5 * tangent * flow / rest);
            return true;
        }

        /// <summary>Σ (L_p − L) over the intact segments (m): the permanent set, absorber deployment included.</summary>
        public double PlasticElongation(bool[] broken)
        {
            double sum = 0.0;
            for (int j = 0; j < plasticRest.Length; j++) if (!broken[j]) sum += plasticRest[j] - reference[j];
            return sum;
        }

        /// <summary>Deployment L_p − L of the absorber (m; 0 without one).</summary>
        public double Deployment => absorberSegment >= 0 ? plasticRest[absorberSegment] - reference[absorberSegment] : 0.0;
    }
}
