namespace HookeRope
{
    /// <summary>Which material value the inspector edits; the other follows from the cross-section A = πR².</summary>
    public enum RopeStiffnessInput
    {
        /// <summary>Young's modulus E in pascals.</summary>
        YoungsModulus,
        /// <summary>Axial stiffness E·A in newtons (what a rope datasheet gives as force per unit strain).</summary>
        AxialStiffness,
    }
}
