namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.RangeAttribute: make a float or int variable in a script be restricted to a specific
    /// range (UCR Runtime/Export/PropertyDrawer/PropertyAttribute.cs). The Inspector draws a slider; the stand-in has no
    /// drawer, so the attribute only carries the values.
    /// </summary>
    [System.AttributeUsage(System.AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public sealed class RangeAttribute : PropertyAttribute
    {
        /// <summary>The lower end of the range.</summary>
        public readonly float min;

        /// <summary>The upper end of the range.</summary>
        public readonly float max;

        /// <summary>Attribute used to make a float or int variable in a script be restricted to a specific range.</summary>
        public RangeAttribute(float min, float max) { this.min = min; this.max = max; }
    }
}
