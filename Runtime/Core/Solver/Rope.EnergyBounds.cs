using System;

namespace HookeRope.Solver
{
    public sealed partial class Rope
    {
        /// <summary>
        /// Units in the last place of the rope's largest coordinate (rope-local frame; one ulp is 2⁻²³·m to 2⁻²⁴·m for a
        /// coordinate of magnitude m) that <see cref="ElasticEnergyBounds"/> allows a length to be off by: the exact solve
        /// stops refining a length at 4 ulps (<c>ExactChainSolver.RoundOffFloor</c>, its round-off floor) and each substep's
        /// displacement is stored in float32, so 8 covers both. (The positions themselves carry sub-float remainders, so
        /// this is looser than their own resolution.)
        /// </summary>
        public const float RoundOffUlps = 8f;

        /// <summary>
        /// The elastic energy in joules of every state within the solve's round-off of this one lies in [lower, upper]:
        /// Σ ½·(|C_j| ∓ ε_j)²/α_j over the segments (stretched ones for a tension-only rope; the lower bound takes
        /// (|C| − ε)₊; C measured from the exact positions X + Low and the plastic rest length) plus the compliant pins'
        /// ½·(|x − p| ∓ ε)²/α, with ε = <see cref="RoundOffUlps"/>·2⁻²³·m, m the largest |coordinate| of the rope's
        /// particles and pin targets (rope-local). <see cref="ElasticEnergy"/> (Σ ½C²/α) lies in between. For energy
        /// checks: compare the lower bound now with the upper bound of the energy put in. The bounds are |F|·ε + ½ε²/α
        /// apart per segment: for a 1 m, 256-segment steel rope (α = 2.5e-10 m/N) ½ε²/α alone is 1.8 mJ per segment.
        /// </summary>
        public void ElasticEnergyBounds(out double lower, out double upper)
        {
            lower = 0.0;
            upper = 0.0;
            bool tensionOnly = settings.Tension == TensionModel.TensionOnly;
            float[] x = chain.X, y = chain.Y, z = chain.Z;
            float size = 0f;
            for (int i = 0; i < chain.ParticleCount; i++) size = MathF.Max(size, Largest(x[i], y[i], z[i]));
            for (int p = 0; p < pinCount; p++) size = MathF.Max(size, Largest(pinEnd[p].X, pinEnd[p].Y, pinEnd[p].Z));
            double eps = RoundOffUlps * (1.0 / 8388608.0) * size;
            for (int j = 0; j < chain.SegmentCount; j++)
            {
                if (chain.Broken[j] || chain.Compliance[j] == 0f) continue;
                chain.Span(j, out double dx, out double dy, out double dz);
                double c = Math.Sqrt(dx * dx + dy * dy + dz * dz) - chain.CurrentRest(j);
                Accumulate(tensionOnly ? c : Math.Abs(c), eps, chain.Compliance[j], ref lower, ref upper);
            }
            for (int p = 0; p < pinCount; p++)
            {
                if (pinBroken[p] || pinCompliance[p] == 0f) continue;
                int i = pinParticle[p];
                double dx = ((double)x[i] + chain.LowX[i]) - pinEnd[p].X, dy = ((double)y[i] + chain.LowY[i]) - pinEnd[p].Y, dz = ((double)z[i] + chain.LowZ[i]) - pinEnd[p].Z;
                Accumulate(Math.Sqrt(dx * dx + dy * dy + dz * dz), eps, pinCompliance[p], ref lower, ref upper);
            }
        }

        /// <summary>Adds ½(c ∓ ε)²/α for a stretch c (m; only c + ε &gt; 0 stores energy) to the bounds.</summary>
        private static void Accumulate(double c, double eps, double compliance, ref double lower, ref double upper)
        {
            double low = c - eps, high = c + eps;
            if (low > 0.0) lower += 0.5 * low * low / compliance;
            if (high > 0.0) upper += 0.5 * high * high / compliance;
        }

        private static float Largest(float x, float y, float z) => MathF.Max(MathF.Abs(x), MathF.Max(MathF.Abs(y), MathF.Abs(z)));

    }
}
