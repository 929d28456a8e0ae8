namespace HookeRope.Radius
{
    /// <summary>Why the radius model decided that the rope breaks.</summary>
    public enum BreakReason
    {
        /// <summary>The rope does not break (yet).</summary>
        None = 0,

        /// <summary>The strain of the defect segment reached <see cref="RadiusSettings.BreakStrain"/>.</summary>
        Strain = 1,

        /// <summary>The neck radius fell below <see cref="RadiusSettings.BreakRadiusFraction"/> times the rest radius (only with necking on).</summary>
        NeckRadius = 2,
    }
}
