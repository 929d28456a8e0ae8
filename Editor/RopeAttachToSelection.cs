using UnityEditor;
using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>
    /// The inspector's "Attach Start/End to selection" buttons, without the IMGUI. The selected Transform becomes the
    /// end's attachment: inside a Rigidbody's hierarchy (a body outside the rope's own hierarchy) the end pulls that
    /// body two-way at the selection (Body = the Rigidbody, Point = the selection, or none when the selection is the
    /// body's own Transform); anywhere else the end follows it (Point = the selection, Body = none). Undo-able.
    /// </summary>
    internal static class RopeAttachToSelection
    {
        /// <summary>Undo name of "Attach Start to selection".</summary>
        internal const string AttachStartName = "Attach Start to selection";

        /// <summary>Undo name of "Attach End to selection".</summary>
        internal const string AttachEndName = "Attach End to selection";

        /// <summary>
        /// Why the buttons are disabled for <paramref name="ropes"/> with <paramref name="selection"/> (Selection.activeTransform),
        /// or null when they are enabled: nothing selected, or one of the ropes itself.
        /// </summary>
        internal static string Unavailable(ElasticRope[] ropes, Transform selection)
        {
            const string how = "lock this inspector (padlock icon), then select the object to attach to in the Hierarchy or Scene view.";
            if (selection == null) return "Nothing is selected: " + how;
            foreach (var rope in ropes)
                if (rope != null && rope.transform == selection) return "The rope itself is selected: " + how;
            return null;
        }

        /// <summary>The Rigidbody whose hierarchy holds <paramref name="selection"/>, skipping bodies in <paramref name="rope"/>'s own hierarchy; null when none.</summary>
        internal static Rigidbody BodyOf(Transform selection, ElasticRope rope)
        {
            for (var t = selection; t != null; t = t.parent)
            {
                if (RopeAutoWiring.IsInside(t, rope.transform)) continue;
                var body = t.GetComponent<Rigidbody>();
                if (body != null) return body;
            }
            return null;
        }

        /// <summary>Attaches <paramref name="end"/> of <paramref name="rope"/> to <paramref name="selection"/> (see the class), recorded for Undo.</summary>
        internal static void Attach(ElasticRope rope, RopeEnd end, Transform selection, string undoName)
        {
            if (rope == null || end == null || selection == null) return;
            Undo.RecordObject(rope, undoName);
            var body = BodyOf(selection, rope);
            end.Body = body;
            end.Point = body != null && body.transform == selection ? null : selection;
        }
    }
}
