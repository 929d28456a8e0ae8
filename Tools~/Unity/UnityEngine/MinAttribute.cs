namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.MinAttribute: make a float or int variable in a script be restricted to a specific
    /// minimum value (UCR Runtime/Export/PropertyDrawer/PropertyAttribute.cs). The Inspector's drawer clamps what is
    /// typed; the stand-in has no drawer, so the attribute only carries the value.
    /// </summary>
    [System.AttributeUsage(System.AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public sealed class MinAttribute : PropertyAttribute
    {
        /// <summary>The minimum allowed value.</summary>
        public readonly float min;

        /// <summary>Attribute used to make a float or int variable in a script be restricted to a specific minimum value.</summary>
        public MinAttribute(float min) { this.min = min; }
    }
}
