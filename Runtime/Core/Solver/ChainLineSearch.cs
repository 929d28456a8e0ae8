using System;

namespace HookeRope.Solver
{
    /// <summary>
    /// Backtracking line search for an iteration of <see cref="ExactChainSolver"/> whose linearisation was off (a violent
    /// substep). The implicit step minimises Φ(x) = ½|x − x̃|²_M/h² + Σ_j ψ_j(l_j) with ψ_j = ½(l_j − L'_j)²/α'_j
    /// (tension-only: only where l_j &gt; L'_j), and the iteration's motion δ is a descent direction of Φ. Measured from the
    /// iterate before the iteration, h²Φ changes along s·δ by Σ_i [s δ_i·P_i + ½s² m_i|δ_i|²] + h²Σ_j Δψ_j, P_i the
    /// accumulated pull of the solve on particle i (m_i (x_i − x̃_i) = P_i). The step is halved until h²Φ decreases by at
    /// least 1e-4 of the predicted decrease (Armijo). With contacts held with friction, Φ also holds each one's damper,
    /// ½ζ|s_slip|² (<see cref="ChainContacts.FrictionChange"/>), and a direction that is no descent direction is shortened
    /// until Φ does not rise.
    /// </summary>
    internal static class ChainLineSearch
    {
        /// <summary>Most halvings of the step.</summary>
        public const int MaxHalvings = 12;

        /// <summary>Armijo constant: the accepted step decreases Φ by at least this fraction of the linear prediction.</summary>
        public const double Sufficient = 1e-4;

        /// <summary>
        /// The step s ∈ (0, 1] along the iteration's motion (1: the full Newton step). <paramref name="friction"/>: some contact
        /// of the solve is held with friction (<see cref="ChainContacts.FrictionInSolve"/>), for <see cref="Shorten"/>.
        /// </summary>
        public static double Backtrack(ChainState c, bool tensionOnly, out bool friction)
        {
            friction = false;
            if (c.RigidInSolve) return 1.0;
            friction = c.ContactCount > 0 && ChainContacts.FrictionInSolve(c);
            double slope = Slope(c, tensionOnly, friction);
            if (!(slope < 0.0))
            {
                if (!friction) return 1.0;
                // with friction, a direction that is no descent direction comes from passes that ended with some contact's
                // friction still moving (a contact cycling between sticking and sliding): its full step was measured to raise
                // the objective (a 1 GPa rope hitting the sphere: +0.24 in h²Φ, then 14 kJ of elastic energy), so it is
                // shortened until it does not raise the objective
                slope = 0.0;
            }
            double s = 1.0;
            for (int k = 0; k < MaxHalvings; k++)
            {
                if (Change(c, tensionOnly, friction, s) <= Sufficient * s * slope) return s;
                s *= 0.5;
            }
            return s;
        }

        /// <summary>
        /// Takes back (1 − s) of the iteration: positions, accumulated forces, multipliers; with <paramref name="friction"/>
        /// (<see cref="Backtrack"/>'s) the contacts' impulses and friction too.
        /// </summary>
        public static void Shorten(ChainState c, double s, bool friction)
        {
            double back = 1.0 - s;
            int n = c.ParticleCount;
            if (friction) ChainContacts.Shorten(c, s);
            for (int i = 0; i < n; i++)
            {
                // in float, DLow left as it is (an error of at most half a float step of D). Taking it back exactly through
                // AddDisplacement flips two knife-edge sweep cases (16-segment steel, load ratio 1e6, released 10× stretched, backward
                // Euler, 1 kHz) to a 1.5e12 J gain; that family flips under 1e-5 changes of its release stretch (stability-grid.md)
                c.DX[i] -= (float)(back * c.MotionX[i]); c.DY[i] -= (float)(back * c.MotionY[i]); c.DZ[i] -= (float)(back * c.MotionZ[i]);
                c.MotionX[i] *= s; c.MotionY[i] *= s; c.MotionZ[i] *= s;
            }
            for (int j = 0; j < c.SegmentCount; j++)
            {
                c.ForceX[j] -= back * c.StepX[j]; c.ForceY[j] -= back * c.StepY[j]; c.ForceZ[j] -= back * c.StepZ[j];
                c.StepX[j] *= s; c.StepY[j] *= s; c.StepZ[j] *= s;
                c.Lambda[j] = c.Active[j] ? -(c.ForceX[j] * c.DirX[j] + c.ForceY[j] * c.DirY[j] + c.ForceZ[j] * c.DirZ[j]) : 0.0;
            }
            if (friction) ChainContacts.FinishShortened(c);
        }

        /// <summary>dΦ/ds at s = 0 (×h²); <paramref name="friction"/>: with the friction of the contacts held with it (<see cref="ChainContacts.FrictionChange"/>).</summary>
        private static double Slope(ChainState c, bool tensionOnly, bool friction)
        {
            double slope = 0.0;
            int n = c.ParticleCount, segs = c.SegmentCount;
            for (int i = 0; i < n; i++)
            {
                Pull(c, i, out double px, out double py, out double pz);
                slope += c.MotionX[i] * px + c.MotionY[i] * py + c.MotionZ[i] * pz;
            }
            for (int j = 0; j < segs; j++)
            {
                if (!c.Assembled[j]) continue;
                Before(c, j, out double dx, out double dy, out double dz, out double ux, out double uy, out double uz);
                double l = Math.Sqrt(dx * dx + dy * dy + dz * dz);
                double stretch = l - c.EffectiveRest[j];
                if ((tensionOnly && stretch <= 0.0) || l == 0.0) continue;
                slope += stretch / c.AxialCompliance[j] * (dx * ux + dy * uy + dz * uz) / l;
            }
            if (friction)
            {
                ChainContacts.FrictionChange(c, 0.0, out double frictionSlope);
                slope += frictionSlope;
            }
            return slope;
        }

        /// <summary>h²·(Φ(s) − Φ(0)), with the friction of the contacts held with it when <paramref name="friction"/>.</summary>
        private static double Change(ChainState c, bool tensionOnly, bool friction, double s)
        {
            double change = 0.0;
            int n = c.ParticleCount, segs = c.SegmentCount;
            for (int i = 0; i < n; i++)
            {
                double w = c.InverseMass[i];
                if (w == 0.0) continue;
                Pull(c, i, out double px, out double py, out double pz);
                double mx = c.MotionX[i], my = c.MotionY[i], mz = c.MotionZ[i];
                change += s * (mx * px + my * py + mz * pz) + 0.5 * s * s * (mx * mx + my * my + mz * mz) / w;
            }
            for (int j = 0; j < segs; j++)
            {
                if (!c.Assembled[j]) continue;
                Before(c, j, out double dx, out double dy, out double dz, out double ux, out double uy, out double uz);
                change += Energy(c, j, tensionOnly, dx + s * ux, dy + s * uy, dz + s * uz) - Energy(c, j, tensionOnly, dx, dy, dz);
            }
            if (friction) change += ChainContacts.FrictionChange(c, s, out _);
            return change;
        }

        private static double Energy(ChainState c, int j, bool tensionOnly, double dx, double dy, double dz)
        {
            double stretch = Math.Sqrt(dx * dx + dy * dy + dz * dz) - c.EffectiveRest[j];
            if (tensionOnly && stretch <= 0.0) return 0.0;
            return 0.5 * stretch * stretch / c.AxialCompliance[j];
        }

        /// <summary>Segment j before the iteration (d, m) and the iteration's change of it (u, m).</summary>
        private static void Before(ChainState c, int j, out double dx, out double dy, out double dz, out double ux, out double uy, out double uz)
        {
            ux = c.MotionX[j + 1] - c.MotionX[j]; uy = c.MotionY[j + 1] - c.MotionY[j]; uz = c.MotionZ[j + 1] - c.MotionZ[j];
            // the live segment Prev + Low + D + DLow (ChainState.LiveSpan) less the iteration's change
            c.LiveSpan(j, out dx, out dy, out dz, out _, out _, out _);
            dx -= ux; dy -= uy; dz -= uz;
        }

        /// <summary>The accumulated pull Λ_i − Λ_{i−1} on particle i before the iteration (N·s²).</summary>
        private static void Pull(ChainState c, int i, out double px, out double py, out double pz)
        {
            px = 0; py = 0; pz = 0;
            if (i < c.SegmentCount && !c.Broken[i]) { px = c.ForceX[i] - c.StepX[i]; py = c.ForceY[i] - c.StepY[i]; pz = c.ForceZ[i] - c.StepZ[i]; }
            if (i > 0 && !c.Broken[i - 1]) { px -= c.ForceX[i - 1] - c.StepX[i - 1]; py -= c.ForceY[i - 1] - c.StepY[i - 1]; pz -= c.ForceZ[i - 1] - c.StepZ[i - 1]; }
        }
    }
}
