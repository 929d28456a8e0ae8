namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.HeaderAttribute: use this PropertyAttribute to add a header above some fields in the Inspector.</summary>
    [System.AttributeUsage(System.AttributeTargets.Field, Inherited = true, AllowMultiple = true)]
    public class HeaderAttribute : PropertyAttribute
    {
        /// <summary>Add a header above some fields in the Inspector.</summary>
        public HeaderAttribute(string header) { }
    }
}
