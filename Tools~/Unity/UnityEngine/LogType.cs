namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.LogType: the type of the log message in Debug.unityLogger.Log or delegate registered with Application.RegisterLogCallback.</summary>
    public enum LogType
    {
        /// <summary>LogType used for Errors.</summary>
        Error = 0,
        /// <summary>LogType used for Asserts.</summary>
        Assert = 1,
        /// <summary>LogType used for Warnings.</summary>
        Warning = 2,
        /// <summary>LogType used for regular log messages.</summary>
        Log = 3,
        /// <summary>LogType used for Exceptions.</summary>
        Exception = 4,
    }
}
