using System;
using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: when Unity sends Awake, OnEnable, OnDisable and OnDestroy, following the manual's "Order of
    /// execution for event functions". Awake runs once, when the script's GameObject is first active (even if the
    /// script is disabled); OnEnable follows when the script is enabled; OnDisable when it is disabled, its GameObject
    /// deactivated or destroyed; OnDestroy only for scripts whose Awake ran. In Edit mode only [ExecuteAlways] /
    /// [ExecuteInEditMode] scripts receive messages.
    /// </summary>
    internal static class Lifecycle
    {
        /// <summary>True when <paramref name="behaviour"/> receives messages now (Play mode, or an edit-mode script).</summary>
        internal static bool Runs(MonoBehaviour behaviour) => World.IsPlaying || RunsInEditMode(behaviour.GetType());

        static readonly Dictionary<Type, bool> s_EditMode = new Dictionary<Type, bool>();

        static bool RunsInEditMode(Type type)
        {
            if (s_EditMode.TryGetValue(type, out bool runs)) return runs;
            runs = Attribute.IsDefined(type, typeof(ExecuteAlways), true) || Attribute.IsDefined(type, typeof(ExecuteInEditMode), true);
            s_EditMode[type] = runs;
            return runs;
        }

        /// <summary>A script was just added: Awake and OnEnable now when its GameObject is active.</summary>
        internal static void Added(MonoBehaviour behaviour)
        {
            if (behaviour.Owner.IsActiveInHierarchy) Activate(behaviour);
        }

        /// <summary>The script's enabled flag changed.</summary>
        internal static void EnabledChanged(MonoBehaviour behaviour)
        {
            if (!behaviour.Owner.IsActiveInHierarchy || !Runs(behaviour)) return;
            if (behaviour.enabled) Activate(behaviour);
            else Deactivate(behaviour);
        }

        /// <summary>Every GameObject below <paramref name="root"/> (itself included) became active or inactive in the hierarchy.</summary>
        internal static void ActiveInHierarchyChanged(GameObject root, bool active)
        {
            var behaviours = new List<MonoBehaviour>();
            CollectBehaviours(root.transform, behaviours, onlyActive: active);
            for (int i = 0; i < behaviours.Count; i++)
            {
                if (!behaviours[i].IsAlive) continue;
                if (active) Activate(behaviours[i]);
                else Deactivate(behaviours[i]);
            }
        }

        static void CollectBehaviours(Transform t, List<MonoBehaviour> into, bool onlyActive)
        {
            var go = t.gameObject;
            if (onlyActive && !go.ActiveSelfCore) return;
            go.CollectComponents(into);
            var children = t.ChildList;
            for (int i = 0; i < children.Count; i++) CollectBehaviours(children[i], into, onlyActive);
        }

        static void Activate(MonoBehaviour behaviour)
        {
            if (!Runs(behaviour)) return;
            if (!behaviour.AwakeCalled)
            {
                behaviour.AwakeCalled = true;
                Messages.Send(behaviour, "Awake");
            }
            if (behaviour.IsAlive && behaviour.enabled && !behaviour.EnableCalled && behaviour.Owner.IsActiveInHierarchy)
            {
                behaviour.EnableCalled = true;
                Messages.Send(behaviour, "OnEnable");
            }
        }

        static void Deactivate(MonoBehaviour behaviour)
        {
            if (!behaviour.EnableCalled) return;
            behaviour.EnableCalled = false;
            Messages.Send(behaviour, "OnDisable");
        }

        /// <summary>Destroys one component now: OnDisable, OnDestroy, then it leaves its GameObject.</summary>
        internal static void DestroyComponent(Component component)
        {
            if (component is MonoBehaviour behaviour)
            {
                Deactivate(behaviour);
                if (behaviour.AwakeCalled) Messages.Send(behaviour, "OnDestroy");
            }
            if (!component.IsAlive) return;
            component.Owner.ComponentList.Remove(component);
            component.MarkDestroyed();
            component.OnStandInDestroy();
        }

        /// <summary>Destroys a GameObject with its children and components: OnDisable for all, then OnDestroy for all.</summary>
        internal static void DestroyHierarchy(GameObject root)
        {
            var objects = new List<GameObject>();
            CollectObjects(root.transform, objects);
            var behaviours = new List<MonoBehaviour>();
            for (int i = 0; i < objects.Count; i++) objects[i].CollectComponents(behaviours);
            for (int i = 0; i < behaviours.Count; i++) Deactivate(behaviours[i]);
            for (int i = 0; i < behaviours.Count; i++)
                if (behaviours[i].AwakeCalled) Messages.Send(behaviours[i], "OnDestroy");

            root.transform.DetachFromParent();
            for (int i = objects.Count - 1; i >= 0; i--)
            {
                var go = objects[i];
                var components = go.ComponentList;
                for (int c = components.Count - 1; c >= 0; c--)
                {
                    var component = components[c];
                    if (!component.IsAlive) continue;
                    component.MarkDestroyed();
                    component.OnStandInDestroy();
                }
                go.MarkDestroyed();
                go.OnStandInDestroy();
                World.Remove(go);
            }
        }

        static void CollectObjects(Transform t, List<GameObject> into)
        {
            into.Add(t.Owner);
            var children = t.ChildList;
            for (int i = 0; i < children.Count; i++) CollectObjects(children[i], into);
        }
    }
}
