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
    }
}
