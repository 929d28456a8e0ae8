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
        /// <summary>
        /// A stiff rope held on a sphere with friction: the exact solve's friction-held iterations keep their full step and
        /// only the plain 10⁻³ length test, so length errors stay in the segments at the contact.
        /// </summary>
        public const string Friction =
            "friction on a stiff rope: Coulomb friction is inside the exact chain solve (ChainContacts), but an iteration " +
            "with a contact held on a surface with friction keeps its full Newton step and only the 10⁻³ length test " +
            "(ExactChainSolver.Iterate: the line search's objective has no friction, and the energy test of the length errors " +
            "made the 2π box wrap at μ 0.6 slide 145 m in 2 s), so on a 200 GPa rope the segments at a sticking contact keep " +
            "length errors e whose ½e²/α shows as an elastic energy gain (17 cases since the secant friction update, " +
            "ChainContacts.Secant, and the pure-axial pushing segment, was 20; the motion alone gains nothing in 11 of them; " +
            "the other 6, one of them 1.8 MJ, also gain motion, their cause not isolated beyond this; giving friction-held iterations the energy test again " +
            "passed one more case and made the 2π box wrap at μ 0.6 slide 38 m)";

        /// <summary>
        /// A bilateral chain that pushes and folds against the sphere: its violent substeps do not converge, and the length
        /// errors they leave store energy.
        /// </summary>
        public const string Rod =
            "rod in compression: a pushing bilateral segment takes no geometric stiffness in the exact solve (ExactChainSolver." +
            "Assemble: its exact −|T|/l makes the implicit step's energy non-convex across it), so the iteration converges only " +
            "linearly where a pushing chain folds: the two undamped 1 GPa 256-segment rods folding against the sphere (BDF2) " +
            "gain 0.2 J of motion (1/90 s) and 14.8 J, 2.1 J of it motion (1/30 s, load ratio 10³, in violent substeps of up to " +
            "32 iterations); taking a pure-axial segment's residual along the segment instead of along its lagging force " +
            "(solver.md, \"Rods in compression\") removed the 151 J its fold stored at 1/90 s and passed the 45 t load on a " +
            "2-segment steel rod hitting the sphere (+9.4 kJ) and the damped 256-segment steel rod (+0.226 J); negative " +
            "geometric stiffness bounded to keep the Newton matrix positive definite, and a line search on every iteration of a " +
            "violent substep, were measured and failed more cases";

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
            // a rod's failure is an energy gain of a rope that pushed; a bilateral rope resting on the sphere that does not
            // come quite to rest fails as its tension-only twin does (the 2-segment cases: 8.96e-7 J against 8.88e-7 J), under Push
            if (c.Tension == TensionModel.Bilateral && o.LargestPush > 0.0 && (o.GainedEnergy || !c.Collider)) return Rod;
            if (c.Collider) return Push;
            return null;
        }
    }
}
