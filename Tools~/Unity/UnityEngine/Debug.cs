namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Debug.</summary>
    public class Debug
    {
        /// <summary>Logs a message to the Unity Console.</summary>
        public static void Log(object message) => throw Shim.NotRun;

        /// <summary>A variant of Debug.Log that logs a warning message to the console.</summary>
        public static void LogWarning(object message, Object context) => throw Shim.NotRun;

        /// <summary>A variant of Debug.Log that logs an error message to the console.</summary>
        public static void LogError(object message, Object context) => throw Shim.NotRun;
    }
}
