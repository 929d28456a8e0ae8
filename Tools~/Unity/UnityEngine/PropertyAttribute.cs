namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.PropertyAttribute: base class to derive custom property attributes from.</summary>
    [System.AttributeUsage(System.AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public abstract class PropertyAttribute : System.Attribute
    {
    }
}
