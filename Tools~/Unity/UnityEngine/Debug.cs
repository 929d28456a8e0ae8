using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Debug: every message is recorded (the test runner's LogAssert reads the record: an
    /// unexpected Error, Assert or Exception fails the test, as in Unity's Test Framework) and echoed to the console.
    /// </summary>
    public class Debug
    {
        /// <summary>Logs a message to the Unity Console.</summary>
        public static void Log(object message) => LogCapture.Add(LogType.Log, message, null);

        /// <summary>Logs a message to the Unity Console.</summary>
        public static void Log(object message, Object context) => LogCapture.Add(LogType.Log, message, context);

        /// <summary>A variant of Debug.Log that logs a warning message to the console.</summary>
        public static void LogWarning(object message) => LogCapture.Add(LogType.Warning, message, null);

        /// <summary>A variant of Debug.Log that logs a warning message to the console.</summary>
        public static void LogWarning(object message, Object context) => LogCapture.Add(LogType.Warning, message, context);

        /// <summary>A variant of Debug.Log that logs an error message to the console.</summary>
        public static void LogError(object message) => LogCapture.Add(LogType.Error, message, null);

        /// <summary>A variant of Debug.Log that logs an error message to the console.</summary>
        public static void LogError(object message, Object context) => LogCapture.Add(LogType.Error, message, context);

        /// <summary>A variant of Debug.Log that logs an error message from an exception to the console.</summary>
        public static void LogException(Exception exception) => LogCapture.Add(LogType.Exception, exception, null);

        /// <summary>A variant of Debug.Log that logs an error message from an exception to the console.</summary>
        public static void LogException(Exception exception, Object context) => LogCapture.Add(LogType.Exception, exception, context);
    }
}
