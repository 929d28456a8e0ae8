namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.HelpURLAttribute: provide a custom documentation URL for a class.</summary>
    [System.AttributeUsage(System.AttributeTargets.Class, AllowMultiple = false)]
    public class HelpURLAttribute : System.Attribute
    {
        /// <summary>Initialize the HelpURL attribute with a documentation url.</summary>
        public HelpURLAttribute(string url) { }
    }
}
