using HookeRope.StandIn;

namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.EditorGUI: IMGUI controls, which need a GUI event the stand-in does not have.</summary>
    public sealed class EditorGUI
    {
        /// <summary>The indent level of the field labels.</summary>
        public static int indentLevel
        {
            get => throw StandInError.Unsupported("EditorGUI.indentLevel (IMGUI)");
            set => throw StandInError.Unsupported("EditorGUI.indentLevel (IMGUI)");
        }

        /// <summary>Create a group of controls that can be disabled.</summary>
        public static void BeginDisabledGroup(bool disabled) => throw StandInError.Unsupported("EditorGUI.BeginDisabledGroup (IMGUI)");

        /// <summary>Ends a disabled group started with BeginDisabledGroup.</summary>
        public static void EndDisabledGroup() => throw StandInError.Unsupported("EditorGUI.EndDisabledGroup (IMGUI)");

        /// <summary>Draws a filled rectangle of color at the specified position and size within the current editor window.</summary>
        public static void DrawRect(UnityEngine.Rect rect, UnityEngine.Color color) => throw StandInError.Unsupported("EditorGUI.DrawRect (IMGUI)");
    }
}
