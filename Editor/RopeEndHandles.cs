using System;
using UnityEditor;
using UnityEngine;

namespace HookeRope.Editor
{
    /// <summary>
    /// The Scene-view handles of a rope's ends, without the IMGUI: each attached end is moved through the Transform
    /// that carries it — its Point, else its Body's Transform (a free end has no handle) — with Undo.
    /// <see cref="ElasticRopeEditor"/>'s OnSceneGUI passes Handles.PositionHandle as the handle; tests pass a drag.
    /// </summary>
    internal static class RopeEndHandles
    {
        /// <summary>Undo name of a Start handle drag.</summary>
        internal const string MoveStartName = "Move Rope Start";

        /// <summary>Undo name of an End handle drag.</summary>
        internal const string MoveEndName = "Move Rope End";

        /// <summary>The Transform a handle moves for <paramref name="end"/>: its Point, else its Body's Transform; null for a free end.</summary>
        internal static Transform HandleTransform(RopeEnd end)
        {
            if (end == null) return null;
            if (end.Point != null) return end.Point;
            return end.Body != null ? end.Body.transform : null;
        }

        /// <summary>
        /// Moves <paramref name="end"/>'s handle Transform to <paramref name="worldPosition"/> (m), recorded for Undo
        /// under <paramref name="undoName"/>. False (nothing recorded) for a free end or when it is already there.
        /// </summary>
        internal static bool MoveEnd(RopeEnd end, Vector3 worldPosition, string undoName)
        {
            var t = HandleTransform(end);
            if (t == null || t.position == worldPosition) return false;
            Undo.RecordObject(t, undoName);
            t.position = worldPosition;
            return true;
        }

        /// <summary>
        /// Shows one handle per attached end of <paramref name="rope"/>: <paramref name="handle"/> gets the end's world
        /// position (m) and returns where the user dragged it; a changed position moves the end. Returns how many ends moved.
        /// </summary>
        internal static int Draw(ElasticRope rope, Func<Vector3, Vector3> handle)
        {
            if (rope == null) return 0;
            int moved = 0;
            if (DrawOne(rope.StartAttachment, handle, MoveStartName)) moved++;
            if (DrawOne(rope.EndAttachment, handle, MoveEndName)) moved++;
            return moved;
        }

        static bool DrawOne(RopeEnd end, Func<Vector3, Vector3> handle, string undoName)
        {
            var t = HandleTransform(end);
            if (t == null) return false;
            return MoveEnd(end, handle(t.position), undoName);
        }
    }
}
