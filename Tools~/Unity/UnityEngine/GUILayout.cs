namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.GUILayout: the interface to Unity's GUI with automatic layout.</summary>
    public class GUILayout
    {
        /// <summary>Make a single press button.</summary>
        public static bool Button(string text, params GUILayoutOption[] options) => throw Shim.NotRun;
    }
}
