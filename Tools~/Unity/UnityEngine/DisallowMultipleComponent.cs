namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.DisallowMultipleComponent: prevents MonoBehaviour of same type (or subtype) to be added more than once to a GameObject.</summary>
    [System.AttributeUsage(System.AttributeTargets.Class, Inherited = false)]
    public sealed class DisallowMultipleComponent : System.Attribute
    {
    }
}
