using System.Collections.Generic;
using System.Runtime.CompilerServices;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: how clones and assets are built outside the scene and its lifecycle. A detached GameObject
    /// is created inactive and out of the scene list, so adding its components sends no message; its intended
    /// activeSelf is kept aside. <see cref="Attach"/> puts a finished clone hierarchy into the scene and activates
    /// it deepest-first, root last, so Awake and OnEnable run once every field of every clone is set (as Unity's
    /// Instantiate does). A prefab asset stays detached for good (inactive, never in World.Live, no messages).
    /// </summary>
    internal static class SceneHooks
    {
        static readonly ConditionalWeakTable<GameObject, object> s_IntendedActive = new ConditionalWeakTable<GameObject, object>();
        static readonly ConditionalWeakTable<GameObject, object> s_Assets = new ConditionalWeakTable<GameObject, object>();

        /// <summary>A new GameObject outside the scene that receives no message until attached.</summary>
        internal static GameObject NewDetached(string name, bool activeSelf)
        {
            var go = new GameObject(name);
            World.Remove(go);
            go.SetActive(false);
            s_IntendedActive.AddOrUpdate(go, activeSelf);
            return go;
        }

        /// <summary>The activeSelf a GameObject has (or, detached, will have once attached).</summary>
        internal static bool ActiveSelf(GameObject go) =>
            s_IntendedActive.TryGetValue(go, out var intended) ? (bool)intended : go.ActiveSelfCore;

        /// <summary>Sets the activeSelf a detached GameObject will get.</summary>
        internal static void SetIntendedActive(GameObject go, bool active) => s_IntendedActive.AddOrUpdate(go, active);

        /// <summary>Marks a detached hierarchy as an asset (a loaded prefab): it never joins the scene.</summary>
        internal static void MarkAsset(GameObject root)
        {
            foreach (var go in Hierarchy(root)) s_Assets.AddOrUpdate(go, true);
        }

        /// <summary>True for the GameObjects of a loaded prefab asset.</summary>
        internal static bool IsAsset(GameObject go) => s_Assets.TryGetValue(go, out _);

        /// <summary>Puts a detached clone hierarchy into the scene and activates it (Awake/OnEnable per Unity's rules).</summary>
        internal static void Attach(GameObject root)
        {
            var objects = Hierarchy(root);
            foreach (var go in objects) World.Add(go);
            PhysicsWorld.HierarchyPlaced(root.transform);
            for (int i = objects.Count - 1; i >= 1; i--) Activate(objects[i]);
            Activate(root);
        }

        static void Activate(GameObject go)
        {
            bool active = ActiveSelf(go);
            s_IntendedActive.Remove(go);
            go.SetActive(active);
        }

        /// <summary><paramref name="root"/> and its descendants, depth-first in child order.</summary>
        internal static List<GameObject> Hierarchy(GameObject root)
        {
            var into = new List<GameObject>();
            Collect(root.transform, into);
            return into;
        }

        static void Collect(Transform t, List<GameObject> into)
        {
            into.Add(t.gameObject);
            var children = t.ChildList;
            for (int i = 0; i < children.Count; i++) Collect(children[i], into);
        }
    }
}
