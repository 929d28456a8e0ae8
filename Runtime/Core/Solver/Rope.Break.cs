using System;

namespace HookeRope.Solver
{
    public sealed partial class Rope
    {
        /// <summary>
        /// The recoil of a break at the middle of <paramref name="segment"/> (still intact): the elastic energy the segment
        /// holds, E = ½·C²/α (J; C = l − L, L_p for a plastic segment; none when slack on a tension-only rope or inextensible), goes into the two end
        /// particles as equal and opposite impulses p along the segment's direction n, apart from the cut:
        /// Δv_j = −p·w_j·n, Δv_{j+1} = +p·w_{j+1}·n (w = 1/m, 0 for a kinematic particle). p solves
        /// p²/(2μ) + p·u = E (μ = 1/(w_j + w_{j+1}), u = (v_{j+1} − v_j)·n the separation speed), so the kinetic energy
        /// rises by exactly E whatever the ends' velocities were, and the momentum of two free ends is kept. In the
        /// continuum the unloading wave gives the released material E as kinetic energy within L/(2c) (c = √(E·A/μ_l)),
        /// far below a substep; the lumped particle that carries the half segment's mass takes it at once. The velocity
        /// change enters the integrator's history as a boost (as <see cref="SetVelocity"/>). A step too coarse for the
        /// recoil (substep h &gt; L/c: the unloading wave crosses more than a segment per substep) cannot carry it: an end
        /// moving at Δv would close the stretch of the segment behind it within the substep and fold the slack rope over
        /// itself. So p is capped where |Δv|·h would exceed that stretch (h = the last host step / substeps; no cap before
        /// the first step); the energy above the cap is lost to the coarse step, as the integrator loses the unresolved
        /// wave of the rest of the rope. Returns the kinetic energy the ends took (J): E unless capped; <paramref name="stored"/> = E.
        /// </summary>
        private double ReleaseRecoil(int segment, out double stored)
        {
            stored = 0.0;
            int a = segment, b = segment + 1;
            double compliance = chain.Compliance[segment];
            if (!(compliance > 0.0)) return 0.0;
            chain.Span(segment, out double dx, out double dy, out double dz);
            double length = Math.Sqrt(dx * dx + dy * dy + dz * dz);
            double c = length - chain.CurrentRest(segment);   // a plastic segment stores only what lies beyond its permanent set
            if (settings.Tension == TensionModel.TensionOnly && c < 0.0) return 0.0;
            double energy = 0.5 * c * c / compliance;
            if (!(energy > 0.0) || double.IsInfinity(energy)) return 0.0;
            stored = energy;
            double nx, ny, nz;
            if (length > 1e-12)
            {
                nx = dx / length; ny = dy / length; nz = dz / length;
            }
            else
            {
                nx = chain.DirX[segment]; ny = chain.DirY[segment]; nz = chain.DirZ[segment];
            }
            // a compressed (bilateral) segment pushes its ends together as it relaxes: the impulse points inward
            if (c < 0.0) { nx = -nx; ny = -ny; nz = -nz; }
            double wa = chain.Kinematic[a] ? 0.0 : 1.0 / chain.Mass[a];
            double wb = chain.Kinematic[b] ? 0.0 : 1.0 / chain.Mass[b];
            double w = wa + wb;
            if (!(w > 0.0)) return 0.0;
            double reduced = 1.0 / w;
            double u = (chain.VelX[b] - (double)chain.VelX[a]) * nx + (chain.VelY[b] - (double)chain.VelY[a]) * ny + (chain.VelZ[b] - (double)chain.VelZ[a]) * nz;
            double p = reduced * (Math.Sqrt(u * u + 2.0 * energy / reduced) - u);
            // what a substep can resolve: in one substep an end may close at most the stretch of the segment behind it
            double h = lastStepTime > 0f ? (double)lastStepTime / settings.Substeps : 0.0;
            if (h > 0.0)
            {
                if (wa > 0.0) p = Math.Min(p, Math.Max(0.0, StretchBehind(a, -1)) / (wa * h));
                if (wb > 0.0) p = Math.Min(p, Math.Max(0.0, StretchBehind(b, 1)) / (wb * h));
            }
            if (wa > 0.0) Kick(a, -p * wa * nx, -p * wa * ny, -p * wa * nz);
            if (wb > 0.0) Kick(b, p * wb * nx, p * wb * ny, p * wb * nz);
            // the kinetic energy the ends took (p·u + p²/(2μ); E itself unless the substep capped the impulse)
            return p * u + 0.5 * p * p / reduced;
        }

        /// <summary>
        /// Stretch l − L (m; L_p for a plastic segment) of the intact segment on the far side of end particle <paramref name="particle"/> (side −1: the
        /// segment before it, +1: after it); +∞ when there is none (a free end has nothing to fold into).
        /// </summary>
        private double StretchBehind(int particle, int side)
        {
            int j = side < 0 ? particle - 1 : particle;
            if (j < 0 || j >= chain.SegmentCount || chain.Broken[j]) return double.PositiveInfinity;
            chain.Span(j, out double dx, out double dy, out double dz);
            return Math.Sqrt(dx * dx + dy * dy + dz * dz) - chain.CurrentRest(j);
        }

        /// <summary>Adds (dx, dy, dz) m/s to particle i's velocity and to its integrator history.</summary>
        private void Kick(int i, double dx, double dy, double dz)
        {
            float fx = (float)dx, fy = (float)dy, fz = (float)dz;
            BoostHistory(i, fx, fy, fz);
            chain.VelX[i] += fx;
            chain.VelY[i] += fy;
            chain.VelZ[i] += fz;
        }
    }
}
