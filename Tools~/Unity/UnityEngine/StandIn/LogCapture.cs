using System;
using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: the console. Records every Debug message since the last <see cref="Clear"/>.</summary>
    internal static class LogCapture
    {
        /// <summary>One console entry: its type and text (an exception's text is "Type: message").</summary>
        internal readonly struct Entry
        {
            internal Entry(LogType type, string message) { Type = type; Message = message; }
            internal LogType Type { get; }
            internal string Message { get; }
            public override string ToString() => Type + ": " + Message;
        }

        static readonly List<Entry> s_Entries = new List<Entry>();

        /// <summary>Entries in the order they were logged.</summary>
        internal static IReadOnlyList<Entry> Entries => s_Entries;

        /// <summary>Raised for every entry (the test runner matches LogAssert expectations as messages arrive).</summary>
        internal static event Action<Entry> Logged;

        internal static void Add(LogType type, object message, UnityEngine.Object context)
        {
            string text = message is Exception e ? e.GetType().Name + ": " + e.Message : message?.ToString() ?? "Null";
            var entry = new Entry(type, text);
            s_Entries.Add(entry);
            Console.WriteLine("[Unity " + type + "] " + (message is Exception ex ? ex.ToString() : text));
            Logged?.Invoke(entry);
            Application.CallLogCallback(text, type);
        }

        internal static void Clear() => s_Entries.Clear();
    }
}
