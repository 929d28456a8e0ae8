namespace HookeRope
{
    /// <summary>The value type of a <see cref="ParameterInfo"/> row.</summary>
    public enum ParameterKind
    {
        /// <summary>A single-precision number; Min, Max and Default are in the row's unit.</summary>
        Float,
        /// <summary>An integer count.</summary>
        Int,
        /// <summary>A switch; Default is 0 (off) or 1 (on).</summary>
        Bool,
        /// <summary>An enumeration; Min, Max and Default are the numeric values of its members.</summary>
        Enum,
        /// <summary>A three-component vector; Min and Max bound each component, the default is in DefaultComponents.</summary>
        Vector,
        /// <summary>An RGBA colour with components in [0, 1]; the default is in DefaultComponents.</summary>
        Color,
    }
}
