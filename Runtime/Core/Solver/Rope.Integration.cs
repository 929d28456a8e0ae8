using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// The second-order integrator <see cref="TimeIntegrator.Bdf2"/>: x_{n+1} = (4x_n − x_{n−1})/3 + (2h/3)·v_{n+1},
    /// v_{n+1} = (4v_n − v_{n−1})/3 + (2h/3)·a_{n+1}. Each substep predicts d_pred = d_prev/3 + (2h/9)(4v − v_prev) + (4h²/9)·g
    /// (m; d_prev = x_n − x_{n−1}), runs the unchanged constraint solve with the effective step h_eff = 2h/3
    /// (α̃ = 9α/(4h²)), and sets v = base + d/h + Δ/(2h) with base = (4v − v_prev)/3 + (2h/3)·g − d_pred/h, where Δ is the
    /// displacement the chain solve applied (its constraint forces, a = Δ/h_eff²). Whatever else moved a particle after the
    /// prediction (collider push-out, friction, compliant pins) therefore enters the velocity as in backward Euler, as Δ/h,
    /// and does not bounce. Without a valid history (the first substep, a change of integrator or of h) the substep is
    /// backward Euler, which starts the history.
    /// </summary>
    public sealed partial class Rope
    {
        private bool historyValid;
        private double historyStep;
        /// <summary>
        /// Change of strain (dimensionless) within one substep beyond which the substep counts as violent (a teleported
        /// anchor, a rope released far stretched): the history restarts and the next substep is backward Euler. A
        /// linearisation that far from where the substep started makes the solve's displacement a poor force estimate, and
        /// BDF2 would carry it into two velocities. A rope that is merely stretched far (a soft lanyard at 100 % strain
        /// during an arrest) changes its strain smoothly and keeps the second-order scheme.
        /// </summary>
        public const float ViolentStrain = 0.5f;

        /// <summary>
        /// True when some intact segment's length at the solve's linearisation point differs from its length at the start
        /// of the substep by more than <see cref="ViolentStrain"/>·L.
        /// </summary>
        private bool Violent()
        {
            float[] length = chain.Length, rest = chain.RestLength, x = chain.PrevX, y = chain.PrevY, z = chain.PrevZ;
            bool[] broken = chain.Broken;
            for (int j = 0; j < chain.SegmentCount; j++)
            {
                if (broken[j]) continue;
                float dx = x[j + 1] - x[j], dy = y[j + 1] - y[j], dz = z[j + 1] - z[j];
                float start = MathF.Sqrt(dx * dx + dy * dy + dz * dz);
                if (MathF.Abs(length[j] - start) > ViolentStrain * rest[j]) return true;
            }
            return false;
        }

        /// <summary>The scheme substep h (s) runs: the chosen one, or backward Euler while the history does not fit it.</summary>
        private TimeIntegrator SubstepScheme(TimeIntegrator chosen, double h)
        {
            if (chosen == TimeIntegrator.BackwardEuler) { historyValid = false; return chosen; }
            return historyValid && h == historyStep ? chosen : TimeIntegrator.BackwardEuler;
        }

        /// <summary>Effective step h_eff (s) of the solve, α̃ = α/h_eff², for a substep h (s) of the scheme.</summary>
        private static double EffectiveStep(TimeIntegrator scheme, double h) => scheme == TimeIntegrator.Bdf2 ? h * (2.0 / 3.0) : h;

        /// <summary>
        /// Prediction of a second-order run (scheme: this substep's, h s, g m/s²): d = d_pred, the velocity base, v_prev = v,
        /// Δ = 0; kinematic particles do not move here (the pins place them). A backward-Euler substep predicts d = h·v + h²·g
        /// with base 0 (v = d/h).
        /// </summary>
        private void PredictSecondOrder(TimeIntegrator scheme, double h, Float3 g)
        {
            int n = chain.ParticleCount;
            float[] x = chain.X, y = chain.Y, z = chain.Z, px = chain.PrevX, py = chain.PrevY, pz = chain.PrevZ;
            float[] vx = chain.VelX, vy = chain.VelY, vz = chain.VelZ, ux = chain.PrevVelX, uy = chain.PrevVelY, uz = chain.PrevVelZ;
            float[] dx = chain.DX, dy = chain.DY, dz = chain.DZ;
            double[] bx = chain.BaseVelX, by = chain.BaseVelY, bz = chain.BaseVelZ;
            float[] qx = chain.PredictedDX, qy = chain.PredictedDY, qz = chain.PredictedDZ;
            bool[] kinematic = chain.Kinematic;
            bool bdf2 = scheme == TimeIntegrator.Bdf2;
            double invH = 1.0 / h, h2 = h * h, c = 4.0 * h2 / 9.0, e = 2.0 * h / 3.0;
            float size = 0f;
            for (int i = 0; i < n; i++)
            {
                px[i] = x[i]; py[i] = y[i]; pz[i] = z[i];
                size = Larger(size, x[i], y[i], z[i]);
                double wx = vx[i], wy = vy[i], wz = vz[i];
                if (kinematic[i])
                {
                    dx[i] = 0f; dy[i] = 0f; dz[i] = 0f;
                    bx[i] = 0.0; by[i] = 0.0; bz[i] = 0.0;
                }
                else if (bdf2)
                {
                    double mx = (4.0 * wx - ux[i]) / 3.0, my = (4.0 * wy - uy[i]) / 3.0, mz = (4.0 * wz - uz[i]) / 3.0;
                    dx[i] = (float)(dx[i] / 3.0 + e * mx + c * g.X);
                    dy[i] = (float)(dy[i] / 3.0 + e * my + c * g.Y);
                    dz[i] = (float)(dz[i] / 3.0 + e * mz + c * g.Z);
                    bx[i] = mx + e * g.X - dx[i] * invH;
                    by[i] = my + e * g.Y - dy[i] * invH;
                    bz[i] = mz + e * g.Z - dz[i] * invH;
                }
                else
                {
                    dx[i] = (float)(h * wx + h2 * g.X); dy[i] = (float)(h * wy + h2 * g.Y); dz[i] = (float)(h * wz + h2 * g.Z);
                    bx[i] = 0.0; by[i] = 0.0; bz[i] = 0.0;
                }
                ux[i] = (float)wx; uy[i] = (float)wy; uz[i] = (float)wz;
                qx[i] = dx[i]; qy[i] = dy[i]; qz[i] = dz[i];
            }
            chain.Size = size;
            Array.Clear(chain.SolveDX, 0, n);
            Array.Clear(chain.SolveDY, 0, n);
            Array.Clear(chain.SolveDZ, 0, n);
        }

        /// <summary>
        /// The host changed particle i's velocity by (dx, dy, dz) m/s: the same change is applied to its history (v_prev, and
        /// d_prev = x_n − x_{n−1} by h·Δv), a Galilean boost that keeps BDF2's acceleration memory. A moved position needs
        /// nothing: d_prev is a difference.
        /// </summary>
        private void BoostHistory(int i, float dx, float dy, float dz)
        {
            chain.PrevVelX[i] += dx; chain.PrevVelY[i] += dy; chain.PrevVelZ[i] += dz;
            float h = (float)historyStep;
            chain.DX[i] += dx * h; chain.DY[i] += dy * h; chain.DZ[i] += dz * h;
        }

        /// <summary>Marks the start (sign −1) or the end (+1) of a chain solve: Δ accumulates the displacement it applies.</summary>
        private void TrackSolveDisplacement(double sign)
        {
            int n = chain.ParticleCount;
            float[] dx = chain.DX, dy = chain.DY, dz = chain.DZ;
            double[] sx = chain.SolveDX, sy = chain.SolveDY, sz = chain.SolveDZ;
            for (int i = 0; i < n; i++)
            {
                sx[i] += sign * dx[i]; sy[i] += sign * dy[i]; sz[i] += sign * dz[i];
            }
        }

        /// <summary>
        /// Velocities of a second-order run: v = base + d/h + κ·Δ/h (κ = 1/2 for BDF2, 0 for a backward-Euler substep),
        /// x = x_prev + d (h s); violent: the next substep restarts with backward Euler. A non-finite result falls back to the last good position at rest.
        /// </summary>
        private void UpdateVelocitiesSecondOrder(TimeIntegrator scheme, double h, bool violent)
        {
            int n = chain.ParticleCount;
            float[] dx = chain.DX, dy = chain.DY, dz = chain.DZ;
            double[] bx = chain.BaseVelX, by = chain.BaseVelY, bz = chain.BaseVelZ;
            double[] sx = chain.SolveDX, sy = chain.SolveDY, sz = chain.SolveDZ;
            float[] wx = chain.PrevVelX, wy = chain.PrevVelY, wz = chain.PrevVelZ;
            float[] qx = chain.PredictedDX, qy = chain.PredictedDY, qz = chain.PredictedDZ;
            bool[] kinematic = chain.Kinematic;
            double invH = 1.0 / h, k = scheme == TimeIntegrator.Bdf2 ? 0.5 * invH : 0.0;
            for (int i = 0; i < n; i++)
            {
                // what moved the particle besides the prediction and the chain solve (collider push-out, friction, a pin
                // target) is a velocity kick c/h, as in backward Euler; boosting the history by it too (v_prev += c/h) makes
                // the next prediction carry it exactly once instead of 11/9 times
                double cx = dx[i] - qx[i] - sx[i], cy = dy[i] - qy[i] - sy[i], cz = dz[i] - qz[i] - sz[i];
                if (kinematic[i])
                {
                    wx[i] = (float)(dx[i] * invH); wy[i] = (float)(dy[i] * invH); wz[i] = (float)(dz[i] * invH);
                }
                else if (cx != 0.0 || cy != 0.0 || cz != 0.0)
                {
                    wx[i] += (float)(cx * invH); wy[i] += (float)(cy * invH); wz[i] += (float)(cz * invH);
                }
                CommitParticle(i, (float)(bx[i] + dx[i] * invH + k * sx[i]), (float)(by[i] + dy[i] * invH + k * sy[i]), (float)(bz[i] + dz[i] * invH + k * sz[i]));
            }
            // a violent substep (see ViolentStrain) restarts the history: the next substep is backward Euler
            historyValid = !violent;
            historyStep = h;
        }
    }
}
