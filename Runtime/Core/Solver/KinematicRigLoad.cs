using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// Couples a rope load with a host rig that has no rigid body (a character controller, a kinematic XR rig): the
    /// rope carries the rig as a point mass inside its own implicit solve, and the host moves the rig to where that
    /// mass ended. Before a step the load takes the rig's position x₀ and the velocity
    /// v₀ = v₁⁻ + (x₀ − x₁⁻)/Δt: the load's final velocity of the last step plus the rig's deviation from where it was
    /// told to go (x₁⁻) over the step — a finite difference of the rig between steps with the rope's end-of-step
    /// velocity kept. A rig stopped by a wall loses the blocked velocity; a rig moved exactly as told keeps the
    /// rope's. <see cref="SetVelocity"/> replaces v₀ for the next step (a rig script's own velocity, or after a
    /// teleport). After the step the host moves the rig by <see cref="Displacement"/> = x₁ − x₀. No force crosses
    /// the boundary, so the coupling is as stable as the rope's solve for any stiffness (an explicit force on a
    /// kinematic integrator diverges once ω·Δt &gt; 2, ω = sqrt(k/M)). Allocation-free.
    /// </summary>
    internal sealed class KinematicRigLoad
    {
        Float3 _start, _told, _velocity;
        bool _started, _velocitySet;

        /// <summary>Displacement in metres (world axes) the host gives its rig for the last step: x₁ − x₀. Zero before the first step.</summary>
        public Float3 Displacement { get; private set; }

        /// <summary>Velocity in m/s (world axes) the next step starts from, before the deviation term: the load's velocity after the last step, or the value given to <see cref="SetVelocity"/>.</summary>
        public Float3 Velocity => _velocity;

        /// <summary>
        /// Sets the rig velocity (m/s, world axes, finite) the next step starts from, replacing the finite difference
        /// for that step. NaN/∞ → ArgumentException, state untouched.
        /// </summary>
        public void SetVelocity(Float3 velocity)
        {
            if (!velocity.IsFinite)
                throw new ArgumentException("velocity must be a finite velocity in m/s", nameof(velocity));
            _velocity = velocity;
            _velocitySet = true;
        }

        /// <summary>Forgets the rig's history: the next step starts at rest (or from <see cref="SetVelocity"/>), with no deviation term.</summary>
        public void Reset()
        {
            _started = _velocitySet = false;
            _velocity = Displacement = Float3.Zero;
        }

        /// <summary>
        /// Before a rope step of <paramref name="deltaTime"/> s (&gt; 0): writes the rig's position
        /// <paramref name="rigPosition"/> (m, the rope's world frame) and its velocity into <paramref name="load"/>.
        /// <paramref name="rounding"/> (m, ≥ 0) is the rounding of the host's position (its float resolution where the
        /// rig is): a deviation from where the rig was told to go no larger than that is rounding, not motion, and is
        /// left out (at 20 m from the origin, 2 µm of rounding over a 0.02 s step would be 0.1 mm/s of false velocity
        /// every step).
        /// </summary>
        public void BeforeStep(Rope rope, int load, Float3 rigPosition, float deltaTime, float rounding = 0f)
        {
            if (!(deltaTime > 0f)) throw new ArgumentOutOfRangeException(nameof(deltaTime), deltaTime, "deltaTime must be in (0, +inf) s");
            Float3 velocity = _velocity;
            Float3 deviation = rigPosition - _told;
            if (_started && !_velocitySet && deviation.Length > rounding) velocity += deviation * (1f / deltaTime);
            rope.SetLoadState(load, rigPosition, velocity);
            _start = rigPosition;
            _started = true;
            _velocitySet = false;
        }

        /// <summary>After the rope step: where the load ended becomes where the rig must go (<see cref="Displacement"/>).</summary>
        public void AfterStep(Rope rope, int load)
        {
            _told = rope.GetLoadPosition(load);
            _velocity = rope.GetLoadVelocity(load);
            Displacement = _told - _start;
        }
    }
}
