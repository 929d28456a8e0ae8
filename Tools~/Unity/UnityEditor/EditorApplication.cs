namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.EditorApplication: main Application class.</summary>
    public sealed class EditorApplication
    {
        /// <summary>Is the editor currently in play mode?</summary>
        public static bool isPlaying { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
