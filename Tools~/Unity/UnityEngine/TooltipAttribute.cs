namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.TooltipAttribute: specify a tooltip for a field in the Inspector window.</summary>
    [System.AttributeUsage(System.AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public class TooltipAttribute : PropertyAttribute
    {
        /// <summary>Specify a tooltip for a field.</summary>
        public TooltipAttribute(string tooltip) { }
    }
}
