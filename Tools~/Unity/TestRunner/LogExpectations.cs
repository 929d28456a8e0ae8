using System.Collections.Generic;
using System.Text;
using System.Text.RegularExpressions;
using NUnit.Framework;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: the bookkeeping behind LogAssert for the current test.</summary>
    internal static class LogExpectations
    {
        readonly struct Expected
        {
            internal Expected(LogType type, string text, Regex pattern) { Type = type; Text = text; Pattern = pattern; }
            internal LogType Type { get; }
            internal string Text { get; }
            internal Regex Pattern { get; }
            internal bool Matches(LogCapture.Entry e) => e.Type == Type && (Pattern != null ? Pattern.IsMatch(e.Message) : e.Message == Text);
            public override string ToString() => "[" + Type + "] " + (Pattern != null ? "Regex: " + Pattern : Text);
        }

        static readonly List<Expected> s_Expected = new List<Expected>();
        static readonly List<LogCapture.Entry> s_Unexpected = new List<LogCapture.Entry>();
        static bool s_Listening;

        internal static bool IgnoreFailingMessages { get; set; }

        /// <summary>Starts a test: no expectations, nothing unexpected, failing messages counted.</summary>
        internal static void Begin()
        {
            if (!s_Listening)
            {
                LogCapture.Logged += OnLogged;
                s_Listening = true;
            }
            s_Expected.Clear();
            s_Unexpected.Clear();
            IgnoreFailingMessages = false;
            LogCapture.Clear();
        }

        internal static void Expect(LogType type, string text, Regex pattern) => s_Expected.Add(new Expected(type, text, pattern));

        /// <summary>The failure text of the current test's log (unexpected errors, missing expected messages), or null.</summary>
        internal static string Failure()
        {
            if (s_Unexpected.Count == 0 && s_Expected.Count == 0) return null;
            var text = new StringBuilder();
            for (int i = 0; i < s_Unexpected.Count; i++)
                text.Append("Unhandled log message: '[").Append(s_Unexpected[i].Type).Append("] ").Append(s_Unexpected[i].Message)
                    .Append("'. Use UnityEngine.TestTools.LogAssert.Expect to expect it.\n");
            for (int i = 0; i < s_Expected.Count; i++)
                text.Append("Expected log did not appear: ").Append(s_Expected[i]).Append('\n');
            return text.ToString();
        }

        internal static void ThrowIfFailed()
        {
            string failure = Failure();
            s_Unexpected.Clear();
            s_Expected.Clear();
            if (failure != null) throw new AssertionException(failure);
        }

        static void OnLogged(LogCapture.Entry entry)
        {
            if (s_Expected.Count > 0 && s_Expected[0].Matches(entry))
            {
                s_Expected.RemoveAt(0);
                return;
            }
            bool failing = entry.Type == LogType.Error || entry.Type == LogType.Exception || entry.Type == LogType.Assert;
            if (failing && !IgnoreFailingMessages) s_Unexpected.Add(entry);
        }
    }
}
