namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.MinAttribute: make a float or int variable in a script be restricted to a specific minimum value.</summary>
    [System.AttributeUsage(System.AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public sealed class MinAttribute : PropertyAttribute
    {
        /// <summary>Attribute used to make a float or int variable in a script be restricted to a specific minimum value.</summary>
        public MinAttribute(float min) { }
    }
}
