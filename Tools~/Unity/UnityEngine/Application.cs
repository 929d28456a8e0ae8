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
    }
}
