namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.YieldInstruction: base class for all yield instructions.</summary>
    public class YieldInstruction
    {
    }
}
