using System;
using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: the points of a frame where a coroutine (or a [UnityTest]) resumes.</summary>
    internal enum LoopPoint
    {
        /// <summary>After FixedUpdate and the physics step of one fixed step (where WaitForFixedUpdate resumes).</summary>
        AfterFixedStep,

        /// <summary>After Update, before LateUpdate (where `yield return null` resumes).</summary>
        AfterUpdate,

        /// <summary>After LateUpdate and the deferred destroys: the frame is over.</summary>
        EndOfFrame,
    }

    /// <summary>
    /// Not part of Unity: the player loop, advanced by tests (the stand-in has no real-time clock). One frame, after
    /// the manual's "Order of execution for event functions": the clock advances by <see cref="FrameInterval"/>;
    /// scripts run in [DefaultExecutionOrder] order, then creation order; in Play mode, one fixed step per due multiple of Time.fixedDeltaTime (Start for new scripts, FixedUpdate on
    /// every active and enabled script, then the physics step when Physics.simulationMode is FixedUpdate, then
    /// WaitForFixedUpdate resumes); interpolated Rigidbodies are posed; Start for new scripts, Update, `yield null`
    /// resumes, LateUpdate; deferred destroys. In Edit mode only [ExecuteAlways] scripts get Update and LateUpdate,
    /// every tick (Unity calls them when the scene changed), and there are no fixed steps. Allocation-free after
    /// the first frames.
    /// </summary>
    internal static class PlayerLoop
    {
        const float DefaultFrameInterval = 1f / 90f;
        static readonly List<MonoBehaviour> s_Behaviours = new List<MonoBehaviour>();
        static IEnumerator<LoopPoint> s_Frame;

        /// <summary>Seconds between frames (a VR headset's 90 Hz by default, like a fixed Time.captureDeltaTime).</summary>
        internal static float FrameInterval { get; set; } = DefaultFrameInterval;

        /// <summary>Raised at the start of every frame, before the fixed steps: the editor's update (the stand-in's UnityEditor publishes its ObjectChangeEvents there).</summary>
        internal static event Action EditorUpdate;

        /// <summary>True while a frame has started and not yet ended.</summary>
        internal static bool InFrame => s_Frame != null;

        /// <summary>Runs the loop (continuing the current frame, if any) until it reaches <paramref name="point"/>.</summary>
        internal static void RunUntil(LoopPoint point)
        {
            while (true)
            {
                s_Frame ??= Frame();
                if (!s_Frame.MoveNext())
                {
                    s_Frame = null;
                    continue;
                }
                if (s_Frame.Current == point) return;
            }
        }

        /// <summary>Finishes the current frame, if one is in progress.</summary>
        internal static void FinishFrame()
        {
            if (s_Frame != null) RunUntil(LoopPoint.EndOfFrame);
        }

        /// <summary>Runs <paramref name="count"/> whole frames (finishing the current one first).</summary>
        internal static void RunFrames(int count)
        {
            FinishFrame();
            for (int i = 0; i < count; i++) RunUntil(LoopPoint.EndOfFrame);
        }

        /// <summary>Runs whole frames until at least <paramref name="seconds"/> of Time.time have passed.</summary>
        internal static void RunSeconds(float seconds)
        {
            FinishFrame();
            double end = Time.time + seconds - 1e-6;
            while (Time.time < end) RunUntil(LoopPoint.EndOfFrame);
        }

        internal static void Reset()
        {
            s_Frame = null;
            s_Behaviours.Clear();
            FrameInterval = DefaultFrameInterval;
        }

        static IEnumerator<LoopPoint> Frame()
        {
            Time.BeginFrame(FrameInterval);
            EditorUpdate?.Invoke();
            if (World.IsPlaying)
            {
                while (Time.TryBeginFixedStep())
                {
                    Time.InFixedStep = true;
                    try
                    {
                        Dispatch(Phase.FixedUpdate);
                        if (Physics.simulationMode == SimulationMode.FixedUpdate) PhysicsWorld.Step(Time.fixedDeltaTime);
                    }
                    finally
                    {
                        Time.InFixedStep = false;
                    }
                    yield return LoopPoint.AfterFixedStep;
                }
                PhysicsWorld.BeforeUpdate();
            }
            Dispatch(Phase.Update);
            yield return LoopPoint.AfterUpdate;
            Dispatch(Phase.LateUpdate);
            World.FlushDestroys();
            yield return LoopPoint.EndOfFrame;
        }

        enum Phase { FixedUpdate, Update, LateUpdate }

        /// <summary>Start for every new active and enabled script, then the phase's message for every active and enabled script.</summary>
        static void Dispatch(Phase phase)
        {
            CollectRunning();
            for (int i = 0; i < s_Behaviours.Count; i++)
            {
                var b = s_Behaviours[i];
                if (b.StartCalled || !b.isActiveAndEnabled) continue;
                b.StartCalled = true;
                Messages.Send(b, "Start");
            }
            for (int i = 0; i < s_Behaviours.Count; i++)
            {
                var b = s_Behaviours[i];
                if (!b.isActiveAndEnabled) continue;
                var call = phase == Phase.FixedUpdate ? b.FixedUpdateCall : phase == Phase.Update ? b.UpdateCall : b.LateUpdateCall;
                if (call == null) continue;
                try
                {
                    call();
                }
                catch (Exception e)
                {
                    Debug.LogException(e, b);
                }
            }
            s_Behaviours.Clear();
        }

        /// <summary>
        /// The scripts that receive messages now (Awake ran), sorted by [DefaultExecutionOrder] (lower first, 0 without
        /// it), in creation order among equal orders (a stable insertion sort: no allocation).
        /// </summary>
        static void CollectRunning()
        {
            s_Behaviours.Clear();
            var objects = World.Objects;
            for (int o = 0; o < objects.Count; o++)
            {
                var components = objects[o].ComponentList;
                for (int c = 0; c < components.Count; c++)
                {
                    if (!(components[c] is MonoBehaviour b) || !b.IsAlive || !b.AwakeCalled || !Lifecycle.Runs(b)) continue;
                    int order = ExecutionOrder(b.GetType());
                    int at = s_Behaviours.Count;
                    while (at > 0 && ExecutionOrder(s_Behaviours[at - 1].GetType()) > order) at--;
                    s_Behaviours.Insert(at, b);
                }
            }
        }

        static readonly Dictionary<Type, int> s_Orders = new Dictionary<Type, int>();

        /// <summary>The type's [DefaultExecutionOrder] value as declared on the class itself (approx.: a base class's is not inherited), 0 without it.</summary>
        internal static int ExecutionOrder(Type type)
        {
            if (s_Orders.TryGetValue(type, out int order)) return order;
            var attribute = (DefaultExecutionOrder)Attribute.GetCustomAttribute(type, typeof(DefaultExecutionOrder), false);
            order = attribute?.order ?? 0;
            s_Orders.Add(type, order);
            return order;
        }
    }
}
