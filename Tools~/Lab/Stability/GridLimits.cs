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
        /// A stiff rope held on a sphere with friction at 1/90 s: no case left in the full sweep (the last one, whose
        /// frictionless twin failed under <see cref="Push"/>, was fixed with it).
        /// </summary>
        public const string Friction =
            "friction on a stiff rope: Coulomb friction is inside the exact chain solve (ChainContacts); since friction-held " +
            "iterations take the energy test and the line search like any other, a contact the chain pulls in the first " +
            "iteration loses its friction before the active set may release it (ChainContacts.Update), and a released contact " +
            "the solve drives back into the surface makes the solver iterate again (ChainContacts.ReleasedInside), no case " +
            "remains, was 1 (7 before the release rule, 17 before the line search): the 200 GPa, 16-segment, load ratio 1 " +
            "rope on the sphere at 1/90 s, backward Euler, tension-only, +0.46 J elastic, now gains nothing";

        /// <summary>
        /// A bilateral chain that pushes and folds against the sphere: its violent substeps do not converge, and the length
        /// errors they leave store energy.
        /// </summary>
        public const string Rod =
            "rod in compression: a pushing bilateral segment takes no geometric stiffness in the exact solve (ExactChainSolver." +
            "Assemble: its exact −|T|/l makes the implicit step's energy non-convex across it), so the iteration converges only " +
            "linearly where a pushing chain folds; no grid case fails under it since a BDF2 substep whose impact left the solve " +
            "violent and unconverged runs again as backward Euler (Rope.NewImpact: the undamped 1 GPa 256-segment rod with a 10³ " +
            "load hitting the sphere at 1/30 s gained 14.8 J, 2.1 J of it motion, in violent substeps of up to 32 iterations, " +
            "its tension-only twin 0.63 J); taking a pure-axial segment's residual along the segment instead of along its " +
            "lagging force (solver.md, \"Rods in compression\") removed the 151 J its fold stored at 1/90 s and passed the 45 t " +
            "load on a 2-segment steel rod hitting the sphere (+9.4 kJ) and the damped 256-segment steel rod (+0.226 J); negative " +
            "geometric stiffness bounded to keep the Newton matrix positive definite, and a line search on every iteration of a " +
            "violent substep, were measured and failed more cases";

        /// <summary>
        /// The collision pass after the last iteration pushes particles out of the collider without the chain: no case left in
        /// the full sweep.
        /// </summary>
        public const string Push =
            "push after the solve: the collision pass after the last chain iteration pushes particles out of the sphere " +
            "(ContactPass.LastIteration) without the chain, storing ½δ²/α in the segments at the pushed particle (1 µm on a " +
            "6 cm steel segment is 0.1 mJ) that the next substep releases; a contact the first iteration released stays free " +
            "in the substep, and where the solve drove it back into the sphere (up to 67 µm on the 200 GPa 16-segment rope at " +
            "1/90 s, 0.046 J in its positions against 3e-8 J in its tensions) the solver now iterates again, so the detection " +
            "holds it (ChainContacts.ReleasedInside: both 16-segment cases pass, was +0.0395 J and +0.0505 J); no case " +
            "remains: the last, the 1 GPa 256-segment rope with 10³ at 1/30 s (BDF2, tension-only, +0.628 J, 0.627 J of it " +
            "motion), passes since a BDF2 substep whose impact left the solve violent and unconverged runs again as backward " +
            "Euler (Rope.NewImpact); solving again after the push was tried and failed more cases (the 2-segment ropes resting on the sphere that did not come quite to rest, 8.1e-7 – 9.0e-7 J, read " +
            "BDF2's steady velocity h·g_n/2 into the surface at a pushed particle that stood still, and now come to rest: " +
            "Rope.RemoveVelocityIntoSurface)";

        /// <summary>Every documented limit, in the order the grid report lists them.</summary>
        public static readonly string[] All = { Friction, Rod, Push };

        /// <summary>A limit's name, the text before its colon (e.g. "push after the solve").</summary>
        public static string Name(string limit) => limit.Substring(0, limit.IndexOf(':'));

        /// <summary>
        /// The report's line of <paramref name="limit"/> with <paramref name="cases"/> cases under it:
        /// "- **name** (n cases): explanation." (stability-grid.md, "Documented domain limits").
        /// </summary>
        public static string ReportLine(string limit, int cases) =>
            "- **" + Name(limit) + "** (" + cases.ToString(System.Globalization.CultureInfo.InvariantCulture) + " cases): " +
            limit.Substring(limit.IndexOf(':') + 2) + ".";

        /// <summary>
        /// The limit a failing case falls under, or null (an undocumented failure, or a case that passed). Non-finite
        /// results and escapes are never a documented limit.
        /// </summary>
        public static string Explain(GridOutcome o)
        {
            if (!o.Failed || !o.Finite || o.Escaped || o.NotRecovered) return null;
            GridCase c = o.Case;
            if (c.Collider && c.Friction > 0f) return Friction;
            // a rod's failure is an energy gain of a rope that pushed
            if (c.Tension == TensionModel.Bilateral && o.LargestPush > 0.0 && (o.GainedEnergy || !c.Collider)) return Rod;
            if (c.Collider) return Push;
            return null;
        }
    }
}
