namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Time: the interface to get time information from Unity.</summary>
    public class Time
    {
        /// <summary>The interval in seconds of in-game time at which physics and other fixed frame rate updates are performed.</summary>
        public static float fixedDeltaTime { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>The time the latest MonoBehaviour.FixedUpdate has started (Read Only).</summary>
        public static float fixedTime => throw Shim.NotRun;

        /// <summary>The time at the beginning of the current frame in seconds since the start of the application (Read Only).</summary>
        public static float time => throw Shim.NotRun;

        /// <summary>The interval in seconds from the last frame to the current one (Read Only).</summary>
        public static float deltaTime => throw Shim.NotRun;
    }
}
