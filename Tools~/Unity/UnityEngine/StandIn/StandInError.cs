using System;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: the errors of the stand-in itself.</summary>
    internal static class StandInError
    {
        /// <summary>A Unity member outside the subset the stand-in implements: fails loudly instead of returning a default.</summary>
        internal static NotSupportedException Unsupported(string member) =>
            new NotSupportedException("Unity stand-in: " + member + " is outside the subset the stand-in implements. " +
                                      "Implement it from the Unity Scripting Reference (see Tools~/Unity/STAND-IN.md) before using it.");
    }
}
