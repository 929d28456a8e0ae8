namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.SerializeField: force Unity to serialize a private field.</summary>
    [System.AttributeUsage(System.AttributeTargets.Field)]
    public sealed class SerializeField : System.Attribute
    {
    }
}
