namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.WaitForFixedUpdate: waits until next fixed frame rate update function.</summary>
    public sealed class WaitForFixedUpdate : YieldInstruction
    {
    }
}
