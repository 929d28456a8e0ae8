using System;

namespace HookeRope.Lab.Commands
{
    /// <summary>The command line or an output path is wrong: one friendly line, exit code 2.</summary>
    public sealed class UsageException : Exception
    {
        /// <summary>Creates the error with the line shown to the user (it names the option, value or path).</summary>
        public UsageException(string message) : base(message)
        {
        }
    }
}
