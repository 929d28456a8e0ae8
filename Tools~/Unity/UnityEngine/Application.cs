namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Application: access to application runtime data.</summary>
    public class Application
    {
        /// <summary>Returns true when called in any kind of built Player, or when called in the Editor in Play Mode (Read Only).</summary>
        public static bool isPlaying => throw Shim.NotRun;
    }
}
