namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.MessageType: user message types.</summary>
    public enum MessageType
    {
        /// <summary>Neutral message.</summary>
        None = 0,
        /// <summary>Info message.</summary>
        Info = 1,
        /// <summary>Warning message.</summary>
        Warning = 2,
        /// <summary>Error message.</summary>
        Error = 3,
    }
}
