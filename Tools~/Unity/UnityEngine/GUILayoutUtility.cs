namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.GUILayoutUtility (immediate-mode GUI: not modelled, every call throws): utility functions for implementing and extending the GUILayout class.</summary>
    public class GUILayoutUtility
    {
        /// <summary>Reserve layout space for a flexible rect.</summary>
        public static Rect GetRect(float minWidth, float maxWidth, float minHeight, float maxHeight) =>
            throw HookeRope.StandIn.StandInError.Unsupported("GUILayoutUtility.GetRect (IMGUI layout runs only inside an OnGUI event)");
    }
}
