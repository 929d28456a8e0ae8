using System.Collections.Generic;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the stand-in's Undo history, a log only (nothing can be undone): each Undo call and each
    /// SerializedObject.ApplyModifiedProperties adds an entry, in order. Cleared when the scene is reset.
    /// </summary>
    internal static class UndoLog
    {
        /// <summary>What an entry records.</summary>
        internal enum Kind
        {
            /// <summary>Undo.RegisterCreatedObjectUndo.</summary>
            CreatedObject,
            /// <summary>Undo.RecordObject (state before a change by script).</summary>
            RecordObject,
            /// <summary>SerializedObject.ApplyModifiedProperties (state before the applied edits).</summary>
            ModifiedProperties,
        }

        /// <summary>One undo record.</summary>
        internal readonly struct Entry
        {
            internal Entry(Kind kind, Object target, string name)
            {
                What = kind;
                Target = target;
                Name = name;
            }

            internal Kind What { get; }
            internal Object Target { get; }
            internal string Name { get; }

            /// <inheritdoc/>
            public override string ToString() => What + " '" + Name + "' on " + (Target is null ? "null" : Target.ToString());
        }

        static readonly List<Entry> s_Entries = new List<Entry>();

        static UndoLog() => World.WorldReset += s_Entries.Clear;

        /// <summary>The entries, oldest first.</summary>
        internal static IReadOnlyList<Entry> Entries => s_Entries;

        internal static void Add(Kind kind, Object target, string name) => s_Entries.Add(new Entry(kind, target, name));
    }
}
