using System;
using System.Runtime.CompilerServices;

namespace HookeRope.Solver
{
    /// <summary>
    /// The state and the sweep of <see cref="GaussSeidelKernel.FusedSingle"/>: a rope's particles and segments packed
    /// into two arrays of small float structs, so one substep is one pass that loads and stores each particle once
    /// (predict particle j + 1, project segment j, commit particle j), the loop structure of PositionBasedDynamics'
    /// <c>solve_DistanceConstraint</c> loop. All in float. Each particle keeps its position x and velocity v; within a
    /// substep it moves by a displacement d from where the substep started (backward Euler: v ← v + g·h, d = v·h, the
    /// projections add to d, then x ← x + d and v = d/h). The segment vector is (x_b − x_a) + (d_b − d_a), so a segment's
    /// stretch is resolved to the float step of its own length and of the displacements, not only to the coordinates'
    /// (a position-Verlet form, x ← 2x − p + g·h², read a hanging rope's top tension 6.6 % low at 64 substeps, where
    /// g·h² is 2.5 float steps of a coordinate at 1–2 m). The projection is XPBD's (Macklin 2016) with compliance
    /// α̃ = α/h², the damping of eq. 26 (γ = β/h on segments with α &gt; 0) and the tension-only clamp of the accumulated
    /// λ (λ ≤ 0 pulls). <see cref="Rope"/> loads it from the chain at the start of a host step and writes the chain back
    /// at its end (Rope.FusedStep.cs).
    /// </summary>
    internal sealed class FusedChain
    {
        /// <summary>One particle (rope-local frame).</summary>
        public struct Particle
        {
            /// <summary>Position at the start of the substep (m); after the substep's last sweep, its end.</summary>
            public float X, Y, Z;
            /// <summary>Velocity (m/s).</summary>
            public float VX, VY, VZ;
            /// <summary>
            /// Displacement of the substep (m) between sweeps of a substep of several iterations; for a pinned particle, the
            /// pin's motion over the substep (written before the first sweep).
            /// </summary>
            public float DX, DY, DZ;
            /// <summary>Inverse mass (1/kg); 0 for a pinned particle.</summary>
            public float W;
        }

        /// <summary>One segment: its constants for the host step's substep h and its multiplier.</summary>
        public struct Segment
        {
            /// <summary>Rest length L (m).</summary>
            public float Rest;
            /// <summary>α̃ = α/h² (1/kg; α = L/(E·A)).</summary>
            public float AlphaTilde;
            /// <summary>The damping fold γ = β/h (dimensionless; 0 for an inextensible segment).</summary>
            public float Gamma;
            /// <summary>1/((1 + γ)(w_a + w_b) + α̃) (kg), 0 for a broken segment or one that cannot move.</summary>
            public float InverseDenominator;
            /// <summary>The accumulated multiplier λ of this substep (N·s², ≤ 0 pulls).</summary>
            public float Lambda;
            /// <summary>The smallest substep λ of the host step (its largest tension).</summary>
            public float LambdaMin;
            /// <summary>The summed substep λ of the host step.</summary>
            public float LambdaSum;
            /// <summary>Padding to 32 bytes.</summary>
            public float Unused;
        }

        /// <summary>Particles (count = segments + 1).</summary>
        public readonly Particle[] Particles;

        /// <summary>Segments.</summary>
        public readonly Segment[] Segments;

        /// <summary>A packed chain of <paramref name="segmentCount"/> segments (allocated once, at a rope's first fused step).</summary>
        public FusedChain(int segmentCount)
        {
            Particles = new Particle[segmentCount + 1];
            Segments = new Segment[segmentCount];
        }

        /// <summary>The substep's first sweep: it predicts each particle just before its first projection and starts λ from 0.</summary>
        public struct Predicting { }

        /// <summary>A later sweep: the displacements and λ as the sweep before left them.</summary>
        public struct Continuing { }

        /// <summary>The substep's last sweep: it commits each particle after its last projection and raises the host step's λ minimum and sum.</summary>
        public struct Committing { }

        /// <summary>A sweep before the last: it stores the displacements for the next.</summary>
        public struct Storing { }

        /// <summary>
        /// One Gauss–Seidel sweep over the segments in order (gh = g·h in m/s, h the substep in s, invH = 1/h).
        /// TFirst <see cref="Predicting"/> or <see cref="Continuing"/>, TLast <see cref="Committing"/> or
        /// <see cref="Storing"/>: a substep of one iteration is one Predicting, Committing sweep. The JIT compiles one body
        /// per pair of struct type arguments and folds the typeof tests. <paramref name="tensionOnly"/>: λ ≤ 0.
        /// </summary>
        public void Sweep<TFirst, TLast>(float ghx, float ghy, float ghz, float h, float invH, bool tensionOnly) where TFirst : struct where TLast : struct
        {
            bool predict = typeof(TFirst) == typeof(Predicting);
            bool commit = typeof(TLast) == typeof(Committing);
            Segment[] segmentArray = Segments;
            Particle[] particleArray = Particles;
            if (segmentArray == null || particleArray == null || particleArray.Length != segmentArray.Length + 1) ChainState.ThrowSizes();
            Span<Segment> segments = segmentArray;
            // particle j + 1 of segment j at index j: a span of the segments' length, indexed without bounds checks
            Span<Particle> next = particleArray.AsSpan(1, segments.Length);
            ref Particle a = ref particleArray[0];
            // particle a = j is carried from the projection before: its displacement in registers, its start position and
            // inverse mass read from memory where used (x86-64 has 16 XMM registers: the fewer values live across the loop,
            // the fewer spills), so each particle is loaded and stored once per sweep
            float dxa, dya, dza;
            Begin<TFirst>(ref a, ghx, ghy, ghz, h, out dxa, out dya, out dza);
            for (int j = 0; j < segments.Length; j++)
            {
                ref Particle b = ref next[j];
                float dxb, dyb, dzb;
                Begin<TFirst>(ref b, ghx, ghy, ghz, h, out dxb, out dyb, out dzb);
                ref Segment s = ref segments[j];
                // the segment's change over the substep, and its vector (x_b − x_a) + change
                float cx = dxb - dxa, cy = dyb - dya, cz = dzb - dza;
                float ex = (b.X - a.X) + cx, ey = (b.Y - a.Y) + cy, ez = (b.Z - a.Z) + cz;
                float len = MathF.Sqrt(ex * ex + ey * ey + ez * ez);
                // a vanishing or non-finite segment is not projected (NaN compares false); a broken or immovable one has
                // 1/denominator = 0 and moves by 0
                float lambda = predict ? 0f : s.Lambda;
                if (len > 1e-12f && len <= float.MaxValue)
                {
                    float inv = 1f / len;
                    float nx = ex * inv, ny = ey * inv, nz = ez * inv;
                    // the damping term γ·n·(d_b − d_a) (γ = 0 where it is off)
                    float rel = s.Gamma * (nx * cx + ny * cy + nz * cz);
                    float numerator = predict ? s.Rest - len - rel : s.Rest - len - s.AlphaTilde * lambda - rel;
                    float d = numerator * s.InverseDenominator;
                    // λ starts from 0 in the first sweep: the clamp and the sum without the zero
                    if (predict)
                    {
                        if (tensionOnly && d > 0f) d = 0f;
                        lambda = d;
                    }
                    else
                    {
                        if (tensionOnly && lambda + d > 0f) d = -lambda;
                        lambda += d;
                    }
                    float ma = a.W * d, mb = b.W * d;
                    dxa -= nx * ma; dya -= ny * ma; dza -= nz * ma;
                    dxb += nx * mb; dyb += ny * mb; dzb += nz * mb;
                }
                s.Lambda = lambda;
                if (commit)
                {
                    if (lambda < s.LambdaMin) s.LambdaMin = lambda;
                    s.LambdaSum += lambda;
                }
                End<TLast>(ref a, dxa, dya, dza, invH);
                a = ref b;
                dxa = dxb; dya = dyb; dza = dzb;
            }
            End<TLast>(ref a, dxa, dya, dza, invH);
        }

        /// <summary>
        /// A particle's displacement at the start of its first projection in this sweep: predicted (v ← v + g·h, d = v·h; a
        /// pinned particle's d is its pin's motion, stored) or, in a later sweep, as the sweep before stored it.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Begin<TFirst>(ref Particle q, float ghx, float ghy, float ghz, float h, out float dx, out float dy, out float dz) where TFirst : struct
        {
            if (typeof(TFirst) == typeof(Predicting) && q.W != 0f)
            {
                float vx = q.VX + ghx, vy = q.VY + ghy, vz = q.VZ + ghz;
                dx = vx * h; dy = vy * h; dz = vz * h;
                return;
            }
            dx = q.DX; dy = q.DY; dz = q.DZ;
        }

        /// <summary>A particle after its last projection in this sweep: committed (x ← x + d, v = d/h) or its displacement stored for the next sweep.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void End<TLast>(ref Particle q, float dx, float dy, float dz, float invH) where TLast : struct
        {
            if (typeof(TLast) == typeof(Committing))
            {
                q.X += dx; q.Y += dy; q.Z += dz;
                q.VX = dx * invH; q.VY = dy * invH; q.VZ = dz * invH;
                return;
            }
            q.DX = dx; q.DY = dy; q.DZ = dz;
        }
    }
}
