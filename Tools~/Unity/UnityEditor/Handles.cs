using UnityEngine;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.Handles: custom 3D GUI controls and drawing in the Scene view. The stand-in has no
    /// Scene view and no input, so a handle is never dragged: every handle returns the value it was given, as Unity's
    /// do in an event that does not move them.
    /// </summary>
    public sealed class Handles
    {
        /// <summary>Make a 3D Scene view position handle (the stand-in: never dragged, returns <paramref name="position"/>).</summary>
        public static Vector3 PositionHandle(Vector3 position, Quaternion rotation) => position;

        /// <summary>Colors of the handles (kept; the stand-in draws nothing). Default white.</summary>
        public static Color color { get; set; } = Color.white;

        /// <summary>Draw anti-aliased line specified with point array and width (the stand-in: no IMGUI repaint event, throws).</summary>
        public static void DrawAAPolyLine(float width, params Vector3[] points) =>
            throw HookeRope.StandIn.StandInError.Unsupported("Handles.DrawAAPolyLine (drawing needs an IMGUI repaint event)");
    }
}
