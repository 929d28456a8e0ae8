namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.GUILayoutOption: class internally used to pass layout options into GUILayout functions.</summary>
    public sealed class GUILayoutOption
    {
        internal GUILayoutOption() { }
    }
}
