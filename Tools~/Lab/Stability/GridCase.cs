using HookeRope.Solver;

namespace HookeRope.Lab.Stability
{
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
        /// <summary>The anchor jumps 1 km after 0.5 s, and the run (damped, β = <see cref="GridSweep.RecoveryDamping"/>) must bring the rope back under it.</summary>
        public bool Teleport;
        /// <summary>Simulated time, s.</summary>
        public double Duration;

        /// <summary>Rest length of the rope, m: 1 m, or 100 m for 10 000 segments (1 cm segments).</summary>
        public double RestLength => Segments >= 10000 ? 100.0 : 1.0;

        /// <summary>One line naming every axis.</summary>
        public override string ToString() =>
            $"E {YoungsModulus:G3} Pa, ratio {MassRatio:G3}, dt 1/{1.0 / HostStep:G4} s, {Segments} seg, stretch {Stretch:G3}, {Integrator}, {Tension}" +
            (Collider ? ", collider" : "") + (Teleport ? ", 1 km teleport" : "");
    }
}
