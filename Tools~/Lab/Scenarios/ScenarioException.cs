using System;

namespace HookeRope.Lab.Scenarios
{
    /// <summary>A scenario file is invalid; <see cref="Path"/> names the JSON field ($.rope.segments).</summary>
    public sealed class ScenarioException : Exception
    {
        /// <summary>JSON path of the offending field, "$" for the document.</summary>
        public string Path { get; }

        /// <summary>Creates the error for a JSON path with a human message.</summary>
        public ScenarioException(string path, string message) : base(path + ": " + message)
        {
            Path = path;
        }
    }
}
