using System;
using System.Collections.Generic;
using UnityEngine;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the one open scene of the stand-in. Holds every live scene GameObject in creation order,
    /// whether the "editor" is in Play mode, the queue of deferred <see cref="Object.Destroy(Object, float)"/> calls
    /// and the instance-id counter. Test runs reset it between runs.
    /// </summary>
    internal static class World
    {
        static readonly List<GameObject> s_Objects = new List<GameObject>();
        static readonly List<(Object Target, float Time)> s_PendingDestroy = new List<(Object, float)>();
        static int s_NextInstanceId = -2;

        /// <summary>Raised by <see cref="Reset"/>: other parts of the stand-in clear their static state.</summary>
        internal static event Action WorldReset;

        /// <summary>Application.isPlaying: true in a play-mode run (set by the test harness).</summary>
        internal static bool IsPlaying { get; set; }

        /// <summary>Live scene GameObjects in creation order (assets such as loaded prefabs are not in the scene).</summary>
        internal static IReadOnlyList<GameObject> Objects => s_Objects;

        /// <summary>Live components of type <typeparamref name="T"/> on scene objects, in creation order, active or not.</summary>
        internal static IEnumerable<T> Live<T>() where T : Component
        {
            for (int i = 0; i < s_Objects.Count; i++)
            {
                var components = s_Objects[i].ComponentList;
                for (int c = 0; c < components.Count; c++)
                    if (components[c] is T match && match.IsAlive) yield return match;
            }
        }

        /// <summary>Counts the live scene objects (for leak checks).</summary>
        internal static int ObjectCount => s_Objects.Count;

        /// <summary>A new instance id: negative, as Unity gives to objects created at run time.</summary>
        internal static int NextInstanceId() => s_NextInstanceId--;

        internal static void Add(GameObject go) => s_Objects.Add(go);

        internal static void Remove(GameObject go) => s_Objects.Remove(go);

        /// <summary>Queues <paramref name="target"/> for destruction at the end of the frame in which at least <paramref name="delay"/> seconds have passed.</summary>
        internal static void QueueDestroy(Object target, float delay)
        {
            for (int i = 0; i < s_PendingDestroy.Count; i++)
                if (ReferenceEquals(s_PendingDestroy[i].Target, target)) return;
            s_PendingDestroy.Add((target, Time.time + Math.Max(0f, delay)));
        }

        /// <summary>Runs the deferred destroys that are due (end of frame).</summary>
        internal static void FlushDestroys()
        {
            for (int i = 0; i < s_PendingDestroy.Count;)
            {
                var (target, due) = s_PendingDestroy[i];
                if (due > Time.time) { i++; continue; }
                s_PendingDestroy.RemoveAt(i);
                if (target.IsAlive) target.DestroyNow();
            }
        }

        /// <summary>
        /// The Editor leaving Play mode: Application.quitting is raised ("invoked when exiting Play mode", Scripting
        /// Reference "Application.quitting"), then every scene object is destroyed (OnDisable, OnDestroy) and Play mode
        /// ends. The order of the event against the destruction is the stand-in's (approx.: native in Unity).
        /// </summary>
        internal static void ExitPlayMode()
        {
            if (!IsPlaying) throw new InvalidOperationException("The stand-in is not in Play mode.");
            Application.CallQuitting();
            DestroyScene();
            s_PendingDestroy.Clear();
            IsPlaying = false;
        }

        /// <summary>Destroys every scene object and clears all stand-in state (time, physics, logs…).</summary>
        internal static void Reset()
        {
            DestroyScene();
            s_Objects.Clear();
            s_PendingDestroy.Clear();
            PlayerLoop.Reset();
            Time.Reset();
            WorldReset?.Invoke();
        }

        static void DestroyScene()
        {
            for (int i = s_Objects.Count - 1; i >= 0; i--)
            {
                if (i >= s_Objects.Count) continue;
                var go = s_Objects[i];
                if (go.IsAlive && go.transform.parent == null) go.DestroyNow();
            }
        }
    }
}
