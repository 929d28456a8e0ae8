namespace UnityEngine.TestTools
{
    /// <summary>Not part of Unity: the exception every shim body throws.</summary>
    internal static class Shim
    {
        internal static System.NotSupportedException NotRun =>
            new System.NotSupportedException("API shim for compile checks only; run this code in Unity.");
    }
}
