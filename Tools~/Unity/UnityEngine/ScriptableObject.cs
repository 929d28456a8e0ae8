namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.ScriptableObject.</summary>
    public class ScriptableObject : Object
    {
    }
}
