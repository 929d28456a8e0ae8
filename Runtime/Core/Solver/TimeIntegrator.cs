namespace HookeRope.Solver
{
    /// <summary>
    /// Time integration of each substep. Both schemes predict the particles, run the same constraint solve (exact chain or
    /// Gauss–Seidel, tension-only passes, contacts, pins) with their own effective compliance, and then set the velocities
    /// by their own rule. See Documentation~/solver.md ("Time integration") for the equations and the measured dissipation.
    /// </summary>
    public enum TimeIntegrator
    {
        /// <summary>
        /// Backward (implicit) Euler: v += g·h, x = x + v·h, solve with α̃ = α/h², v = Δx/h. First order. Most robust,
        /// dissipative: an oscillation of angular frequency ω decays like exp(−ω²·h·t/2).
        /// </summary>
        BackwardEuler,
        /// <summary>
        /// Second-order backward differentiation (BDF2): solve with α̃ = 9α/(4h²). L-stable: damps the highest chain modes,
        /// slow modes lose amplitude ∝ ω⁴·h³·t. Starts (and restarts after a change of h or of the integrator) with one
        /// backward-Euler substep.
        /// </summary>
        Bdf2,
    }
}
