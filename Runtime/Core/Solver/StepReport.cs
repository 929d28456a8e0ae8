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
    }
}
