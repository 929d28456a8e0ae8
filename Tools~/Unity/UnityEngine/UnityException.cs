using System;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.UnityException: the exception Unity's native calls throw.</summary>
    public class UnityException : SystemException
    {
        /// <summary>Creates the exception with a message.</summary>
        public UnityException(string message) : base(message) { }
    }
}
