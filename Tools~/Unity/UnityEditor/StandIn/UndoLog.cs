using System.Collections.Generic;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the stand-in's Undo history: each Undo call and each SerializedObject.ApplyModifiedProperties
    /// adds an entry, in order, tagged with the current undo group (Undo.IncrementCurrentGroup starts a new one).
    /// Undo.PerformUndo reverts the latest group when it holds only created objects (it destroys them); other records
    /// are a log only. Cleared when the scene is reset.
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
            /// <summary>Undo.SetTransformParent (the previous parent).</summary>
            TransformParent,
        }

        /// <summary>One undo record.</summary>
        internal readonly struct Entry
        {
            internal Entry(Kind kind, Object target, string name, int group)
            {
                What = kind;
                Target = target;
                Name = name;
                Group = group;
            }

            internal int Group { get; }

            internal Kind What { get; }
            internal Object Target { get; }
            internal string Name { get; }

            /// <inheritdoc/>
            public override string ToString() => What + " '" + Name + "' on " + (Target is null ? "null" : Target.ToString());
        }

        static readonly List<Entry> s_Entries = new List<Entry>();

        static UndoLog() => World.WorldReset += () => { s_Entries.Clear(); CurrentGroup = 0; };

        /// <summary>The undo group new entries join (Undo.GetCurrentGroup).</summary>
        internal static int CurrentGroup { get; set; }

        /// <summary>The entries, oldest first.</summary>
        internal static IReadOnlyList<Entry> Entries => s_Entries;

        internal static void Add(Kind kind, Object target, string name) => s_Entries.Add(new Entry(kind, target, name, CurrentGroup));

        /// <summary>Removes and returns the entries of the latest group that has any, newest first.</summary>
        internal static List<Entry> PopLatestGroup()
        {
            var popped = new List<Entry>();
            if (s_Entries.Count == 0) return popped;
            int group = s_Entries[s_Entries.Count - 1].Group;
            for (int i = s_Entries.Count - 1; i >= 0 && s_Entries[i].Group == group; i--)
            {
                popped.Add(s_Entries[i]);
                s_Entries.RemoveAt(i);
            }
            return popped;
        }
    }
}
