namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.YieldInstruction: base class for all yield instructions.</summary>
    public class YieldInstruction
    {
    }
}
