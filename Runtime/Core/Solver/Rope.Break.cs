using System;

namespace HookeRope.Solver
{
    public sealed partial class Rope
    {
        /// <summary>
        /// The recoil of a break at the middle of <paramref name="segment"/> (still intact): the elastic energy the segment
        /// holds, E = ½·C²/α (J; C = l − L, none when slack on a tension-only rope or inextensible), goes into the two end
        /// particles as equal and opposite impulses p along the segment's direction n, apart from the cut:
        /// Δv_j = −p·w_j·n, Δv_{j+1} = +p·w_{j+1}·n (w = 1/m, 0 for a kinematic particle). p solves
        /// p²/(2μ) + p·u = E (μ = 1/(w_j + w_{j+1}), u = (v_{j+1} − v_j)·n the separation speed), so the kinetic energy
        /// rises by exactly E whatever the ends' velocities were, and the momentum of two free ends is kept. In the
        /// continuum the unloading wave gives the released material E as kinetic energy within L/(2c) (c = √(E·A/μ_l)),
        /// far below a substep; the lumped particle that carries the half segment's mass takes it at once. The velocity
        /// change enters the integrator's history as a boost (as <see cref="SetVelocity"/>). Returns E (J).
        /// </summary>
        private double ReleaseRecoil(int segment)
        {
            int a = segment, b = segment + 1;
            double compliance = chain.Compliance[segment];
            if (!(compliance > 0.0)) return 0.0;
            double dx = (double)chain.X[b] - chain.X[a], dy = (double)chain.Y[b] - chain.Y[a], dz = (double)chain.Z[b] - chain.Z[a];
            double length = Math.Sqrt(dx * dx + dy * dy + dz * dz);
            double c = length - chain.RestLength[segment];
            if (settings.Tension == TensionModel.TensionOnly && c < 0.0) return 0.0;
            double energy = 0.5 * c * c / compliance;
            if (!(energy > 0.0) || double.IsInfinity(energy)) return 0.0;
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
            if (!(w > 0.0)) return energy;
            double reduced = 1.0 / w;
            double u = (chain.VelX[b] - (double)chain.VelX[a]) * nx + (chain.VelY[b] - (double)chain.VelY[a]) * ny + (chain.VelZ[b] - (double)chain.VelZ[a]) * nz;
            double p = reduced * (Math.Sqrt(u * u + 2.0 * energy / reduced) - u);
            if (wa > 0.0) Kick(a, -p * wa * nx, -p * wa * ny, -p * wa * nz);
            if (wb > 0.0) Kick(b, p * wb * nx, p * wb * ny, p * wb * nz);
            return energy;
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
