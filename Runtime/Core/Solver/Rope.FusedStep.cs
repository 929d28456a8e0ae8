using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// The host step of <see cref="GaussSeidelKernel.FusedSingle"/> (<see cref="FusedChain"/>): the chain is packed into
    /// float structs at the start of the step, each substep is one fused pass (and one more sweep per further iteration),
    /// and the chain is written back at the end with the read-outs the precise step gives: positions (no sub-float
    /// remainder), velocities, tensions T = −λ/h² of the last substep, their peak and mean over the substeps,
    /// segment lengths and directions, pin forces (and pin breaks, checked every substep when a pin can break), load
    /// forces and peaks, the residual. A particle whose end of step is not finite falls back to its position at the start
    /// of the step, at rest.
    /// </summary>
    public sealed partial class Rope
    {
        // the packed state, made at the first fused step (not in a step after it)
        private FusedChain fused;

        /// <summary>
        /// True when the settings ask for <see cref="GaussSeidelKernel.FusedSingle"/> and the rope has none of what it
        /// lacks: the Gauss–Seidel solver with backward Euler, no collider, no drag, no compliant pin, no plastic state.
        /// </summary>
        private bool FusedStepApplies() =>
            settings.GaussSeidelKernel == GaussSeidelKernel.FusedSingle && settings.Solver == ConstraintSolverKind.GaussSeidel
            && settings.Integrator == TimeIntegrator.BackwardEuler && colliders.Count == 0 && !settings.HasDrag
            && chain.Plasticity == null && CountCompliantPins() == 0;

        /// <summary>
        /// <see cref="Step"/> with <see cref="GaussSeidelKernel.FusedSingle"/> (hostDeltaTime s, checked by the caller): the
        /// same phases and read-outs, in float and fused. Allocation-free after the first call.
        /// </summary>
        private StepReport StepFused(float hostDeltaTime)
        {
            int substeps = settings.Substeps, iterations = settings.Iterations;
            double hd = (double)hostDeltaTime / substeps;
            float h = (float)hd;
            bool tensionOnly = settings.Tension == TensionModel.TensionOnly;
            Float3 g = settings.Gravity;
            float invH = (float)(1.0 / hd);
            float ghx = (float)(g.X * hd), ghy = (float)(g.Y * hd), ghz = (float)(g.Z * hd);
            if (fused == null) fused = new FusedChain(chain.SegmentCount);
            BeginStep();
            PackFused();
            PackFusedSegments(hd, true);
            reportIterations = 0; reportViolent = 0; reportShortened = 0; reportUnconverged = 0;
            // the precise step's BDF2 history does not survive a fused step
            historyValid = false;
            bool breakablePins = BreakablePins();
            for (int k = 0; k < substeps; k++)
            {
                float t = (float)(k + 1) / substeps;
                MoveFusedPins(t);
                if (iterations == 1) fused.Sweep<FusedChain.Predicting, FusedChain.Committing>(ghx, ghy, ghz, h, invH, tensionOnly);
                else
                {
                    fused.Sweep<FusedChain.Predicting, FusedChain.Storing>(ghx, ghy, ghz, h, invH, tensionOnly);
                    for (int it = 1; it < iterations - 1; it++) fused.Sweep<FusedChain.Continuing, FusedChain.Storing>(ghx, ghy, ghz, h, invH, tensionOnly);
                    fused.Sweep<FusedChain.Continuing, FusedChain.Committing>(ghx, ghy, ghz, h, invH, tensionOnly);
                }
                time += hd;
                if (loadCount > 0) TrackFusedLoadPeaks(invH, g);
                // a pin that can break is checked every substep (its force from this substep's tensions); else only the last's is read
                if (pinCount > 0 && (breakablePins || k == substeps - 1) && UpdateFusedPinForces(hd, g))
                {
                    PackFusedMasses();
                    PackFusedSegments(hd, false);
                    breakablePins = BreakablePins();
                }
            }
            UnpackFused(hd, substeps);
            EndStep(hostDeltaTime, g);
            return new StepReport { Residual = ComputeResidual(), Iterations = iterations, Substeps = substeps };
        }

        /// <summary>The start of a host step in either kernel: the positions kept for <see cref="Interpolate"/>, each load's start state, its peak restarted.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private void BeginStep()
        {
            int particles = chain.ParticleCount;
            Array.Copy(chain.X, chain.StepStartX, particles);
            Array.Copy(chain.Y, chain.StepStartY, particles);
            Array.Copy(chain.Z, chain.StepStartZ, particles);
            for (int l = 0; l < loadCount; l++)
            {
                int i = loadParticle[l];
                loadStartVelocity[l] = new Float3((float)chain.VelX[i], (float)chain.VelY[i], (float)chain.VelZ[i]);
                loadStartPosition[l] = new Float3(chain.X[i], chain.Y[i], chain.Z[i]);
                loadSubstepVelocity[l] = loadStartVelocity[l];
                loadPeakForce[l] = 0f;
            }
        }

        /// <summary>The end of a host step (hostDeltaTime s, g m/s²) in either kernel: the pins' targets reached, each load's force over the step.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private void EndStep(float hostDeltaTime, Float3 g)
        {
            for (int p = 0; p < pinCount; p++) pinStart[p] = pinEnd[p];
            lastStepTime = hostDeltaTime;
            float invDt = 1f / hostDeltaTime;
            for (int l = 0; l < loadCount; l++)
            {
                int i = loadParticle[l];
                var v = new Float3((float)chain.VelX[i], (float)chain.VelY[i], (float)chain.VelZ[i]);
                loadForce[l] = ((v - loadStartVelocity[l]) * invDt - g) * loadMass[l];
            }
        }

        /// <summary>Stores pin p's force (N) of this substep in either kernel; above its break force the pin breaks (force 0). Returns true when it broke.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        private bool SetPinForce(int p, Float3 force)
        {
            pinForce[p] = force;
            if (!(force.Length > pinBreakForce[p])) return false;
            pinBroken[p] = true;
            pinForce[p] = Float3.Zero;
            return true;
        }

        /// <summary>True when some unbroken pin has a finite break force.</summary>
        private bool BreakablePins()
        {
            for (int p = 0; p < pinCount; p++) if (!pinBroken[p] && float.IsFinite(pinBreakForce[p])) return true;
            return false;
        }

        /// <summary>Packs the particles: x = X + Low (float), v (float), the inverse masses.</summary>
        private void PackFused()
        {
            int n = chain.ParticleCount;
            Span<FusedChain.Particle> packed = fused.Particles;
            ReadOnlySpan<float> x = ChainState.Exactly(chain.X, n), y = ChainState.Exactly(chain.Y, n), z = ChainState.Exactly(chain.Z, n);
            ReadOnlySpan<float> lx = ChainState.Exactly(chain.LowX, n), ly = ChainState.Exactly(chain.LowY, n), lz = ChainState.Exactly(chain.LowZ, n);
            ReadOnlySpan<double> vx = ChainState.Exactly(chain.VelX, n), vy = ChainState.Exactly(chain.VelY, n), vz = ChainState.Exactly(chain.VelZ, n);
            ReadOnlySpan<float> w = ChainState.Exactly(chain.InverseMass, n);
            if (packed.Length != n) ChainState.ThrowSizes();
            for (int i = 0; i < n; i++)
            {
                ref FusedChain.Particle q = ref packed[i];
                q.X = x[i] + lx[i]; q.Y = y[i] + ly[i]; q.Z = z[i] + lz[i];
                q.VX = (float)vx[i]; q.VY = (float)vy[i]; q.VZ = (float)vz[i];
                q.DX = 0f; q.DY = 0f; q.DZ = 0f;
                q.W = w[i];
            }
        }

        /// <summary>The packed inverse masses again (a pin broke in the step).</summary>
        private void PackFusedMasses()
        {
            FusedChain.Particle[] packed = fused.Particles;
            for (int i = 0; i < packed.Length; i++) packed[i].W = chain.InverseMass[i];
        }

        /// <summary>
        /// The segments' constants for substep h (s): rest length, α̃ = α/h², γ = β/h (0 when α = 0, as the precise sweep),
        /// 1/((1 + γ)(w_a + w_b) + α̃) (0 for a broken segment or a rigid one between two pinned ends); with
        /// <paramref name="restart"/> (the start of a host step) λ's minimum and sum restart.
        /// </summary>
        private void PackFusedSegments(double h, bool restart)
        {
            int s = chain.SegmentCount;
            Span<FusedChain.Segment> packed = fused.Segments;
            ReadOnlySpan<float> rest = ChainState.Exactly(chain.RestLength, s), compliance = ChainState.Exactly(chain.Compliance, s);
            ReadOnlySpan<float> wA = ChainState.Exactly(chain.InverseMass, s), wB = ChainState.Shifted(chain.InverseMass, s);
            ReadOnlySpan<bool> broken = ChainState.Exactly(chain.Broken, s);
            if (packed.Length != s) ChainState.ThrowSizes();
            double invH2 = 1.0 / (h * h), gamma = settings.Damping / h;
            for (int j = 0; j < s; j++)
            {
                ref FusedChain.Segment q = ref packed[j];
                double alpha = compliance[j], alphaTilde = alpha * invH2, g = alpha > 0.0 ? gamma : 0.0;
                double denominator = (1.0 + g) * ((double)wA[j] + wB[j]) + alphaTilde;
                q.Rest = rest[j];
                q.AlphaTilde = (float)alphaTilde;
                q.Gamma = (float)g;
                q.InverseDenominator = broken[j] || !(denominator > 0.0) ? 0f : (float)(1.0 / denominator);
                if (!restart) continue;
                q.LambdaMin = float.MaxValue;
                q.LambdaSum = 0f;
            }
        }

        /// <summary>The rigid pins' motion over the substep to their targets at fraction t of the host step: their particles' displacement.</summary>
        private void MoveFusedPins(float t)
        {
            FusedChain.Particle[] packed = fused.Particles;
            for (int p = 0; p < pinCount; p++)
            {
                if (pinBroken[p] || pinCompliance[p] != 0f) continue;
                ref FusedChain.Particle q = ref packed[pinParticle[p]];
                Float3 target = PinTarget(p, t);
                q.DX = target.X - q.X; q.DY = target.Y - q.Y; q.DZ = target.Z - q.Z;
            }
        }

        /// <summary>Each load's substep force, as <see cref="TrackLoadPeaks"/> with the packed velocity (invH = 1/h, 1/s).</summary>
        private void TrackFusedLoadPeaks(float invH, Float3 g)
        {
            for (int l = 0; l < loadCount; l++)
            {
                ref FusedChain.Particle q = ref fused.Particles[loadParticle[l]];
                var v = new Float3(q.VX, q.VY, q.VZ);
                float force = (((v - loadSubstepVelocity[l]) * invH - g) * loadMass[l]).Length;
                if (force > loadPeakForce[l]) loadPeakForce[l] = force;
                loadSubstepVelocity[l] = v;
            }
        }

        /// <summary>
        /// The rigid pins' forces from this substep (h s): m·g plus the adjacent segments' tensions −λ/h² along their
        /// current directions, as <see cref="UpdatePinForces"/>; a pin above its break force breaks. Returns true when one broke.
        /// </summary>
        private bool UpdateFusedPinForces(double h, Float3 g)
        {
            double invH2 = 1.0 / (h * h);
            bool released = false;
            for (int p = 0; p < pinCount; p++)
            {
                if (pinBroken[p]) continue;
                int i = pinParticle[p];
                Float3 force = g * chain.Mass[i];
                if (i < chain.SegmentCount && !chain.Broken[i]) force += FusedDirection(i) * (float)(-fused.Segments[i].Lambda * invH2);
                if (i > 0 && !chain.Broken[i - 1]) force -= FusedDirection(i - 1) * (float)(-fused.Segments[i - 1].Lambda * invH2);
                if (SetPinForce(p, force)) released = true;
            }
            if (released) RefreshKinematic();
            return released;
        }

        /// <summary>Unit direction of packed segment j (particle j to j + 1), or the chain's last stored direction when it vanishes.</summary>
        private Float3 FusedDirection(int j)
        {
            ref FusedChain.Particle a = ref fused.Particles[j];
            ref FusedChain.Particle b = ref fused.Particles[j + 1];
            var e = new Float3(b.X - a.X, b.Y - a.Y, b.Z - a.Z);
            float length = e.Length;
            return length > 1e-12f && length <= float.MaxValue ? e * (1f / length) : new Float3(chain.DirX[j], chain.DirY[j], chain.DirZ[j]);
        }

        /// <summary>
        /// Writes the packed chain back (h s, substeps per host step): positions with no remainder, velocities, the
        /// segments' tensions, peaks, means, lengths and directions. A particle whose position or velocity is not finite
        /// falls back to its position at the start of the step, at rest.
        /// </summary>
        private void UnpackFused(double h, int substeps)
        {
            int n = chain.ParticleCount, s = chain.SegmentCount;
            ReadOnlySpan<FusedChain.Particle> packed = fused.Particles;
            Span<float> x = ChainState.Exactly(chain.X, n), y = ChainState.Exactly(chain.Y, n), z = ChainState.Exactly(chain.Z, n);
            Span<float> lx = ChainState.Exactly(chain.LowX, n), ly = ChainState.Exactly(chain.LowY, n), lz = ChainState.Exactly(chain.LowZ, n);
            Span<double> vx = ChainState.Exactly(chain.VelX, n), vy = ChainState.Exactly(chain.VelY, n), vz = ChainState.Exactly(chain.VelZ, n);
            ReadOnlySpan<float> sx = ChainState.Exactly(chain.StepStartX, n), sy = ChainState.Exactly(chain.StepStartY, n), sz = ChainState.Exactly(chain.StepStartZ, n);
            if (packed.Length != n) ChainState.ThrowSizes();
            for (int i = 0; i < n; i++)
            {
                ref readonly FusedChain.Particle q = ref packed[i];
                if (float.IsFinite(q.X + q.Y + q.Z + q.VX + q.VY + q.VZ))
                {
                    x[i] = q.X; y[i] = q.Y; z[i] = q.Z;
                    vx[i] = q.VX; vy[i] = q.VY; vz[i] = q.VZ;
                }
                else
                {
                    x[i] = sx[i]; y[i] = sy[i]; z[i] = sz[i];
                    vx[i] = 0.0; vy[i] = 0.0; vz[i] = 0.0;
                }
                lx[i] = 0f; ly[i] = 0f; lz[i] = 0f;
            }
            ReadOnlySpan<FusedChain.Segment> segments = fused.Segments;
            ReadOnlySpan<float> xA = ChainState.Exactly(chain.X, s), yA = ChainState.Exactly(chain.Y, s), zA = ChainState.Exactly(chain.Z, s);
            ReadOnlySpan<float> xB = ChainState.Shifted(chain.X, s), yB = ChainState.Shifted(chain.Y, s), zB = ChainState.Shifted(chain.Z, s);
            Span<float> tension = ChainState.Exactly(chain.Tension, s), peak = ChainState.Exactly(chain.PeakTension, s), mean = ChainState.Exactly(chain.MeanTension, s);
            Span<float> length = ChainState.Exactly(chain.Length, s);
            Span<float> dirX = ChainState.Exactly(chain.DirX, s), dirY = ChainState.Exactly(chain.DirY, s), dirZ = ChainState.Exactly(chain.DirZ, s);
            Span<double> lambda = ChainState.Exactly(chain.Lambda, s);
            ReadOnlySpan<bool> broken = ChainState.Exactly(chain.Broken, s);
            if (segments.Length != s) ChainState.ThrowSizes();
            double invH2 = 1.0 / (h * h), meanScale = invH2 / substeps;
            for (int j = 0; j < segments.Length; j++)
            {
                ref readonly FusedChain.Segment q = ref segments[j];
                bool intact = !broken[j];
                lambda[j] = intact ? q.Lambda : 0.0;
                tension[j] = intact ? Tension(q.Lambda, invH2) : 0f;
                peak[j] = intact ? Tension(q.LambdaMin, invH2) : 0f;
                mean[j] = intact ? Tension(q.LambdaSum, meanScale) : 0f;
                float ex = xB[j] - xA[j], ey = yB[j] - yA[j], ez = zB[j] - zA[j];
                float len = MathF.Sqrt(ex * ex + ey * ey + ez * ez);
                length[j] = len;
                if (len > 1e-12f && len <= float.MaxValue)
                {
                    float inv = 1f / len;
                    dirX[j] = ex * inv; dirY[j] = ey * inv; dirZ[j] = ez * inv;
                }
            }
        }
    }
}
