namespace HookeRope.Solver
{
    /// <summary>What one call of <see cref="Rope.Step"/> did and how accurate its result is.</summary>
    public struct StepReport
    {
        /// <summary>
        /// Largest |l/L − 1 − T/(E·A)| (dimensionless strain error) over the active segments after the
        /// last substep: how far each segment is from the length its own tension and compliance imply.
        /// </summary>
        public float Residual;
        /// <summary>Constraint iterations run per substep.</summary>
        public int Iterations;
        /// <summary>Substeps the host step was split into.</summary>
        public int Substeps;
        /// <summary>
        /// Newton iterations the exact chain solve ran over the substeps (at least Substeps × Iterations; more where the
        /// solve added iterations, see <see cref="Rope.MaxNewtonIterations"/>); 0 for Gauss–Seidel.
        /// </summary>
        public int SolveIterations;
        /// <summary>
        /// Linear solves of the chain system the exact solve ran over the substeps: one per Newton iteration, more where its
        /// active-set passes changed the set of released tension-only segments or held contacts (up to 8 per iteration, 64
        /// while contact friction is still moving to its cone). Each costs about one pass over the segments; 0 for Gauss–Seidel.
        /// </summary>
        public int LinearSolves;
        /// <summary>
        /// Substeps whose exact solve was violent (a linearisation off by more than 10⁻³ of a rest length: a rope released far
        /// stretched, a teleported anchor): their iterations went through the line search, up to
        /// <see cref="Rope.MaxViolentNewtonIterations"/>, and a second-order integrator restarted with backward Euler.
        /// </summary>
        public int ViolentSubsteps;
        /// <summary>Iterations whose Newton step the line search shortened (the full step would have raised the implicit step's objective).</summary>
        public int ShortenedSteps;
        /// <summary>Substeps whose solve ended at its iteration limit still unconverged.</summary>
        public int UnconvergedSubsteps;
    }
}
