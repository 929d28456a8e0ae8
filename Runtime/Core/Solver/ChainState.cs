using System;

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
        public readonly float[] Length;           // m, current
        public readonly bool[] Broken;
        public readonly float[] DirX, DirY, DirZ; // last valid unit direction x_j → x_{j+1}

        // scratch for the exact solve (double)
        public readonly double[] Lower, Diagonal, Upper, Rhs, Delta, Scratch, FullDiagonal, FullLower, FullUpper, FullRhs;
        public readonly bool[] Active;

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
            DX = new float[n]; DY = new float[n]; DZ = new float[n];
            VelX = new float[n]; VelY = new float[n]; VelZ = new float[n];
            Mass = new float[n]; InverseMass = new float[n]; LoadMass = new float[n];
            Kinematic = new bool[n]; Radius = new float[n];
            RestLength = new float[s]; Compliance = new float[s]; Lambda = new double[s];
            Tension = new float[s]; Length = new float[s]; Broken = new bool[s];
            DirX = new float[s]; DirY = new float[s]; DirZ = new float[s];
            Lower = new double[s]; Diagonal = new double[s]; Upper = new double[s];
            Rhs = new double[s]; Delta = new double[s]; Scratch = new double[s];
            FullDiagonal = new double[s]; FullLower = new double[s]; FullUpper = new double[s]; FullRhs = new double[s];
            Active = new bool[s];
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

        /// <summary>Unit direction of segment j (live positions Prev + D) into (nx, ny, nz) and its length; keeps the last valid direction when the ends coincide.</summary>
        public float Direction(int j, out float nx, out float ny, out float nz)
        {
            float dx = (PrevX[j + 1] - PrevX[j]) + (DX[j + 1] - DX[j]);
            float dy = (PrevY[j + 1] - PrevY[j]) + (DY[j + 1] - DY[j]);
            float dz = (PrevZ[j + 1] - PrevZ[j]) + (DZ[j + 1] - DZ[j]);
            float len = MathF.Sqrt(dx * dx + dy * dy + dz * dz);
            if (len > 1e-12f && float.IsFinite(len))
            {
                float inv = 1f / len;
                nx = dx * inv; ny = dy * inv; nz = dz * inv;
                DirX[j] = nx; DirY[j] = ny; DirZ[j] = nz;
            }
            else
            {
                nx = DirX[j]; ny = DirY[j]; nz = DirZ[j];
                if (!float.IsFinite(len)) len = 0f;
            }
            return len;
        }
    }
}
