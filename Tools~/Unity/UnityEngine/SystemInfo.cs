using System;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.SystemInfo: access to system and hardware information (only what the package uses).</summary>
    public sealed class SystemInfo
    {
        /// <summary>
        /// Number of processors present (Read Only): the logical processors the operating system reports (the stand-in:
        /// Environment.ProcessorCount, the same count for the process).
        /// </summary>
        public static int processorCount => Environment.ProcessorCount;
    }
}
