using System;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: the error of an asset file the stand-in cannot read or map, naming the file and line.</summary>
    internal static class YamlError
    {
        /// <summary>A FormatException "file:line: message".</summary>
        internal static FormatException At(string file, int line, string message) =>
            new FormatException(file + ":" + line + ": " + message);
    }
}
