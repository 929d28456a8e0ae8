using System.Text.RegularExpressions;
using UnityEngine;

namespace UnityEngine.TestTools
{
    /// <summary>Shim of UnityEngine.TestTools.LogAssert: lets you expect Unity log messages that would otherwise cause the test to fail.</summary>
    public static class LogAssert
    {
        /// <summary>Verifies that a log message of a specified type appears in the log.</summary>
        public static void Expect(LogType type, string message) => throw Shim.NotRun;

        /// <summary>Verifies that a log message of a specified type appears in the log.</summary>
        public static void Expect(LogType type, Regex message) => throw Shim.NotRun;
    }
}
