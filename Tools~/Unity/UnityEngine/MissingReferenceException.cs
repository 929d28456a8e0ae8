using System;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.MissingReferenceException: thrown when a destroyed object is accessed.</summary>
    public class MissingReferenceException : SystemException
    {
        /// <summary>Creates the exception with a message.</summary>
        public MissingReferenceException(string message) : base(message) { }
    }
}
