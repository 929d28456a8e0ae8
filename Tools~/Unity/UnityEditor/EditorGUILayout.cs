using HookeRope.StandIn;
using UnityEngine;

namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.EditorGUILayout: auto-layouted IMGUI controls, which need a GUI event the stand-in does not have.</summary>
    public class EditorGUILayout
    {
        /// <summary>Make a field for SerializedProperty.</summary>
        public static bool PropertyField(SerializedProperty property, params GUILayoutOption[] options) =>
            throw StandInError.Unsupported("EditorGUILayout.PropertyField (IMGUI)");

        /// <summary>Make a field for SerializedProperty.</summary>
        public static bool PropertyField(SerializedProperty property, bool includeChildren, params GUILayoutOption[] options) =>
            throw StandInError.Unsupported("EditorGUILayout.PropertyField (IMGUI)");

        /// <summary>Make a label with a foldout arrow to the left of it.</summary>
        public static bool Foldout(bool foldout, string content, bool toggleOnLabelClick) => throw StandInError.Unsupported("EditorGUILayout.Foldout (IMGUI)");

        /// <summary>Make a help box with a message to the user.</summary>
        public static void HelpBox(string message, MessageType type) => throw StandInError.Unsupported("EditorGUILayout.HelpBox (IMGUI)");

        /// <summary>Make a label field. (Useful for showing read-only info.)</summary>
        public static void LabelField(string label, string label2, params GUILayoutOption[] options) =>
            throw StandInError.Unsupported("EditorGUILayout.LabelField (IMGUI)");

        /// <summary>Make a small space between the previous control and the following.</summary>
        public static void Space() => throw StandInError.Unsupported("EditorGUILayout.Space (IMGUI)");
    }
}
