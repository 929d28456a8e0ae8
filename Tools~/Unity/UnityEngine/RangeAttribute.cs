namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.RangeAttribute: make a float or int variable in a script be restricted to a specific range.</summary>
    [System.AttributeUsage(System.AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public sealed class RangeAttribute : PropertyAttribute
    {
        /// <summary>Attribute used to make a float or int variable in a script be restricted to a specific range.</summary>
        public RangeAttribute(float min, float max) { }
    }
}
