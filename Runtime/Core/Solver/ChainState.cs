using System;
using System.Runtime.CompilerServices;

namespace HookeRope.Solver
{
    /// <summary>
    /// Structure-of-arrays state of one particle chain in the rope-local frame (metres, m/s, kg).
    /// Allocated once when a rope is built; the step only reads and writes these arrays.
    /// </summary>
    internal sealed class ChainState
    {
        public readonly int ParticleCount;
        public readonly int SegmentCount;

        // particles (rope-local metres, m/s, kg, 1/kg)
        public readonly float[] X, Y, Z;
        public readonly float[] PrevX, PrevY, PrevZ;
        // positions at the start of the last host step (or where the host last placed them), for interpolation
        public readonly float[] StepStartX, StepStartY, StepStartZ;
        // displacement over the current substep: live position = Prev + D. Kept separately so that
        // velocities D/h keep full float precision however small h is.
        public readonly float[] DX, DY, DZ;
        public readonly float[] VelX, VelY, VelZ;
        public readonly float[] Mass;
        public readonly float[] InverseMass;
        public readonly float[] LoadMass;
        public readonly bool[] Kinematic;
        public readonly float[] Radius;

        // segments
        public readonly float[] RestLength;       // m
        public readonly float[] Compliance;       // m/N, α = L/(E·A); 0 = inextensible
        public readonly double[] Lambda;          // N·s², accumulated over the substep, ≤ 0 pulls
        public readonly float[] Tension;          // N, ≥ 0 pulls
        public readonly float[] PeakTension;      // N, largest substep tension of the last host step
        public readonly float[] MeanTension;      // N, mean substep tension of the last host step (sum while stepping)
        public readonly float[] Length;           // m, current
        public readonly bool[] Broken;
        public int BrokenCount;                   // segments with Broken set
        public readonly float[] DirX, DirY, DirZ; // last valid unit direction x_j → x_{j+1}

        // exact solve (double): the tridiagonal system (Full*), the Thomas sweep's c′ and d′ (Upper, Rhs), its solution Δλ (Delta)
        public readonly double[] Upper, Rhs, Delta, FullDiagonal, FullLower, FullUpper, FullRhs;
        public readonly bool[] Active;

        // transverse stabilisation (see UpdateTransverseMass)
        public readonly float[] TransverseInverseMass;  // 1/kg, w_t across the tangent where Augmented
        public readonly float[] TangentX, TangentY, TangentZ;
        public readonly bool[] Augmented;
        public int AugmentedCount;

        // second-order integrator (see Rope.Integration): the chain solve's displacement of this substep Δ (m), the velocity
        // the scheme adds to d/h + κΔ/h (m/s), and the velocity of the substep before (m/s)
        public readonly double[] SolveDX, SolveDY, SolveDZ;
        public readonly double[] BaseVelX, BaseVelY, BaseVelZ;
        public readonly float[] PrevVelX, PrevVelY, PrevVelZ;
        public readonly float[] PredictedDX, PredictedDY, PredictedDZ; // m, the scheme's prediction d_pred of this substep

        // contacts (allocated by EnsureContacts when the rope gets its first collider; null before)
        public float[] ContactNX, ContactNY, ContactNZ; // outward unit surface normal at the particle
        public float[] ContactGap;                      // m, distance − radius (≥ 0) when the contact was detected
        public float[] ContactLoad;                     // m, normal correction the contact took this substep (friction limit)
        public int[] ContactCollider;                   // collider index, −1 = no contact
        public bool[] ContactActive;                    // contact used by the current chain solve (tangent-plane mass)
        public int[] ContactList;                       // particles with ContactCollider ≥ 0, first ContactCount entries
        public int ContactCount;

        public ChainState(int segmentCount)
        {
            SegmentCount = segmentCount;
            ParticleCount = segmentCount + 1;
            int n = ParticleCount, s = segmentCount;
            X = new float[n]; Y = new float[n]; Z = new float[n];
            PrevX = new float[n]; PrevY = new float[n]; PrevZ = new float[n];
            StepStartX = new float[n]; StepStartY = new float[n]; StepStartZ = new float[n];
            DX = new float[n]; DY = new float[n]; DZ = new float[n];
            VelX = new float[n]; VelY = new float[n]; VelZ = new float[n];
            Mass = new float[n]; InverseMass = new float[n]; LoadMass = new float[n];
            Kinematic = new bool[n]; Radius = new float[n];
            RestLength = new float[s]; Compliance = new float[s]; Lambda = new double[s];
            Tension = new float[s]; PeakTension = new float[s]; MeanTension = new float[s]; Length = new float[s]; Broken = new bool[s];
            DirX = new float[s]; DirY = new float[s]; DirZ = new float[s];
            Upper = new double[s]; Rhs = new double[s]; Delta = new double[s];
            FullDiagonal = new double[s]; FullLower = new double[s]; FullUpper = new double[s]; FullRhs = new double[s];
            Active = new bool[s];
            TransverseInverseMass = new float[n]; TangentX = new float[n]; TangentY = new float[n]; TangentZ = new float[n];
            Augmented = new bool[n];
            SolveDX = new double[n]; SolveDY = new double[n]; SolveDZ = new double[n];
            BaseVelX = new double[n]; BaseVelY = new double[n]; BaseVelZ = new double[n];
            PrevVelX = new float[n]; PrevVelY = new float[n]; PrevVelZ = new float[n];
            PredictedDX = new float[n]; PredictedDY = new float[n]; PredictedDZ = new float[n];
        }

        /// <summary>
        /// Cap of the transverse inertia as a multiple of the particle's mass where the rope bends by the most a particle
        /// keeps the stabilisation for (60°). Where the rope direction changes within a substep (a kink, a yanked anchor)
        /// the constraint direction leaves the tangent, and a larger ratio would let the solve throw the particle along
        /// the tangent (displacement amplified by up to sqrt(ratio)).
        /// </summary>
        public const double MinTransverseInertia = 16.0;

        /// <summary>
        /// Cap of the transverse inertia ratio where the rope is straight. A light lanyard arresting a heavy load needs
        /// ratios far above 16 (a 0.46 kg, 24-segment lanyard carrying 11.9 kN at 8 substeps of 1/90 s needs about 33):
        /// capped at 16 everywhere, its tension saturated near 16·m·ℓ/(3h²) (6.5 kN there) and the arrest read 28 % low.
        /// </summary>
        public const double MaxTransverseInertia = 1024.0;

        /// <summary>
        /// The ratio cap between the two is <see cref="MinTransverseInertia"/>·sin²(30°)/sin²(θ/2) for a bend θ between the
        /// particle's two segments: the tangent leaves a constraint direction by θ/2, so the amplification stays that of
        /// the 60° bend.
        /// </summary>
        private const double BendInertiaScale = MinTransverseInertia * 0.25;

        /// <summary>|n_{i−1} + n_i| below which a particle is a kink (segments more than 60° apart) and keeps its plain mass.</summary>
        private const double MinStraightness = 1.7320508;

        /// <summary>
        /// The exact solve linearises each segment along its direction, so a taut chain's transverse (bending) response is
        /// explicit: its zig-zag mode has k = h²·Σ2T/ℓ / m per particle and grows once k &gt; 4/3 (tension above about
        /// m·ℓ/(3h²)), saturating at that tension with the particles flipping every substep. Where k would exceed 1 this
        /// gives the particle the transverse inertia h²·Σ2T/ℓ (row-sum lumped geometric stiffness, tensions T in N of the
        /// last substep, lengths ℓ in m): inverse mass w along the tangent, w_t = 1/(h²·Σ2T/ℓ) across it. Along the rope
        /// nothing changes and static equilibria are untouched; a particle within the limit keeps its plain mass.
        /// </summary>
        public void UpdateTransverseMass(double h)
        {
            double h2 = h * h;
            int s = SegmentCount;
            int count = 0;
            double previous = 0.0; // geometric stiffness 2T/ℓ of segment i − 1 (N/m)
            // unit direction of segment i − 1 (predicted positions) when the previous particle computed it
            bool havePrevious = false;
            double ux = 0.0, uy = 0.0, uz = 0.0;
            for (int i = 0; i < ParticleCount; i++)
            {
                double next = i < s ? GeometricStiffness(i) : 0.0;
                double stiffness = previous + next;
                previous = next;
                // the common case (a slack or lightly loaded rope) costs one multiply and compare per particle
                if (!(stiffness * h2 > Mass[i]) || InverseMass[i] == 0f)
                {
                    Augmented[i] = false;
                    havePrevious = false;
                    continue;
                }
                // tangent t = n_{i−1} + n_i from the predicted positions: the rope direction this substep solves along
                double tx = 0.0, ty = 0.0, tz = 0.0;
                bool interior = i > 0 && i < s && !Broken[i - 1] && !Broken[i];
                if (i > 0 && !Broken[i - 1])
                {
                    if (!havePrevious) PredictedDirection(i - 1, out ux, out uy, out uz);
                    tx += ux; ty += uy; tz += uz;
                }
                havePrevious = i < s && !Broken[i];
                if (havePrevious)
                {
                    PredictedDirection(i, out ux, out uy, out uz);
                    tx += ux; ty += uy; tz += uz;
                }
                // only where the rope is locally straight-ish: two unit directions at ≤ 60° sum to a length ≥ √3
                double norm2 = tx * tx + ty * ty + tz * tz;
                double limit = interior ? MinStraightness : 0.5;
                if (!(norm2 > limit * limit))
                {
                    Augmented[i] = false;
                    continue;
                }
                // sin²(θ/2) = 1 − |n_{i−1} + n_i|²/4 for unit directions; an end particle has one direction and no bend
                double bend = interior ? 1.0 - 0.25 * norm2 : 0.0;
                double ratio = bend > BendInertiaScale / MaxTransverseInertia ? Math.Max(MinTransverseInertia, BendInertiaScale / bend) : MaxTransverseInertia;
                double inertia = Math.Min(stiffness * h2, ratio * Mass[i]);
                double inverseNorm = 1.0 / Math.Sqrt(norm2);
                TangentX[i] = (float)(tx * inverseNorm); TangentY[i] = (float)(ty * inverseNorm); TangentZ[i] = (float)(tz * inverseNorm);
                TransverseInverseMass[i] = (float)(1.0 / inertia);
                Augmented[i] = true;
                count++;
            }
            AugmentedCount = count;
        }

        /// <summary>Unit direction of segment j from the predicted positions Prev + D (double); the last valid direction when its ends coincide.</summary>
        private void PredictedDirection(int j, out double nx, out double ny, out double nz)
        {
            double ex = (double)(PrevX[j + 1] - PrevX[j]) + (DX[j + 1] - DX[j]);
            double ey = (double)(PrevY[j + 1] - PrevY[j]) + (DY[j + 1] - DY[j]);
            double ez = (double)(PrevZ[j + 1] - PrevZ[j]) + (DZ[j + 1] - DZ[j]);
            double len = Math.Sqrt(ex * ex + ey * ey + ez * ez);
            if (len > 1e-12 && len < double.PositiveInfinity)
            {
                double inverse = 1.0 / len;
                nx = ex * inverse; ny = ey * inverse; nz = ez * inverse;
            }
            else
            {
                nx = DirX[j]; ny = DirY[j]; nz = DirZ[j];
            }
        }

        private double GeometricStiffness(int j)
        {
            if (Broken[j]) return 0.0;
            double t = Tension[j];
            if (!(t > 0.0)) return 0.0;
            double l = Math.Max(Length[j], 0.1 * RestLength[j]);
            return 2.0 * t / l;
        }

        /// <summary>Allocates the contact arrays once (when the first collider is added; never in a step).</summary>
        public void EnsureContacts()
        {
            if (ContactCollider != null) return;
            int n = ParticleCount;
            ContactNX = new float[n]; ContactNY = new float[n]; ContactNZ = new float[n];
            ContactGap = new float[n]; ContactLoad = new float[n];
            ContactCollider = new int[n]; ContactActive = new bool[n]; ContactList = new int[n];
            for (int i = 0; i < n; i++) ContactCollider[i] = -1;
            ContactCount = 0;
        }

        /// <summary>Forgets every contact (no collider left).</summary>
        public void ClearContacts()
        {
            if (ContactCollider == null) return;
            for (int k = 0; k < ContactCount; k++)
            {
                int i = ContactList[k];
                ContactCollider[i] = -1;
                ContactActive[i] = false;
            }
            ContactCount = 0;
        }

        /// <summary>
        /// Multiplier change (N·s²) d of a segment whose accumulated multiplier is lambda (≤ 0 pulls): a tension-only segment
        /// stops at λ + d = 0 instead of pushing; otherwise d unchanged.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double LimitToPulling(double lambda, double d, bool tensionOnly) => tensionOnly && lambda + d > 0.0 ? -lambda : d;

        /// <summary>
        /// Length (m) of segment j from the live positions Prev + D, and its unit direction into (nx, ny, nz), which it also
        /// stores as the segment's last valid direction; when the ends coincide (or the length is not finite) the last valid
        /// direction is kept and a non-finite length reads 0. (ddx, ddy, ddz) is the segment's change over the substep,
        /// D_{j+1} − D_j (m), which the damping term needs.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public float Direction(int j, out float nx, out float ny, out float nz, out float ddx, out float ddy, out float ddz)
        {
            ddx = DX[j + 1] - DX[j]; ddy = DY[j + 1] - DY[j]; ddz = DZ[j + 1] - DZ[j];
            float ex = (PrevX[j + 1] - PrevX[j]) + ddx, ey = (PrevY[j + 1] - PrevY[j]) + ddy, ez = (PrevZ[j + 1] - PrevZ[j]) + ddz;
            float len = MathF.Sqrt(ex * ex + ey * ey + ez * ez);
            if (len > 1e-12f && len <= float.MaxValue)
            {
                float inv = 1f / len;
                nx = ex * inv; ny = ey * inv; nz = ez * inv;
                DirX[j] = nx; DirY[j] = ny; DirZ[j] = nz;
            }
            else
            {
                nx = DirX[j]; ny = DirY[j]; nz = DirZ[j];
                if (!(len <= float.MaxValue)) len = 0f;
            }
            return len;
        }
    }
}
