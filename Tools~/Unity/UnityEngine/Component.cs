namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Component.</summary>
    public class Component : Object
    {
        /// <summary>The Transform attached to this GameObject.</summary>
        public Transform transform => throw Shim.NotRun;
    }
}
