namespace HookeRope.Solver
{
    /// <summary>Whether a segment may push as well as pull.</summary>
    public enum TensionModel
    {
        /// <summary>Rope: a segment shorter than its rest length carries no force (unilateral constraint).</summary>
        TensionOnly,
        /// <summary>Rod: a segment resists compression as well as extension (bilateral constraint).</summary>
        Bilateral,
    }
}
