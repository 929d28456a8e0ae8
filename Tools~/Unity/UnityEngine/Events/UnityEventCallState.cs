namespace UnityEngine.Events
{
    /// <summary>Stand-in of UnityEngine.Events.UnityEventCallState: controls the scope of UnityEvent callbacks.</summary>
    public enum UnityEventCallState
    {
        /// <summary>Callback is not issued.</summary>
        Off = 0,
        /// <summary>Callback is always issued.</summary>
        EditorAndRuntime = 1,
        /// <summary>Callback is only issued in the Runtime and Editor playmode.</summary>
        RuntimeOnly = 2,
    }
}
