using System;
using System.Numerics;
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
        // the part of each position below float resolution (m): the particle is at X + Low, |Low| ≤ half an ulp of X
        // (the live position in a substep is Prev + Low + D). Without it every commit rounded the position to float and a
        // displacement below half an ulp of it was lost: a steel cable's load, 10 m down, could not settle closer than the
        // solve's damping-amplified dead band (up to 0.3 % of its stretch). Zero where the host places a particle.
        public readonly float[] LowX, LowY, LowZ;
        // displacement over the current substep: live position = Prev + Low + D + DLow. Kept separately so that
        // velocities D/h keep full float precision however small h is.
        public readonly float[] DX, DY, DZ;
        // the part of D below its float resolution (m), |DLow| ≤ half an ulp of D, written by the chain solves, the compliant
        // and rigid pins, the history boost and backward Euler's prediction (AddDisplacement, SetDisplacement); zero after a
        // second-order prediction, whose velocity base absorbs its rounding. Without it every solver correction was rounded
        // to D's ulp (4e-12 m at 4e-5 m), and as the velocity reads the correction over h that was a velocity error of up to
        // 1e-7 m/s per substep, with the same sign substep after substep: the segment angles of a swinging rope drifted by
        // 2e-4 rad at 512 substeps of 1/45 s. A writer that does not know it (a collider) leaves it: at most half an ulp of D.
        public readonly float[] DLowX, DLowY, DLowZ;
        // velocities (m/s) in double: the integrator's state. A substep changes a velocity by a·h (2e-4 m/s at 1000 substeps of
        // 1/45 s), and rounding the sum to float (a step of up to 9.5e-7 m/s at 10 m/s) every substep erred the same way
        // substep after substep: a free fall read v off g·t by 1e-4 after 1 s
        public readonly double[] VelX, VelY, VelZ;
        public readonly float[] Mass;
        public readonly float[] InverseMass;
        public readonly float[] LoadMass;
        public readonly bool[] Kinematic;
        // the kinematic particles' indices in ascending order (KinematicIndices, kept by ListKinematic), so the lane passes
        // fix their kinematic particles up without scanning the flags
        private readonly int[] kinematicParticles;
        private int kinematicCount;

        /// <summary>The indices of the particles flagged <see cref="Kinematic"/>, ascending, as of the last <see cref="ListKinematic"/>.</summary>
        public ReadOnlySpan<int> KinematicIndices => new ReadOnlySpan<int>(kinematicParticles, 0, kinematicCount);

        /// <summary>Lists the particles flagged <see cref="Kinematic"/> (in <see cref="KinematicIndices"/>): after every change of the flags.</summary>
        public void ListKinematic()
        {
            int count = 0;
            for (int i = 0; i < ParticleCount; i++)
                if (Kinematic[i]) kinematicParticles[count++] = i;
            kinematicCount = count;
        }
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
        // pivots (symmetric 3×3) and reduced right-hand sides, side by side per segment (kept for the next active-set pass, which redoes
        // only the rows from the first changed one), the axial and transverse compliances of
        // Λ (m per N·s²), and the active flags (tension-only, valid rows)
        public readonly double[] ForceX, ForceY, ForceZ, StepX, StepY, StepZ, ResidualX, ResidualY, ResidualZ;
        public readonly SegmentForceSystem.EliminatedRow[] Eliminated;
        public readonly double[] AxialCompliance, TransverseCompliance, EstimatedTension;
        // each row's free block A_j = (w_j + w_{j+1}) I + α̃ n nᵀ + τ (I − n nᵀ) (symmetric 3×3, 1/kg), built once per
        // linearisation for every active-set pass (SegmentForceSystem.PrepareBlocks)
        public readonly double[] BlockXX, BlockXY, BlockXZ, BlockYY, BlockYZ, BlockZZ;
        // the float inputs of the assembly run on lanes (ExactChainSolver.AssembleLanes), read once per run for both of its
        // halves: a field, not a local of the assembly, which would zero it on every call
        public ExactChainSolver.RunInputs AssemblyRun;
        // the two halves' results of that run (ExactChainSolver.AssembleHalf), for the same reason
        public ExactChainSolver.AssembledLanes AssemblyLow, AssemblyHigh;
        public readonly bool[] Active;
        // the convergence test and line search of the exact solve (see ExactChainSolver.Apply and Mismatched, ChainLineSearch): each
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
        public readonly double[] PrevVelX, PrevVelY, PrevVelZ;
        public readonly float[] PredictedDX, PredictedDY, PredictedDZ; // m, the scheme's prediction d_pred of this substep

        // contacts (allocated by EnsureContacts when the rope gets its first collider; null before)
        public float[] ContactNX, ContactNY, ContactNZ; // outward unit surface normal at the particle
        public float[] ContactGap;                      // m, distance − radius (≥ 0) when the contact was detected
        public float[] ContactLoad;                     // m, normal correction the contact took this substep (friction limit)
        public bool[] ContactResting;                   // ContactLoad > 0 at the end of the substep before: pushed out then too (Rope.RemoveVelocityIntoSurface; BDF2 runs with colliders)
        public bool[] ContactNear;                      // the particle was in the contact set at the end of the substep before (Rope.NewImpact; BDF2 runs with colliders)
        public int[] ContactCollider;                   // collider index, −1 = no contact
        public bool[] ContactActive;                    // contact used by the current chain solve (tangent-plane mass)
        public int[] ContactList;                       // particles with ContactCollider ≥ 0, first ContactCount entries
        public int ContactCount;

        // friction in the exact solve (see ChainContacts; allocated with the contacts). Per contact of the current set:
        // its friction state (sticking: the stiff damper; sliding: the damper whose friction is the kinetic cone; neither:
        // none yet), the tangential mobility of a held contact (1/kg: 1/(m + ζ)), the displacement the contact prescribes
        // in this iteration (m: onto the surface, and for a held one what its friction does; folded into the residual), the
        // collider's friction coefficients and its displacement over the substep at the contact (m). Per particle: the
        // contact impulse of this substep (N·s², h² times the force: push-outs, normal reaction, friction) and its friction
        // part, whether the contact was released in this substep, and, kept from one detection to the next, the contact's
        // state (0 none, 1 held, 2 sticking, 3 sliding) and its damping ζ (kg).
        public bool[] ContactSticking, ContactSliding;
        public double[] ContactMobility;
        public double[] ContactShiftX, ContactShiftY, ContactShiftZ;
        public float[] ContactKineticFriction, ContactStaticFriction;
        public float[] ContactSurfaceX, ContactSurfaceY, ContactSurfaceZ;
        public double[] ContactImpulseX, ContactImpulseY, ContactImpulseZ;
        public double[] ContactFrictionX, ContactFrictionY, ContactFrictionZ;
        public bool[] ContactStopped;                   // released in this substep (stays free in it)
        public byte[] ContactMemory;
        public double[] ContactDamping;
        // a sliding contact's ζ (kg) and friction ζ|s| (N·s²) of the pass before in this iteration (0: none), the secant's
        // other point (ChainContacts.Secant)
        public double[] ContactLastDamping, ContactLastForce;
        public bool Bdf2Substep;                        // this substep runs BDF2 (where a contact particle is at rest depends on it)
        public double Substep;                          // s, this substep's h
        public double ContactNormalScale;               // N·s², the largest normal impulse of the last substep's contacts
        public bool HeldWithFriction;                   // the last substep ended with a held contact pressed onto a surface with friction
        public double ContactImpulseScale = 1.0;        // (h_eff/h)²: the impulse (in the solve's h_eff² units) of a push-out per m·push
        // plastic state of the segments (issue 15; null for an elastic rope without an energy absorber: no work, no memory)
        public SegmentPlasticity Plasticity;

        public ChainState(int segmentCount)
        {
            SegmentCount = segmentCount;
            ParticleCount = segmentCount + 1;
            int n = ParticleCount, s = segmentCount;
            X = new float[n]; Y = new float[n]; Z = new float[n];
            PrevX = new float[n]; PrevY = new float[n]; PrevZ = new float[n];
            StepStartX = new float[n]; StepStartY = new float[n]; StepStartZ = new float[n];
            LowX = new float[n]; LowY = new float[n]; LowZ = new float[n];
            DX = new float[n]; DY = new float[n]; DZ = new float[n];
            DLowX = new float[n]; DLowY = new float[n]; DLowZ = new float[n];
            VelX = new double[n]; VelY = new double[n]; VelZ = new double[n];
            Mass = new float[n]; InverseMass = new float[n]; LoadMass = new float[n];
            Kinematic = new bool[n]; Radius = new float[n]; kinematicParticles = new int[n];
            RestLength = new float[s]; Compliance = new float[s]; Lambda = new double[s];
            Tension = new float[s]; PeakTension = new float[s]; MeanTension = new float[s]; Length = new float[s]; Broken = new bool[s];
            DirX = new float[s]; DirY = new float[s]; DirZ = new float[s];
            ForceX = new double[s]; ForceY = new double[s]; ForceZ = new double[s];
            StepX = new double[n]; StepY = new double[n]; StepZ = new double[n]; // entry s: spare (ExactChainSolver.MoveParticlesLanes)
            ResidualX = new double[s]; ResidualY = new double[s]; ResidualZ = new double[s];
            Eliminated = new SegmentForceSystem.EliminatedRow[s];
            AxialCompliance = new double[s]; TransverseCompliance = new double[s]; EstimatedTension = new double[s];
            BlockXX = new double[s]; BlockXY = new double[s]; BlockXZ = new double[s];
            BlockYY = new double[s]; BlockYZ = new double[s]; BlockZZ = new double[s];
            Active = new bool[s];
            EffectiveRest = new double[s]; LengthError = new double[s]; Assembled = new bool[s];
            MotionX = new double[n]; MotionY = new double[n]; MotionZ = new double[n];
            SolveDX = new double[n]; SolveDY = new double[n]; SolveDZ = new double[n];
            BaseVelX = new double[n]; BaseVelY = new double[n]; BaseVelZ = new double[n];
            PrevVelX = new double[n]; PrevVelY = new double[n]; PrevVelZ = new double[n];
            PredictedDX = new float[n]; PredictedDY = new float[n]; PredictedDZ = new float[n];
        }

        /// <summary>The rest length the segment's force is measured from (m): its plastic rest length L_p, or L for an elastic rope.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public double CurrentRest(int j) => Plasticity != null ? Plasticity.Rest(j) : RestLength[j];

        /// <summary>Allocates the contact arrays once (when the first collider is added; never in a step).</summary>
        public void EnsureContacts()
        {
            if (ContactCollider != null) return;
            int n = ParticleCount;
            ContactNX = new float[n]; ContactNY = new float[n]; ContactNZ = new float[n];
            ContactGap = new float[n]; ContactLoad = new float[n]; ContactResting = new bool[n]; ContactNear = new bool[n];
            ContactCollider = new int[n]; ContactActive = new bool[n]; ContactList = new int[n];
            ContactSticking = new bool[n]; ContactSliding = new bool[n]; ContactStopped = new bool[n]; ContactMobility = new double[n];
            ContactShiftX = new double[n]; ContactShiftY = new double[n]; ContactShiftZ = new double[n];
            ContactKineticFriction = new float[n]; ContactStaticFriction = new float[n];
            ContactSurfaceX = new float[n]; ContactSurfaceY = new float[n]; ContactSurfaceZ = new float[n];
            ContactImpulseX = new double[n]; ContactImpulseY = new double[n]; ContactImpulseZ = new double[n];
            ContactFrictionX = new double[n]; ContactFrictionY = new double[n]; ContactFrictionZ = new double[n];
            ContactMemory = new byte[n]; ContactDamping = new double[n];
            ContactLastDamping = new double[n]; ContactLastForce = new double[n];
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
                ContactSticking[i] = false;
                ContactSliding[i] = false;
            }
            ContactCount = 0;
        }

        /// <summary>
        /// Multiplier change (N·s²) d of a segment whose accumulated multiplier is lambda (≤ 0 pulls): a tension-only segment
        /// stops at λ + d = 0 instead of pushing; otherwise d unchanged.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double LimitToPulling(double lambda, double d, bool tensionOnly) => tensionOnly && lambda + d > 0.0 ? -lambda : d;

        /// <summary>Places particle i at (x, y, z) (rope-local m) now, as the start and the end of the step, with no sub-float remainder.</summary>
        public void Place(int i, float x, float y, float z)
        {
            X[i] = PrevX[i] = StepStartX[i] = x;
            Y[i] = PrevY[i] = StepStartY[i] = y;
            Z[i] = PrevZ[i] = StepStartZ[i] = z;
            LowX[i] = 0f; LowY[i] = 0f; LowZ[i] = 0f;
        }

        /// <summary>
        /// Adds (mx, my, mz) m to particle i's substep displacement D + DLow, exactly: the sum is formed in double and split
        /// into the float D and its remainder DLow.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void AddDisplacement(int i, double mx, double my, double mz)
        {
            Add(ref DX[i], ref DLowX[i], mx); Add(ref DY[i], ref DLowY[i], my); Add(ref DZ[i], ref DLowZ[i], mz);
        }

        /// <summary>
        /// Adds m (m, double) to one component of a displacement, d with its sub-float remainder low, exactly as
        /// <see cref="AddDisplacement"/> does: d + low + m formed in double and split back. For the kernels' carried copies (inlined,
        /// so the refs do not expose the locals).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Add(ref float d, ref float low, double m)
        {
            double x = ((double)d + low) + m;
            float f = (float)x;
            d = f;
            low = (float)(x - f);
        }

        /// <summary>
        /// Sets one component of a displacement, d with its sub-float remainder low, to x (m, double), as
        /// <see cref="SetDisplacement"/> does (for the kernels' spans; inlined).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Set(ref float d, ref float low, double x)
        {
            float f = (float)x;
            d = f;
            low = (float)(x - f);
        }

        /// <summary>Sets particle i's substep displacement D + DLow to (x, y, z) m (double), split into the float D and its remainder.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void SetDisplacement(int i, double x, double y, double z)
        {
            Set(ref DX[i], ref DLowX[i], x); Set(ref DY[i], ref DLowY[i], y); Set(ref DZ[i], ref DLowZ[i], z);
        }

        /// <summary>Particle i's substep displacement D + DLow (m, double).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Displacement(int i, out double dx, out double dy, out double dz)
        {
            dx = (double)DX[i] + DLowX[i]; dy = (double)DY[i] + DLowY[i]; dz = (double)DZ[i] + DLowZ[i];
        }

        /// <summary>Change (m, double) of segment j over the substep: (D + DLow)_{j+1} − (D + DLow)_j.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void SubstepChange(int j, out double ddx, out double ddy, out double ddz)
        {
            ddx = Change(DX[j], DX[j + 1], DLowX[j], DLowX[j + 1]);
            ddy = Change(DY[j], DY[j + 1], DLowY[j], DLowY[j + 1]);
            ddz = Change(DZ[j], DZ[j + 1], DLowZ[j], DLowZ[j + 1]);
        }

        /// <summary>Vector (m, double) of segment j between the live positions Prev + Low + D + DLow of its ends; (ddx, ddy, ddz) is its <see cref="SubstepChange"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void LiveSpan(int j, out double ex, out double ey, out double ez, out double ddx, out double ddy, out double ddz)
        {
            SubstepChange(j, out ddx, out ddy, out ddz);
            ex = Component(PrevX[j], PrevX[j + 1], LowX[j], LowX[j + 1], ddx);
            ey = Component(PrevY[j], PrevY[j + 1], LowY[j], LowY[j + 1], ddy);
            ez = Component(PrevZ[j], PrevZ[j + 1], LowZ[j], LowZ[j + 1], ddz);
        }

        /// <summary>
        /// One component (m, double) of a segment's change over the substep from its ends' displacements and their sub-float
        /// remainders (all float): (D_b − D_a) + (DLow_b − DLow_a), formed in double.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Change(float dA, float dB, float lowA, float lowB) => ((double)dB - dA) + ((double)lowB - lowA);

        /// <summary>
        /// One component (m, double) of a segment's live vector from its ends' previous positions, remainders (both float,
        /// passed as double) and the change of its span over the substep (<see cref="Change"/>, double):
        /// (P_b − P_a) + ((Low_b − Low_a) + change).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Component(double prevA, double prevB, double lowA, double lowB, double change) => (prevB - prevA) + ((lowB - lowA) + change);

        /// <summary>
        /// Length (m) of segment j's live vector (ex, ey, ez) and its unit direction (nx, ny, nz), stored in float into
        /// dirX/Y/Z[j] as the last valid direction; a vanishing or non-finite vector keeps the stored direction (see
        /// <see cref="LiveSpan"/>). The kernels pass the direction arrays as spans (<see cref="Exactly"/>).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Normalise(int j, double ex, double ey, double ez, Span<float> dirX, Span<float> dirY, Span<float> dirZ, out double nx, out double ny, out double nz)
        {
            double len = Math.Sqrt(ex * ex + ey * ey + ez * ez);
            if (len > 1e-12 && len <= float.MaxValue)
            {
                double inv = 1.0 / len;
                nx = ex * inv; ny = ey * inv; nz = ez * inv;
                dirX[j] = (float)nx; dirY[j] = (float)ny; dirZ[j] = (float)nz;
                return len;
            }
            nx = dirX[j]; ny = dirY[j]; nz = dirZ[j];
            return len <= float.MaxValue ? len : 0.0;
        }

        /// <summary>
        /// <see cref="Vector.Widen(Vector{float}, out Vector{double}, out Vector{double})"/> with the upper half converted
        /// first: the lower half's conversion is then the source register's last use, and the JIT drops the copy it otherwise
        /// makes of it (the same conversions, the same bits).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Widen(Vector<float> source, out Vector<double> low, out Vector<double> high)
        {
            Vector.Widen(source, out _, out high);
            Vector.Widen(source, out low, out _);
        }

        /// <summary>
        /// The first n entries of an array (one of these particle or segment arrays) as a span whose length the JIT knows to
        /// be n: the array is checked non-null first, so the span's length is not a choice between n and 0, and a loop bounded
        /// by n indexes it without bounds checks (an array indexed j + 1, or several arrays under one loop bound, keep theirs).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Span<T> Exactly<T>(T[] values, int n)
        {
            if (values == null) ThrowSizes();
            return values.AsSpan(0, n);
        }

        /// <summary>
        /// The entries from … from + count − 1 of an array as a span of count (see <see cref="Exactly"/>): a loop over part of
        /// the particles or segments bounded by count indexes it without bounds checks.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Span<T> Range<T>(T[] values, int from, int count)
        {
            if (values == null) ThrowSizes();
            return values.AsSpan(from, count);
        }

        /// <summary>The entries j + 1 … j + n of an array as a span of n (see <see cref="Exactly"/>): a segment's second particle at index j.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Span<T> Shifted<T>(T[] values, int n)
        {
            if (values == null) ThrowSizes();
            return values.AsSpan(1, n);
        }

        /// <summary>
        /// Throws unless every particle array the kernels index has ParticleCount entries and every segment array
        /// SegmentCount (true by construction): after this check the JIT drops the per-element bounds checks of loops bounded by
        /// those lengths (a method that only throws is not inlined, and the JIT knows the call does not return).
        /// </summary>
        public static void ThrowSizes() => throw new InvalidOperationException("ChainState arrays are sized from SegmentCount");

        /// <summary>Vector (m, double) of segment j between the committed positions X + Low of its ends.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Span(int j, out double ex, out double ey, out double ez)
        {
            ex = ((double)X[j + 1] - X[j]) + ((double)LowX[j + 1] - LowX[j]);
            ey = ((double)Y[j + 1] - Y[j]) + ((double)LowY[j + 1] - LowY[j]);
            ez = ((double)Z[j + 1] - Z[j]) + ((double)LowZ[j + 1] - LowZ[j]);
        }
    }
}
