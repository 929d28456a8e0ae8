namespace HookeRope
{
    /// <summary>What one end of a rope is attached to.</summary>
    public enum RopeEndKind
    {
        /// <summary>Nothing: the end hangs free.</summary>
        Free,
        /// <summary>A Transform the end follows exactly (the rope cannot move it).</summary>
        Transform,
        /// <summary>A Rigidbody the rope pulls and is pulled by (two-way).</summary>
        Rigidbody,
    }
}
