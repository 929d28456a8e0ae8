using System;
using System.Runtime.CompilerServices;

namespace HookeRope.Solver
{
    /// <summary>
    /// Inverse mass of one particle without a contact, W = w t tᵀ + w_t (I − t tᵀ) (1/kg): w along the rope tangent t,
    /// w_t across it (<see cref="ChainState.UpdateTransverseMass"/>). A particle without the stabilisation has
    /// w_t = w and t = 0, so W = w I. Its quadratic form has the closed form
    /// n_aᵀ W n_b = w_t (n_a·n_b) + (w − w_t)(t·n_a)(t·n_b), and <see cref="Apply"/> gives W v.
    /// </summary>
    internal readonly struct TransverseMobility
    {
        /// <summary>Inverse mass across the tangent, w_t (1/kg).</summary>
        public readonly double Transverse;
        /// <summary>w − w_t (1/kg), ≥ 0: the extra mobility along the tangent.</summary>
        public readonly double Anisotropy;
        /// <summary>Unit tangent (zero without the stabilisation).</summary>
        public readonly double TangentX, TangentY, TangentZ;
        /// <summary>True when the particle has the stabilisation (otherwise W = w I exactly).</summary>
        public readonly bool Stabilised;

        private TransverseMobility(double transverse, double anisotropy, double tx, double ty, double tz, bool stabilised)
        {
            Transverse = transverse; Anisotropy = anisotropy;
            TangentX = tx; TangentY = ty; TangentZ = tz;
            Stabilised = stabilised;
        }

        /// <summary>The mobility of particle i with its current inverse mass (a compliant pin may have lowered it).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static TransverseMobility Of(ChainState c, int i)
        {
            double w = c.InverseMass[i];
            if (!c.Augmented[i]) return new TransverseMobility(w, 0.0, 0.0, 0.0, 0.0, false);
            double wt = Math.Min(c.TransverseInverseMass[i], w);
            return new TransverseMobility(wt, w - wt, c.TangentX[i], c.TangentY[i], c.TangentZ[i], true);
        }

        /// <summary>t·v.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public double Along(double vx, double vy, double vz) => TangentX * vx + TangentY * vy + TangentZ * vz;

        /// <summary>r = W v (v in N·s² gives r in m): w_t v + (w − w_t)(t·v) t, or w v without the stabilisation.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Apply(double vx, double vy, double vz, out double rx, out double ry, out double rz)
        {
            if (!Stabilised)
            {
                rx = Transverse * vx; ry = Transverse * vy; rz = Transverse * vz;
                return;
            }
            double along = Anisotropy * Along(vx, vy, vz);
            rx = Transverse * vx + along * TangentX;
            ry = Transverse * vy + along * TangentY;
            rz = Transverse * vz + along * TangentZ;
        }

        /// <summary>n_aᵀ W n_b (1/kg) from t·n_a, t·n_b and n_a·n_b.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public double Quadratic(double alongA, double alongB, double dot) => Transverse * dot + Anisotropy * alongA * alongB;
    }
}
