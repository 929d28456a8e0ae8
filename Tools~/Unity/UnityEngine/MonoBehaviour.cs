namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.MonoBehaviour.</summary>
    public class MonoBehaviour : Behaviour
    {
    }
}
