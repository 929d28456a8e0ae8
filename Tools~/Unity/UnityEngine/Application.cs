using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.Application: access to application runtime data.</summary>
    public class Application
    {
        /// <summary>Returns true when called in any kind of built Player, or when called in the Editor in Play Mode (Read Only).</summary>
        public static bool isPlaying => World.IsPlaying;

        /// <summary>Whether the game is running inside the Unity Editor (Read Only); the stand-in plays the Editor.</summary>
        public static bool isEditor => true;

        /// <summary>Use this delegate type with logMessageReceived to monitor what gets logged.</summary>
        public delegate void LogCallback(string condition, string stackTrace, LogType type);

        static LogCallback s_LogCallbackHandler;

        /// <summary>Event that is fired if a log message is received (on the main thread; the stand-in passes an empty stack trace).</summary>
        public static event LogCallback logMessageReceived
        {
            add => s_LogCallbackHandler += value;
            remove => s_LogCallbackHandler -= value;
        }

        /// <summary>
        /// Unity raises this event when the Player application is quitting, and when the Editor exits Play mode (the
        /// stand-in: when a test exits Play mode, <see cref="HookeRope.StandIn.World.ExitPlayMode"/>).
        /// </summary>
        public static event System.Action quitting;

        /// <summary>Stand-in: raises <see cref="quitting"/> (UCR Internal_ApplicationQuit).</summary>
        internal static void CallQuitting() => quitting?.Invoke();

        /// <summary>Stand-in: the console forwards every entry here.</summary>
        internal static void CallLogCallback(string condition, LogType type) => s_LogCallbackHandler?.Invoke(condition, string.Empty, type);
    }
}
