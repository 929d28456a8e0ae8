namespace HookeRope.Radius
{
    /// <summary>
    /// How the rope necks at its defect once the Poisson radius there falls below r_min (when
    /// <see cref="RadiusSettings.Necking"/> is on). The values are serialized (prefab <c>m_NeckMode: 2</c>): keep them.
    /// </summary>
    public enum NeckMode
    {
        /// <summary>
        /// Chen et al. 2022, eq. 18: one hyperbola over the whole current length, defect in the middle.
        /// At onset the middle radius jumps to about 2·r_min²/l, which is a hair on a long thin rope.
        /// </summary>
        Paper = 1,

        /// <summary>
        /// The same hyperbola over a short neck zone (a few diameters) around the defect, with a depth that
        /// grows continuously from zero with the strain beyond onset, so the radius never jumps. Default.
        /// </summary>
        Zone = 2,
    }
}
