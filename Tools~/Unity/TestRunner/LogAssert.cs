using System.Text.RegularExpressions;
using HookeRope.StandIn;

namespace UnityEngine.TestTools
{
    /// <summary>
    /// Stand-in of UnityEngine.TestTools.LogAssert: lets you expect Unity log messages that would otherwise cause the
    /// test to fail. As in Unity's Test Framework, an Error, Assert or Exception message that no expectation consumed
    /// fails the test, and so does an expected message that never arrived; expectations are matched in order.
    /// </summary>
    public static class LogAssert
    {
        /// <summary>Set this property to true to prevent unexpected error log messages from triggering an assertion.</summary>
        public static bool ignoreFailingMessages
        {
            get => LogExpectations.IgnoreFailingMessages;
            set => LogExpectations.IgnoreFailingMessages = value;
        }

        /// <summary>Verifies that a log message of a specified type appears in the log.</summary>
        public static void Expect(LogType type, string message) => LogExpectations.Expect(type, message, null);

        /// <summary>Verifies that a log message of a specified type appears in the log.</summary>
        public static void Expect(LogType type, Regex message) => LogExpectations.Expect(type, null, message);

        /// <summary>Triggers an assertion when receiving any log messages and fails the test if some are unexpected messages.</summary>
        public static void NoUnexpectedReceived() => LogExpectations.ThrowIfFailed();
    }
}
