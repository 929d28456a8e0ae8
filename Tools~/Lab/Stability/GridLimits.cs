using HookeRope.Solver;

namespace HookeRope.Lab.Stability
{
    /// <summary>
    /// The documented domain limits of the stability grid (solver.md, "Stability sweep"): failing cases whose failure has a
    /// known cause in the solver's design, named with it. A failing case that matches none is an undocumented failure, and
    /// <c>stability --full</c> exits 1 for it. The limits are stated, counted and listed case by case, never skipped.
    /// </summary>
    public static class GridLimits
    {
        /// <summary>Coulomb friction is a position correction after the chain solve.</summary>
        public const string Friction =
            "friction after the solve: Coulomb friction moves a contact particle back along the surface after the last chain " +
            "iteration (CollisionSet.Resolve), unopposed by the chain, so on a stiff rope it stretches the segments at the " +
            "contact (½δ²/α) and their tension turns that into motion next substep; friction inside the solve is not built";

        /// <summary>A pushing (bilateral) segment's transverse response is damped buckling, not the exact implicit step.</summary>
        public const string Rod =
            "rod in compression: a bilateral segment that pushes takes |T| for its geometric stiffness (ExactChainSolver.Assemble: " +
            "the exact −|T|/l would let it buckle explicitly), so its substep is damped buckling, not the minimiser of the " +
            "implicit step's energy, and nothing bounds the energy it can gain";

        /// <summary>The collision pass after the last iteration pushes particles out of the collider without the chain.</summary>
        public const string Push =
            "push after the solve: the collision pass after the last chain iteration pushes particles out of the sphere " +
            "(ContactPass.LastIteration) without the chain, storing ½δ²/α in the segments at the pushed particle (1 µm on a " +
            "6 cm steel segment is 0.1 mJ) that the next substep releases, and keeps a rope resting on the sphere from coming " +
            "quite to rest; solving again after the push was tried and failed more cases";

        /// <summary>
        /// The limit a failing case falls under, or null (an undocumented failure, or a case that passed). Non-finite
        /// results and escapes are never a documented limit.
        /// </summary>
        public static string Explain(GridOutcome o)
        {
            if (!o.Failed || !o.Finite || o.Escaped || o.NotRecovered) return null;
            GridCase c = o.Case;
            if (c.Collider && c.Friction > 0f) return Friction;
            if (c.Tension == TensionModel.Bilateral) return Rod;
            if (c.Collider) return Push;
            return null;
        }
    }
}
