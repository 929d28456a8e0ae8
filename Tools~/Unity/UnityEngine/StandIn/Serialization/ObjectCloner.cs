using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using UnityEngine;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: Object.Instantiate's cloning (Scripting Reference "Object.Instantiate", 2022.3). A GameObject
    /// is cloned with its children and every component; cloning a component clones its whole GameObject and returns
    /// the matching component. Serialized fields are copied by value (<see cref="SerializedCopy"/>); references to
    /// objects inside the cloned hierarchy are remapped onto the clones, references outside it are kept. The clone
    /// hierarchy is built out of the scene and receives Awake/OnEnable (when active, and when scripts run in this
    /// mode) only after all of it is set up.
    /// </summary>
    internal sealed class ObjectCloner
    {
        readonly Dictionary<Object, Object> m_Map = new Dictionary<Object, Object>(ReferenceComparer.Instance);
        readonly List<(Component Source, Component Clone)> m_Components = new List<(Component, Component)>();

        /// <summary>Clones the hierarchy of <paramref name="original"/> (a GameObject or a component) out of the scene.</summary>
        internal static (GameObject Root, Object Result) CloneDetached(Object original)
        {
            var sourceRoot = original as GameObject ?? ((Component)original).gameObject;
            var cloner = new ObjectCloner();
            var root = cloner.CloneObject(sourceRoot);
            cloner.CopyState(sourceRoot, root);
            return (root, cloner.Remap(original));
        }

        /// <summary>The clone of <paramref name="o"/> when it belongs to the cloned hierarchy, else <paramref name="o"/>.</summary>
        Object Remap(Object o)
        {
            if (o is null) return null;
            return m_Map.TryGetValue(o, out var clone) ? clone : o;
        }

        GameObject CloneObject(GameObject source)
        {
            var clone = SceneHooks.NewDetached(source.name, SceneHooks.ActiveSelf(source));
            m_Map[source] = clone;
            m_Map[source.transform] = clone.transform;
            var components = source.ComponentList;
            for (int i = 1; i < components.Count; i++)
            {
                var component = components[i];
                if (!component.IsAlive) continue;
                var copy = Claim(clone, component.GetType()) ?? clone.AddComponent(component.GetType());
                if (copy == null) throw new InvalidOperationException("Object.Instantiate could not add a " + component.GetType().Name + " to the clone of '" + source.name + "'");
                m_Map[component] = copy;
                m_Components.Add((component, copy));
            }
            var children = source.transform.ChildList;
            for (int i = 0; i < children.Count; i++)
            {
                var child = CloneObject(children[i].gameObject);
                child.transform.SetParent(clone.transform, false);
            }
            return clone;
        }

        /// <summary>A component of exactly <paramref name="type"/> already on the clone (added by [RequireComponent]) that no original claimed yet.</summary>
        Component Claim(GameObject clone, Type type)
        {
            var components = clone.ComponentList;
            for (int i = 1; i < components.Count; i++)
            {
                var c = components[i];
                if (c.GetType() != type || !c.IsAlive) continue;
                bool claimed = false;
                foreach (var pair in m_Components)
                    if (ReferenceEquals(pair.Clone, c)) { claimed = true; break; }
                if (!claimed) return c;
            }
            return null;
        }

        void CopyState(GameObject sourceRoot, GameObject root)
        {
            foreach (var pair in m_Map)
            {
                if (!(pair.Key is GameObject source)) continue;
                var clone = (GameObject)pair.Value;
                clone.layer = source.layer;
                clone.hideFlags = source.hideFlags;
                var from = source.transform;
                var to = clone.transform;
                if (!ReferenceEquals(source, sourceRoot))
                {
                    to.localPosition = from.localPosition;
                    to.localRotation = from.localRotation;
                }
                to.localScale = from.localScale;
            }
            Func<Object, Object> remap = Remap;
            foreach (var (source, clone) in m_Components)
            {
                if (source is MonoBehaviour behaviour)
                {
                    SerializedCopy.CopyFields(source, clone, remap);
                    ((MonoBehaviour)clone).enabled = behaviour.enabled;
                }
                else BuiltinComponentState.Copy(source, clone, remap);
            }
        }

        sealed class ReferenceComparer : IEqualityComparer<Object>
        {
            internal static readonly ReferenceComparer Instance = new ReferenceComparer();
            public bool Equals(Object x, Object y) => ReferenceEquals(x, y);
            public int GetHashCode(Object obj) => RuntimeHelpers.GetHashCode(obj);
        }
    }
}
