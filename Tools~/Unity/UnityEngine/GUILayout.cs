namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.GUILayout (immediate-mode GUI: not modelled, every call throws): the interface to Unity's GUI with automatic layout.</summary>
    public class GUILayout
    {
        /// <summary>Make a single press button.</summary>
        public static bool Button(string text, params GUILayoutOption[] options) => throw HookeRope.StandIn.StandInError.Unsupported("GUILayout.Button (IMGUI runs only inside an OnGUI event)");
    }
}
