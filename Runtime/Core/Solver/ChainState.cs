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

        // exact solve (double, N·s² per segment; see ExactChainSolver): the segment force vectors Λ = h²·F accumulated over
        // the substep's iterations, this iteration's change δΛ, the residual R (m), the block Thomas sweep's inverse
        // pivots (6 per segment, symmetric 3×3) and reduced right-hand sides, the axial and transverse compliances of
        // Λ (m per N·s²), and the active flags (tension-only, valid rows)
        public readonly double[] ForceX, ForceY, ForceZ, StepX, StepY, StepZ, ResidualX, ResidualY, ResidualZ;
        public readonly double[] PivotInverse, ReducedX, ReducedY, ReducedZ;
        public readonly double[] AxialCompliance, TransverseCompliance, EstimatedTension;
        public readonly bool[] Active;
        // the convergence test and line search of the exact solve (see ExactChainSolver.Check, ChainLineSearch): each
        // segment's effective rest length L' (m, damping folded in) and whether it was assembled this iteration (not broken,
        // not an invalid row), and the iteration's motion of each particle (m)
        public readonly double[] EffectiveRest;
        public readonly double[] LengthError;     // m, the iteration's length error of each pulling or released segment
        public readonly bool[] Assembled;
        public readonly double[] MotionX, MotionY, MotionZ;
        public bool RigidInSolve;                 // some inextensible segment (α = 0) is in the solve: no merit, no line search
        public double Size;                       // m, largest |coordinate| of the particles at the start of the substep

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
            ForceX = new double[s]; ForceY = new double[s]; ForceZ = new double[s];
            StepX = new double[s]; StepY = new double[s]; StepZ = new double[s];
            ResidualX = new double[s]; ResidualY = new double[s]; ResidualZ = new double[s];
            PivotInverse = new double[6 * s]; ReducedX = new double[s]; ReducedY = new double[s]; ReducedZ = new double[s];
            AxialCompliance = new double[s]; TransverseCompliance = new double[s]; EstimatedTension = new double[s];
            Active = new bool[s];
            EffectiveRest = new double[s]; LengthError = new double[s]; Assembled = new bool[s];
            MotionX = new double[n]; MotionY = new double[n]; MotionZ = new double[n];
            SolveDX = new double[n]; SolveDY = new double[n]; SolveDZ = new double[n];
            BaseVelX = new double[n]; BaseVelY = new double[n]; BaseVelZ = new double[n];
            PrevVelX = new float[n]; PrevVelY = new float[n]; PrevVelZ = new float[n];
            PredictedDX = new float[n]; PredictedDY = new float[n]; PredictedDZ = new float[n];
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
