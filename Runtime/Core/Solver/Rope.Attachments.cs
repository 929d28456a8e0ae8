using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    public sealed partial class Rope
    {
        // pins (targets in the rope-local frame)
        private int pinCount;
        private int[] pinParticle = new int[0];
        private Float3[] pinStart = new Float3[0], pinEnd = new Float3[0], pinForce = new Float3[0];
        private float[] pinCompliance = new float[0], pinBreakForce = new float[0];
        private bool[] pinBroken = new bool[0];
        private double[] pinLambda = new double[0];   // 3 per pin, N·s²

        // loads
        private int loadCount;
        private int[] loadParticle = new int[0];
        private float[] loadMass = new float[0];
        private Float3[] loadStartVelocity = new Float3[0], loadStartPosition = new Float3[0], loadForce = new Float3[0];
        private Float3[] loadSubstepVelocity = new Float3[0];   // load velocity at the end of the previous substep, m/s
        private float[] loadPeakForce = new float[0];           // largest substep load force of the last host step, N
        private float lastStepTime;

        /// <summary>Number of pins added so far (broken ones included).</summary>
        public int PinCount => pinCount;

        /// <summary>Number of loads added so far.</summary>
        public int LoadCount => loadCount;

        /// <summary>Number of colliders added so far.</summary>
        public int ColliderCount => colliders.Count;

        /// <summary>The colliders (tests and the bench compare the broad phase with the brute-force pass through it).</summary>
        internal CollisionSet Collisions => colliders;

        /// <summary>
        /// Pins a particle to a kinematic target (world m) that the host moves with <see cref="SetPinTarget"/>
        /// (an XR hand, an anchor). compliance (m/N, finite, ≥ 0): 0 = rigid — the particle becomes kinematic
        /// and is placed on the target now; &gt; 0 = a zero-length XPBD spring of stiffness 1/compliance.
        /// breakForce (N, &gt; 0, +inf = never): the pin releases when the rope pulls on it harder.
        /// Returns the pin index.
        /// </summary>
        public int AddPin(int particle, Float3 target, float compliance = 0f, float breakForce = float.PositiveInfinity)
        {
            CheckParticle(particle);
            CheckFinite(target, nameof(target), "a finite position in metres");
            if (!float.IsFinite(compliance) || compliance < 0f) throw new ArgumentOutOfRangeException(nameof(compliance), compliance, "compliance must be finite and in [0, +inf) m/N");
            if (float.IsNaN(breakForce) || breakForce <= 0f) throw new ArgumentOutOfRangeException(nameof(breakForce), breakForce, "breakForce must be in (0, +inf] N");
            if (pinCount == pinParticle.Length)
            {
                int size = ArrayGrowth.NextCapacity(pinCount);
                Array.Resize(ref pinParticle, size);
                Array.Resize(ref pinStart, size);
                Array.Resize(ref pinEnd, size);
                Array.Resize(ref pinForce, size);
                Array.Resize(ref pinCompliance, size);
                Array.Resize(ref pinBreakForce, size);
                Array.Resize(ref pinBroken, size);
                Array.Resize(ref pinLambda, size * 3);
            }
            int p = pinCount++;
            Float3 local = target - Origin;
            pinParticle[p] = particle;
            pinStart[p] = pinEnd[p] = local;
            pinForce[p] = Float3.Zero;
            pinCompliance[p] = compliance;
            pinBreakForce[p] = breakForce;
            pinBroken[p] = false;
            if (compliance == 0f)
            {
                chain.Place(particle, local.X, local.Y, local.Z);
                chain.VelX[particle] = chain.VelY[particle] = chain.VelZ[particle] = 0f;
                RefreshKinematic();
                RefreshLengths();
            }
            return p;
        }

        /// <summary>Pins the particle nearest to <paramref name="fraction"/> ∈ [0, 1] along the rope (0 = first particle); see <see cref="AddPin"/>.</summary>
        public int AddPinAtFraction(float fraction, Float3 target, float compliance = 0f, float breakForce = float.PositiveInfinity)
        {
            if (!(fraction >= 0f && fraction <= 1f)) throw new ArgumentOutOfRangeException(nameof(fraction), fraction, "fraction must be in [0, 1]");
            return AddPin((int)MathF.Round(fraction * chain.SegmentCount), target, compliance, breakForce);
        }

        /// <summary>Moves a pin's target (world m). The particle follows linearly across the substeps of the next step. NaN/∞ → ArgumentException, rope untouched.</summary>
        public void SetPinTarget(int pin, Float3 target)
        {
            CheckPin(pin);
            CheckFinite(target, nameof(target), "a finite position in metres");
            pinEnd[pin] = target - Origin;
        }

        /// <summary>Current target of a pin in world metres.</summary>
        public Float3 GetPinTarget(int pin)
        {
            CheckPin(pin);
            return Origin + pinEnd[pin];
        }

        /// <summary>
        /// Force in newtons the rope exerts on the pin target over the last substep (world axes). Rigid pin: the
        /// pull of the adjacent segments plus the weight of the pinned particle's lumped mass (the inertia of
        /// a moving target is not included). Compliant pin: the spring force. Zero once broken.
        /// </summary>
        public Float3 GetPinForce(int pin)
        {
            CheckPin(pin);
            return pinForce[pin];
        }

        /// <summary>True when the pin released because its force passed the break force.</summary>
        public bool IsPinBroken(int pin)
        {
            CheckPin(pin);
            return pinBroken[pin];
        }

        /// <summary>Releases a pin now (the particle becomes free, keeping its velocity).</summary>
        public void ReleasePin(int pin)
        {
            CheckPin(pin);
            if (pinBroken[pin]) return;
            pinBroken[pin] = true;
            pinForce[pin] = Float3.Zero;
            RefreshKinematic();
        }

        /// <summary>
        /// Lumps a point mass (kg, finite, &gt; 0) into a particle: a worker, a weight, or a host rigid body.
        /// The particle then carries that mass's gravity and inertia. Returns the load index.
        /// </summary>
        public int AddLoad(int particle, float mass)
        {
            CheckParticle(particle);
            if (!float.IsFinite(mass) || mass <= 0f) throw new ArgumentOutOfRangeException(nameof(mass), mass, "mass must be finite and in (0, +inf) kg");
            if (loadCount == loadParticle.Length)
            {
                int size = ArrayGrowth.NextCapacity(loadCount);
                Array.Resize(ref loadParticle, size);
                Array.Resize(ref loadMass, size);
                Array.Resize(ref loadStartVelocity, size);
                Array.Resize(ref loadStartPosition, size);
                Array.Resize(ref loadForce, size);
                Array.Resize(ref loadSubstepVelocity, size);
                Array.Resize(ref loadPeakForce, size);
            }
            int l = loadCount++;
            loadParticle[l] = particle;
            loadMass[l] = mass;
            loadForce[l] = Float3.Zero;
            loadPeakForce[l] = 0f;
            chain.LoadMass[particle] += mass;
            UpdateMass(particle, settings.LinearDensity);
            return l;
        }

        /// <summary>
        /// Takes a load's mass (kg) back out of its particle (the host body is gone): the particle keeps its position
        /// and velocity and carries only its share of the rope's mass again; the load's forces read zero from the
        /// next step on. Releasing a released load does nothing. Allocation-free.
        /// </summary>
        public void ReleaseLoad(int load)
        {
            CheckLoad(load);
            float mass = loadMass[load];
            if (mass == 0f) return;
            int particle = loadParticle[load];
            chain.LoadMass[particle] = Math.Max(0f, chain.LoadMass[particle] - mass);
            loadMass[load] = 0f;
            loadForce[load] = Float3.Zero;
            loadPeakForce[load] = 0f;
            UpdateMass(particle, settings.LinearDensity);
        }

        /// <summary>True once <see cref="ReleaseLoad"/> took the load's mass out of its particle.</summary>
        public bool IsLoadReleased(int load)
        {
            CheckLoad(load);
            return loadMass[load] == 0f;
        }

        /// <summary>Particle index a load is lumped into.</summary>
        public int GetLoadParticle(int load)
        {
            CheckLoad(load);
            return loadParticle[load];
        }

        /// <summary>
        /// Mean force in newtons (world axes) that everything but gravity — the rope, colliders — exerted on the
        /// load over the last host step: M·(Δv/Δt − g). Static hang: −M·g; zero while the rope is slack.
        /// </summary>
        public Float3 GetLoadForce(int load)
        {
            CheckLoad(load);
            return loadForce[load];
        }

        /// <summary>
        /// Largest magnitude in newtons, over the substeps of the last host step, of the force everything but gravity
        /// exerted on the load during one substep: |M·(Δv/h − g)|. A short peak (a snatch lasting a few host steps)
        /// that <see cref="GetLoadForce"/>'s mean over the host step flattens still reads. Zero once released.
        /// </summary>
        public float GetLoadPeakForce(int load)
        {
            CheckLoad(load);
            return loadPeakForce[load];
        }

        /// <summary>Impulse in N·s the rope gave the load over the last host step (GetLoadForce × Δt). The host applies it to its rigid body.</summary>
        public Float3 GetLoadImpulse(int load)
        {
            CheckLoad(load);
            return loadForce[load] * lastStepTime;
        }

        /// <summary>
        /// Force in newtons (world axes) that a host integrating the load as a rigid body by semi-implicit Euler
        /// (v₁ = v₀ + (F/M + g)·Δt, then x₁ = x₀ + v₁·Δt: PhysX's order) applies over the last host step so that its body
        /// ends exactly where the load particle ended: M·((x₁ − x₀)/Δt² − v₀/Δt − g). Its body then carries the mean
        /// velocity of the step; <see cref="GetLoadHostVelocityCorrection"/> supplies the rest of the rope's impulse.
        /// Applying <see cref="GetLoadForce"/> instead leaves the body short of (or past) the particle by about
        /// a·Δt²/2 every step, and resetting the particle to the body then discards stretch energy: a 4 m fall arrest
        /// coupled that way reads its peak force 6 % low at 90 Hz and 9 % low at 50 Hz.
        /// </summary>
        public Float3 GetLoadHostForce(int load)
        {
            CheckLoad(load);
            if (lastStepTime <= 0f) return Float3.Zero;
            float invDt = 1f / lastStepTime;
            var displacement = GetPosition(loadParticle[load]) - loadStartPosition[load];
            return (displacement * (invDt * invDt) - loadStartVelocity[load] * invDt - settings.Gravity) * loadMass[load];
        }

        /// <summary>
        /// Velocity change in m/s (world axes) the host gives its body at the start of the next step, after
        /// <see cref="GetLoadHostForce"/>, so that the body also carries the load particle's final velocity: v₁ − (x₁ − x₀)/Δt.
        /// With both, the host receives exactly the rope's impulse of the step (<see cref="GetLoadImpulse"/>) and the
        /// body and the particle agree in position and velocity.
        /// </summary>
        public Float3 GetLoadHostVelocityCorrection(int load)
        {
            CheckLoad(load);
            if (lastStepTime <= 0f) return Float3.Zero;
            int i = loadParticle[load];
            return GetVelocity(i) - (GetPosition(i) - loadStartPosition[load]) * (1f / lastStepTime);
        }

        /// <summary>World position of the load (its particle) in metres.</summary>
        public Float3 GetLoadPosition(int load)
        {
            CheckLoad(load);
            return GetPosition(loadParticle[load]);
        }

        /// <summary>Velocity of the load (its particle) in m/s.</summary>
        public Float3 GetLoadVelocity(int load)
        {
            CheckLoad(load);
            return GetVelocity(loadParticle[load]);
        }

        /// <summary>
        /// Overwrites the load particle's state with the host body's (world m, m/s) before a step: two-way
        /// coupling with a rigid body. NaN/∞ → ArgumentException, rope untouched.
        /// </summary>
        public void SetLoadState(int load, Float3 position, Float3 velocity)
        {
            CheckLoad(load);
            CheckFinite(position, nameof(position), "a finite position in metres");
            CheckFinite(velocity, nameof(velocity), "a finite velocity in m/s");
            int i = loadParticle[load];
            SetPosition(i, position);
            SetVelocity(i, velocity);
        }

        /// <summary>Adds a collider (plane, sphere, capsule, box; world pose). Collision work is skipped entirely while a rope has none. Returns its index.</summary>
        public int AddCollider(in ColliderShape shape)
        {
            if (shape.Rotation.LengthSquared == 0f) throw new ArgumentException("shape must be built with ColliderShape.Plane/Sphere/Capsule/Box", nameof(shape));
            chain.EnsureContacts();
            int index = colliders.Add(shape, shape.Position - Origin);
            colliders.Reserve(chain.ParticleCount);
            return index;
        }

        /// <summary>
        /// Removes a collider (index in [0, ColliderCount − 1]); the colliders after it move down one index (k + 1 becomes k),
        /// so re-read the indices of later colliders. Current contacts are forgotten and found again at the next step.
        /// Allocation-free; with no collider left the collision work is skipped again.
        /// </summary>
        public void RemoveCollider(int collider)
        {
            if ((uint)collider >= (uint)colliders.Count) throw new ArgumentOutOfRangeException(nameof(collider), collider, "collider must be in [0, " + (colliders.Count - 1) + "]");
            colliders.RemoveAt(collider);
            chain.ClearContacts();
        }

        /// <summary>Removes every collider (for a host that re-gathers its colliders, e.g. by layer mask, each frame). Allocation-free.</summary>
        public void ClearColliders()
        {
            colliders.Clear();
            chain.ClearContacts();
        }

        /// <summary>Moves a collider to a new world pose (m); the motion is spread over the substeps of the next step. NaN → ArgumentException.</summary>
        public void SetColliderPose(int collider, Float3 position, Quat rotation)
        {
            if ((uint)collider >= (uint)colliders.Count) throw new ArgumentOutOfRangeException(nameof(collider), collider, "collider must be in [0, " + (colliders.Count - 1) + "]");
            CheckFinite(position, nameof(position), "a finite position in metres");
            if (!rotation.IsFinite || !(rotation.LengthSquared > 1e-12f)) throw new ArgumentException("rotation must be a finite, non-zero quaternion", nameof(rotation));
            colliders.SetPose(collider, position - Origin, rotation);
        }

        /// <summary>Signed distance in metres from a world point to the surface of a collider (negative inside), at its latest pose.</summary>
        public float ColliderDistance(int collider, Float3 point)
        {
            if ((uint)collider >= (uint)colliders.Count) throw new ArgumentOutOfRangeException(nameof(collider), collider, "collider must be in [0, " + (colliders.Count - 1) + "]");
            return colliders.SignedDistance(collider, point - Origin, out _);
        }

        private void RefreshKinematic()
        {
            for (int i = 0; i < chain.ParticleCount; i++) chain.Kinematic[i] = false;
            for (int p = 0; p < pinCount; p++)
                if (!pinBroken[p] && pinCompliance[p] == 0f) chain.Kinematic[pinParticle[p]] = true;
            chain.ListKinematic();
            float mu = settings.LinearDensity;
            for (int i = 0; i < chain.ParticleCount; i++) UpdateMass(i, mu);
        }

        private double PinEnergy()
        {
            double e = 0.0;
            for (int p = 0; p < pinCount; p++)
            {
                if (pinBroken[p] || pinCompliance[p] == 0f) continue;
                int i = pinParticle[p];
                double dx = (double)chain.X[i] - pinEnd[p].X + chain.LowX[i], dy = (double)chain.Y[i] - pinEnd[p].Y + chain.LowY[i];
                double dz = (double)chain.Z[i] - pinEnd[p].Z + chain.LowZ[i];
                e += 0.5 * (dx * dx + dy * dy + dz * dz) / pinCompliance[p];
            }
            return e;
        }

        private void CheckPin(int pin)
        {
            if ((uint)pin >= (uint)pinCount) throw new ArgumentOutOfRangeException(nameof(pin), pin, "pin must be in [0, " + (pinCount - 1) + "]");
        }

        private void CheckLoad(int load)
        {
            if ((uint)load >= (uint)loadCount) throw new ArgumentOutOfRangeException(nameof(load), load, "load must be in [0, " + (loadCount - 1) + "]");
        }
    }
}
