using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// An elastic rope: a chain of particles joined by XPBD distance constraints whose compliance is
    /// that of the real material (α = L_seg/(E·A)), stepped with substeps (Small Steps) and either a
    /// Gauss–Seidel or an exact whole-chain solve per iteration.
    /// <para>Frames: every <see cref="Float3"/> argument and return value is in world metres; the
    /// spans (<see cref="PositionX"/>…) are in the rope-local frame, world = <see cref="Origin"/> + local,
    /// which keeps float32 precision when the rope is far from the world origin.</para>
    /// <para>Sign convention: tensions and the accumulated XPBD multipliers are reported as forces,
    /// ≥ 0 when a segment pulls; a tension-only segment never reports a negative tension.</para>
    /// </summary>
    public sealed partial class Rope
    {
        private readonly RopeSettings settings;
        private readonly ChainState chain;
        private readonly CollisionSet colliders = new CollisionSet();
        private int appliedVersion = -1;
        private float appliedRadius = float.NaN;
        private double time;

        /// <summary>
        /// Builds a rope from <paramref name="settings"/> (kept by reference and re-read each step)
        /// with its particles evenly spaced on the straight line start → end (world metres). The
        /// rest length comes from the settings, so a start–end distance different from it starts the
        /// rope stretched or slack.
        /// </summary>
        public Rope(RopeSettings settings, Float3 start, Float3 end)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            if (!start.IsFinite) throw new ArgumentException("start must be a finite position in metres", nameof(start));
            if (!end.IsFinite) throw new ArgumentException("end must be a finite position in metres", nameof(end));
            this.settings = settings;
            Origin = start;
            chain = new ChainState(settings.SegmentCount);
            int s = chain.SegmentCount;
            Float3 span = end - start;
            Float3 fallback = settings.Gravity.NormalizedOr(new Float3(0f, -1f, 0f));
            Float3 dir = span.NormalizedOr(fallback);
            for (int i = 0; i <= s; i++)
            {
                Float3 p = span * ((float)i / s);
                chain.Place(i, p.X, p.Y, p.Z);
            }
            for (int j = 0; j < s; j++) { chain.DirX[j] = dir.X; chain.DirY[j] = dir.Y; chain.DirZ[j] = dir.Z; }
            ApplySettings();
        }

        /// <summary>The settings this rope reads (shared by reference; changes apply at the next step).</summary>
        public RopeSettings Settings => settings;

        /// <summary>World position in metres of the rope-local frame's origin (the start point given at construction).</summary>
        public Float3 Origin { get; }

        /// <summary>Simulated time in seconds since the rope was built.</summary>
        public double Time => time;

        /// <summary>Number of particles (SegmentCount + 1).</summary>
        public int ParticleCount => chain.ParticleCount;

        /// <summary>Number of segments (fixed when the rope is built).</summary>
        public int SegmentCount => chain.SegmentCount;

        /// <summary>Particle X coordinates in metres, rope-local frame (world = Origin + local).</summary>
        public ReadOnlySpan<float> PositionX => chain.X;
        /// <summary>Particle Y coordinates in metres, rope-local frame (world = Origin + local).</summary>
        public ReadOnlySpan<float> PositionY => chain.Y;
        /// <summary>Particle Z coordinates in metres, rope-local frame (world = Origin + local).</summary>
        public ReadOnlySpan<float> PositionZ => chain.Z;

        /// <summary>Rest length of each segment in metres.</summary>
        public ReadOnlySpan<float> RestLengths => chain.RestLength;

        /// <summary>Current length of each segment in metres (after the last step), from the exact positions (float + remainder): resolved far below the float step of the coordinates.</summary>
        public ReadOnlySpan<float> SegmentLengths => chain.Length;

        /// <summary>Tension of each segment in newtons over the last substep, ≥ 0 = pulling (T = −λ/h²).</summary>
        public ReadOnlySpan<float> Tensions => chain.Tension;

        /// <summary>Largest tension (N) of each segment over the substeps of the last host step: a short peak (a snatch) that ends between steps still reads.</summary>
        public ReadOnlySpan<float> PeakTensions => chain.PeakTension;

        /// <summary>Mean tension (N) of each segment over the substeps of the last host step.</summary>
        public ReadOnlySpan<float> MeanTensions => chain.MeanTension;

        /// <summary>Collision radius of each particle in metres (default: the rest radius; the radius model of <see cref="RopeSimulation"/> writes it).</summary>
        public ReadOnlySpan<float> ParticleRadius => chain.Radius;

        /// <summary>Writes the particles' collision radii in metres (the radius model's output); length must be <see cref="ParticleCount"/>.</summary>
        internal void SetParticleRadii(ReadOnlySpan<float> radii)
        {
            if (radii.Length != chain.ParticleCount)
                throw new ArgumentException("radii must hold one radius per particle (" + chain.ParticleCount + ")", nameof(radii));
            radii.CopyTo(chain.Radius);
        }

        /// <summary>Broken flag of each segment (true = broken; its two sides move independently).</summary>
        public ReadOnlySpan<bool> BrokenSegments => chain.Broken;

        /// <summary>Number of broken segments (0 = intact).</summary>
        public int BrokenSegmentCount => chain.BrokenCount;

        /// <summary>
        /// Writes the particle positions (m, rope-local frame: world = <see cref="Origin"/> + local) interpolated between
        /// the start and the end of the last host step: alpha 0 = start, 1 = now (clamped to [0, 1]). Before the first
        /// step, or for particles the host placed since, start and end coincide. Each span needs at least
        /// <see cref="ParticleCount"/> entries. Allocation-free.
        /// </summary>
        public void Interpolate(float alpha, Span<float> x, Span<float> y, Span<float> z)
        {
            int n = chain.ParticleCount;
            if (x.Length < n || y.Length < n || z.Length < n)
                throw new ArgumentException("x, y and z must each hold at least ParticleCount (" + n + ") values");
            float a = ClampAlpha(alpha);
            float[] sx = chain.StepStartX, sy = chain.StepStartY, sz = chain.StepStartZ;
            float[] ex = chain.X, ey = chain.Y, ez = chain.Z;
            for (int i = 0; i < n; i++)
            {
                x[i] = sx[i] + (ex[i] - sx[i]) * a;
                y[i] = sy[i] + (ey[i] - sy[i]) * a;
                z[i] = sz[i] + (ez[i] - sz[i]) * a;
            }
        }

        /// <summary>World position (m) of a particle interpolated between the start (alpha 0) and the end (alpha 1) of the last host step; alpha is clamped to [0, 1].</summary>
        public Float3 GetInterpolatedPosition(int particle, float alpha)
        {
            CheckParticle(particle);
            float a = ClampAlpha(alpha);
            float sx = chain.StepStartX[particle], sy = chain.StepStartY[particle], sz = chain.StepStartZ[particle];
            return Origin + new Float3(sx + (chain.X[particle] - sx) * a, sy + (chain.Y[particle] - sy) * a, sz + (chain.Z[particle] - sz) * a);
        }

        private static float ClampAlpha(float alpha) => alpha >= 1f ? 1f : alpha > 0f ? alpha : 0f;

        /// <summary>World position of a particle in metres.</summary>
        public Float3 GetPosition(int particle)
        {
            CheckParticle(particle);
            return Origin + new Float3(chain.X[particle], chain.Y[particle], chain.Z[particle]);
        }

        /// <summary>Moves a particle to a world position (m) without changing its velocity; NaN/∞ → ArgumentException.</summary>
        public void SetPosition(int particle, Float3 position)
        {
            CheckParticle(particle);
            CheckFinite(position, nameof(position), "a finite position in metres");
            Float3 local = position - Origin;
            chain.Place(particle, local.X, local.Y, local.Z);
            RefreshLengths();
        }

        /// <summary>Velocity of a particle in m/s.</summary>
        public Float3 GetVelocity(int particle)
        {
            CheckParticle(particle);
            return new Float3((float)chain.VelX[particle], (float)chain.VelY[particle], (float)chain.VelZ[particle]);
        }

        /// <summary>Sets the velocity of a particle in m/s; NaN/∞ → ArgumentException.</summary>
        public void SetVelocity(int particle, Float3 velocity)
        {
            CheckParticle(particle);
            CheckFinite(velocity, nameof(velocity), "a finite velocity in m/s");
            BoostHistory(particle, velocity.X - chain.VelX[particle], velocity.Y - chain.VelY[particle], velocity.Z - chain.VelZ[particle]);
            chain.VelX[particle] = velocity.X;
            chain.VelY[particle] = velocity.Y;
            chain.VelZ[particle] = velocity.Z;
        }

        /// <summary>Mass of a particle in kg: its lumped share of the rope (μ·L/2 per adjacent segment) plus attached loads.</summary>
        public float GetParticleMass(int particle)
        {
            CheckParticle(particle);
            return chain.Mass[particle];
        }

        /// <summary>True when the segment has broken (its two sides move independently).</summary>
        public bool IsSegmentBroken(int segment)
        {
            CheckSegment(segment);
            return chain.Broken[segment];
        }

        /// <summary>
        /// Breaks a segment now (no-op if already broken) and raises <see cref="Broken"/>. The rope parts at the segment's
        /// middle: each side keeps half of its rest length and of its mass (the lumped μ·L/2 its particle already carries),
        /// so no rest length and no mass vanish (the mesh draws each half as a relaxed dangling end). The elastic energy the
        /// segment stored, ½·C²/α (J), is released into the recoil: the two end particles are pushed apart along the
        /// segment with equal and opposite impulses whose kinetic energy is exactly that energy (a kinematic end counts as
        /// infinitely heavy; both kinematic: the anchors take it), capped where the last step's substep is too coarse to
        /// carry it without folding the slack end (see <see cref="RopeBreakEvent.RecoilEnergy"/>). Allocation-free.
        /// </summary>
        public void BreakSegment(int segment)
        {
            CheckSegment(segment);
            if (chain.Broken[segment]) return;
            float tension = chain.Tension[segment];
            double recoil = ReleaseRecoil(segment, out double stored);
            chain.Broken[segment] = true;
            chain.BrokenCount++;
            chain.Lambda[segment] = 0.0;
            chain.Tension[segment] = 0f;
            var midpoint = new Float3(
                0.5f * (chain.X[segment] + chain.X[segment + 1]),
                0.5f * (chain.Y[segment] + chain.Y[segment + 1]),
                0.5f * (chain.Z[segment] + chain.Z[segment + 1]));
            Broken?.Invoke(new RopeBreakEvent(time, Origin + midpoint, segment, tension, stored, recoil));
        }

        /// <summary>Raised when a segment breaks (<see cref="BreakSegment"/>: a cut, or the fracture decision of <see cref="RopeSimulation"/>): time s, position m, segment, tension N just before.</summary>
        public event Action<RopeBreakEvent> Broken;

        /// <summary>
        /// Re-reads the settings now (rest lengths, compliance, masses, and — if the rest radius changed — the
        /// particle radii). <see cref="Step"/> calls it automatically when <see cref="RopeSettings.Version"/> changed.
        /// </summary>
        public void ApplySettings()
        {
            int s = chain.SegmentCount;
            float restSegment = settings.RestLength / s;
            float axial = settings.AxialStiffness;
            float compliance = float.IsPositiveInfinity(axial) ? 0f : restSegment / axial;
            for (int j = 0; j < s; j++)
            {
                chain.RestLength[j] = restSegment;
                chain.Compliance[j] = compliance;
            }
            float mu = settings.LinearDensity;
            for (int i = 0; i <= s; i++) UpdateMass(i, mu);
            if (settings.Radius != appliedRadius)
            {
                appliedRadius = settings.Radius;
                for (int i = 0; i <= s; i++) chain.Radius[i] = appliedRadius;
            }
            ApplyPlasticity();
            appliedVersion = settings.Version;
            RefreshLengths();
        }

        /// <summary>
        /// Total mechanical energy in joules: <see cref="KineticEnergy"/> + <see cref="GravitationalEnergy"/> +
        /// <see cref="ElasticEnergy"/>. For tests and the lab.
        /// </summary>
        public double TotalEnergy() => KineticEnergy() + GravitationalEnergy() + ElasticEnergy();

        /// <summary>Kinetic energy Σ½m|v|² in joules (particles with their loads).</summary>
        public double KineticEnergy()
        {
            double e = 0.0;
            for (int i = 0; i < chain.ParticleCount; i++)
            {
                double vx = chain.VelX[i], vy = chain.VelY[i], vz = chain.VelZ[i];
                e += 0.5 * chain.Mass[i] * (vx * vx + vy * vy + vz * vz);
            }
            return e;
        }

        /// <summary>Gravitational energy −Σ m g·x in joules, zero at the rope-local origin (<see cref="Origin"/>).</summary>
        public double GravitationalEnergy()
        {
            double e = 0.0;
            Float3 g = settings.Gravity;
            for (int i = 0; i < chain.ParticleCount; i++)
                e -= chain.Mass[i] * ((double)g.X * ((double)chain.X[i] + chain.LowX[i]) + (double)g.Y * ((double)chain.Y[i] + chain.LowY[i])
                    + (double)g.Z * ((double)chain.Z[i] + chain.LowZ[i]));
            return e;
        }

        /// <summary>Elastic energy Σ½C²/α in joules (C = l − L_p: measured from the plastic rest length) over the loaded segments (stretched ones for a tension-only rope) and compliant pins.</summary>
        public double ElasticEnergy()
        {
            double e = 0.0;
            bool tensionOnly = settings.Tension == TensionModel.TensionOnly;
            for (int j = 0; j < chain.SegmentCount; j++)
            {
                if (chain.Broken[j] || chain.Compliance[j] == 0f) continue;
                chain.Span(j, out double dx, out double dy, out double dz);
                double c = Math.Sqrt(dx * dx + dy * dy + dz * dz) - chain.CurrentRest(j);
                if (tensionOnly && c < 0.0) continue;
                e += 0.5 * c * c / chain.Compliance[j];
            }
            return e + PinEnergy();
        }

        private void UpdateMass(int i, float mu)
        {
            int s = chain.SegmentCount;
            double m = 0.0;
            if (i > 0) m += 0.5 * mu * chain.RestLength[i - 1];
            if (i < s) m += 0.5 * mu * chain.RestLength[i];
            m += chain.LoadMass[i];
            chain.Mass[i] = (float)m;
            chain.InverseMass[i] = chain.Kinematic[i] ? 0f : (float)(1.0 / m);
        }

        private void RefreshLengths()
        {
            int s = chain.SegmentCount;
            // on lanes while VectorPath.Enabled (runs of Vector<float> segments, the same bits); the rows below take the rest
            int from = VectorPath.Enabled ? RefreshLengthLanes() : 0;
            if (from >= s) return;
            // ChainState.Span on spans of exactly s entries (A: particle j, B: particle j + 1), indexed without bounds checks
            ReadOnlySpan<float> xA = ChainState.Exactly(chain.X, s), yA = ChainState.Exactly(chain.Y, s), zA = ChainState.Exactly(chain.Z, s);
            ReadOnlySpan<float> xB = ChainState.Shifted(chain.X, s), yB = ChainState.Shifted(chain.Y, s), zB = ChainState.Shifted(chain.Z, s);
            ReadOnlySpan<float> lxA = ChainState.Exactly(chain.LowX, s), lyA = ChainState.Exactly(chain.LowY, s), lzA = ChainState.Exactly(chain.LowZ, s);
            ReadOnlySpan<float> lxB = ChainState.Shifted(chain.LowX, s), lyB = ChainState.Shifted(chain.LowY, s), lzB = ChainState.Shifted(chain.LowZ, s);
            Span<float> length = ChainState.Exactly(chain.Length, s);
            for (int j = from; j < s; j++)
            {
                double dx = ((double)xB[j] - xA[j]) + ((double)lxB[j] - lxA[j]);
                double dy = ((double)yB[j] - yA[j]) + ((double)lyB[j] - lyA[j]);
                double dz = ((double)zB[j] - zA[j]) + ((double)lzB[j] - lzA[j]);
                length[j] = (float)Math.Sqrt(dx * dx + dy * dy + dz * dz);
            }
        }

        private void CheckParticle(int particle)
        {
            if ((uint)particle >= (uint)chain.ParticleCount)
                throw new ArgumentOutOfRangeException(nameof(particle), particle, "particle must be in [0, " + (chain.ParticleCount - 1) + "]");
        }

        private void CheckSegment(int segment)
        {
            if ((uint)segment >= (uint)chain.SegmentCount)
                throw new ArgumentOutOfRangeException(nameof(segment), segment, "segment must be in [0, " + (chain.SegmentCount - 1) + "]");
        }

        private static void CheckFinite(Float3 value, string name, string what)
        {
            if (!value.IsFinite) throw new ArgumentException(name + " must be " + what + " (no NaN or infinity)", name);
        }
    }
}
