using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Time. The stand-in's player loop advances it: each frame adds
    /// min(frame interval, maximumDeltaTime) to <see cref="time"/>, then runs one fixed step for every multiple of
    /// <see cref="fixedDeltaTime"/> that <see cref="time"/> has reached. Inside FixedUpdate, time and deltaTime return
    /// fixedTime and fixedDeltaTime, as documented.
    /// </summary>
    public class Time
    {
        const float DefaultFixedDeltaTime = 0.02f, DefaultMaximumDeltaTime = 0.3333333f;
        static double s_Time, s_FixedTime, s_NextFixedTime;
        static float s_DeltaTime, s_FixedDeltaTime = DefaultFixedDeltaTime, s_MaximumDeltaTime = DefaultMaximumDeltaTime;
        static int s_FrameCount;

        /// <summary>The time at the beginning of the current frame in seconds since the start of the application (Read Only); fixedTime inside FixedUpdate.</summary>
        public static float time => InFixedStep ? (float)s_FixedTime : (float)s_Time;

        /// <summary>The interval in seconds from the last frame to the current one (Read Only); fixedDeltaTime inside FixedUpdate.</summary>
        public static float deltaTime => InFixedStep ? s_FixedDeltaTime : s_DeltaTime;

        /// <summary>The time the latest MonoBehaviour.FixedUpdate has started (Read Only), in seconds since the start of the game.</summary>
        public static float fixedTime => (float)s_FixedTime;

        /// <summary>The double precision time the latest MonoBehaviour.FixedUpdate has started (Read Only), in seconds since the start of the game.</summary>
        public static double fixedTimeAsDouble => s_FixedTime;

        /// <summary>The interval in seconds of in-game time at which physics and other fixed frame rate updates are performed.</summary>
        public static float fixedDeltaTime
        {
            get => s_FixedDeltaTime;
            set
            {
                if (!(value > 0f) || float.IsInfinity(value))
                    throw StandInError.Unsupported("Time.fixedDeltaTime = " + value + " (the stand-in accepts only a finite positive step)");
                s_FixedDeltaTime = value;
            }
        }

        /// <summary>The maximum value of Time.deltaTime in any given frame (seconds).</summary>
        public static float maximumDeltaTime
        {
            get => s_MaximumDeltaTime;
            set => s_MaximumDeltaTime = Math.Max(value, s_FixedDeltaTime);
        }

        /// <summary>The total number of frames since the start of the game (Read Only).</summary>
        public static int frameCount => s_FrameCount;

        /// <summary>Returns true if called inside a fixed time step callback (like MonoBehaviour's FixedUpdate), otherwise returns false.</summary>
        public static bool inFixedTimeStep => InFixedStep;

        // ---- stand-in internals -----------------------------------------------------------------------------
        internal static bool InFixedStep { get; set; }

        /// <summary>Starts a frame: the first frame is at time 0, each later one advances by <paramref name="interval"/> seconds capped by maximumDeltaTime.</summary>
        internal static void BeginFrame(float interval)
        {
            s_DeltaTime = Math.Min(interval, s_MaximumDeltaTime);
            if (s_FrameCount > 0) s_Time += s_DeltaTime;
            s_FrameCount++;
        }

        /// <summary>Starts the next fixed step when its start time has been reached by the frame time; false when none is due.</summary>
        internal static bool TryBeginFixedStep()
        {
            if (s_NextFixedTime > s_Time + 1e-9) return false;
            s_FixedTime = s_NextFixedTime;
            s_NextFixedTime += s_FixedDeltaTime;
            return true;
        }

        internal static void Reset()
        {
            s_Time = s_FixedTime = s_NextFixedTime = 0.0;
            s_DeltaTime = 0f;
            s_FixedDeltaTime = DefaultFixedDeltaTime;
            s_MaximumDeltaTime = DefaultMaximumDeltaTime;
            s_FrameCount = 0;
            InFixedStep = false;
        }
    }
}
