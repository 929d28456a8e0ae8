using HookeRope.Solver;

namespace HookeRope.Lab.Stability
{
    /// <summary>What a <see cref="GridCase"/> checks besides finiteness and energy.</summary>
    public enum GridFamily
    {
        /// <summary>Undamped, 1 s (0.25 s at 10 000 segments): no energy above the energy put in.</summary>
        Undamped,
        /// <summary>Damped (drag and material damping) for long enough that the physics settles it: it comes to rest, hanging from its anchor.</summary>
        Settle,
        /// <summary>Undamped, 1 s, 16 segments swinging into a sphere with Coulomb friction μ 0.3: no energy above the energy put in.</summary>
        Friction,
        /// <summary>Damped, the anchor jumps 1 km after 0.5 s: no energy above the energy right after the jump, and it comes to rest under the new anchor.</summary>
        Teleport,
    }

    /// <summary>One case of the integrator grid sweep (<see cref="GridSweep"/>): the axes of issue 14 item 4.</summary>
    public sealed class GridCase
    {
        /// <summary>Young's modulus E, Pa.</summary>
        public double YoungsModulus;
        /// <summary>Load mass over the mass of one rope particle (0 = no load).</summary>
        public double MassRatio;
        /// <summary>Host step, s.</summary>
        public double HostStep;
        /// <summary>Segments.</summary>
        public int Segments;
        /// <summary>Initial length over rest length (1 = laid at rest length).</summary>
        public double Stretch;
        /// <summary>Time integrator.</summary>
        public TimeIntegrator Integrator;
        /// <summary>Rope or rod.</summary>
        public TensionModel Tension;
        /// <summary>With a sphere collider beside the rope's path.</summary>
        public bool Collider;
        /// <summary>Coulomb friction coefficient μ of the sphere (0: frictionless).</summary>
        public float Friction;
        /// <summary>What the case checks.</summary>
        public GridFamily Family;
        /// <summary>Linear drag rate k (1/s): every particle and load feels −k·m·v (0 = none; see <see cref="GridSweep.Drag"/>).</summary>
        public double Drag;
        /// <summary>The rope's own viscous drag c, N·s/m² (<see cref="RopeSettings.ViscousDrag"/>; the teleport cases).</summary>
        public float ViscousDrag;
        /// <summary>The rope's own quadratic air drag coefficient C_d (<see cref="RopeSettings.DragCoefficient"/>; the teleport cases).</summary>
        public float DragCoefficient;
        /// <summary>XPBD material damping β, s.</summary>
        public float Damping;
        /// <summary>Simulated time, s.</summary>
        public double Duration;

        /// <summary>The anchor jumps 1 km after 0.5 s.</summary>
        public bool Teleport => Family == GridFamily.Teleport;

        /// <summary>Damped: it must come to rest.</summary>
        public bool Damped => Family == GridFamily.Settle || Family == GridFamily.Teleport;

        /// <summary>Rest length of the rope, m: 1 m, or 100 m for 10 000 segments (1 cm segments).</summary>
        public double RestLength => Segments >= 10000 ? 100.0 : 1.0;

        /// <summary>One line naming every axis.</summary>
        public override string ToString() =>
            $"E {YoungsModulus:G3} Pa, ratio {MassRatio:G3}, dt 1/{1.0 / HostStep:G4} s, {Segments} seg, stretch {Stretch:G3}, {Integrator}, {Tension}" +
            (Collider ? (Friction > 0f ? $", collider μ {Friction:G2}" : ", collider") : "") + (Teleport ? ", 1 km teleport" : "") +
            (Teleport ? $", rope drag c {ViscousDrag:G3} N·s/m² + C_d {DragCoefficient:G3}, β {Damping:G3} s, {Duration:G4} s" :
             Damped ? $", damped (drag {Drag:G3}/s, β {Damping:G3} s, {Duration:G4} s)" : "");
    }
}
