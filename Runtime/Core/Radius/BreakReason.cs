namespace HookeRope.Radius
{
    /// <summary>Why the radius model decided that the rope breaks.</summary>
    public enum BreakReason
    {
        /// <summary>The rope does not break (yet).</summary>
        None = 0,

        /// <summary>The strain of the defect segment passed <see cref="RadiusSettings.BreakElongation"/>.</summary>
        Elongation = 1,

        /// <summary>The neck radius fell below <see cref="RadiusSettings.BreakRadiusFraction"/> times the rest radius.</summary>
        NeckRadius = 2,
    }
}
