namespace HookeRope.Solver
{
    /// <summary>How the segment constraints of a rope are solved in each iteration.</summary>
    public enum ConstraintSolverKind
    {
        /// <summary>Gauss–Seidel XPBD: one segment at a time, in order. Cheap; slow to converge at high mass ratios.</summary>
        GaussSeidel,
        /// <summary>Exact linearised solve of the whole chain per iteration (tridiagonal, Thomas algorithm, O(n)).</summary>
        ExactChain,
    }
}
