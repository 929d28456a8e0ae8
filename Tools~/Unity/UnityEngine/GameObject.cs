using System;
using System.Collections.Generic;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.GameObject: a named object with a Transform and components, active or not. Adding
    /// a component honours [RequireComponent] (required components are added first) and [DisallowMultipleComponent]
    /// (a second one is refused with Unity's error), and runs Awake/OnEnable at once in Play mode (in Edit mode only
    /// for [ExecuteAlways] scripts), as Unity does.
    /// </summary>
    public sealed partial class GameObject : Object
    {
        readonly List<Component> m_Components = new List<Component>();
        bool m_ActiveSelf = true;
        int m_Layer;

        /// <summary>Creates a new game object, named name.</summary>
        public GameObject(string name) : this(name, Array.Empty<Type>()) { }

        /// <summary>Creates a new game object named "New Game Object".</summary>
        public GameObject() : this("New Game Object") { }

        /// <summary>Creates a game object and attaches the specified components.</summary>
        public GameObject(string name, params Type[] components)
        {
            NameCore = name ?? string.Empty;
            Component.Construct(typeof(Transform), this);
            World.Add(this);
            if (components == null) return;
            for (int i = 0; i < components.Length; i++) AddComponent(components[i]);
        }

        /// <summary>The Transform attached to this GameObject.</summary>
        public Transform transform
        {
            get { EnsureAlive(); return (Transform)m_Components[0]; }
        }

        /// <summary>The layer the GameObject is in (0–31).</summary>
        public int layer
        {
            get { EnsureAlive(); return m_Layer; }
            set
            {
                EnsureAlive();
                if (value < 0 || value > 31)
                {
                    Debug.LogError("A game object can only be in one layer. The layer needs to be in the range [0...31]");
                    return;
                }
                m_Layer = value;
            }
        }

        /// <summary>The local active state of this GameObject (Read Only).</summary>
        public bool activeSelf
        {
            // a clone being built or a loaded prefab asset is held inactive outside the scene: report its own state
            get { EnsureAlive(); return SceneHooks.ActiveSelf(this); }
        }

        /// <summary>Defines whether the GameObject is active in the Scene: active itself and all its parents.</summary>
        public bool activeInHierarchy
        {
            get { EnsureAlive(); return IsActiveInHierarchy; }
        }

        /// <summary>Activates/Deactivates the GameObject, depending on the given true or false value.</summary>
        public void SetActive(bool value)
        {
            EnsureAlive();
            if (m_ActiveSelf == value) return;
            bool before = IsActiveInHierarchy;
            m_ActiveSelf = value;
            if (before != IsActiveInHierarchy) Lifecycle.ActiveInHierarchyChanged(this, IsActiveInHierarchy);
        }

        /// <summary>Adds a component class of type componentType to the GameObject.</summary>
        public T AddComponent<T>() where T : Component => (T)AddComponent(typeof(T));

        /// <summary>Adds a component class of type componentType to the GameObject.</summary>
        public Component AddComponent(Type componentType)
        {
            EnsureAlive();
            if (componentType == null) throw new ArgumentNullException(nameof(componentType));
            if (!typeof(Component).IsAssignableFrom(componentType))
                throw new ArgumentException("AddComponent requires a type derived from Component; " + componentType.Name + " is not.", nameof(componentType));
            if (componentType.IsAbstract || componentType == typeof(Component) || componentType == typeof(Behaviour) || componentType == typeof(MonoBehaviour))
            {
                Debug.LogError("Cannot add component of type '" + componentType.Name + "' because it is abstract. Add component of type that is derived from '" +
                               componentType.Name + "' instead.");
                return null;
            }
            if (componentType == typeof(Transform))
            {
                Debug.LogError("Can't add component 'Transform' to " + NameCore + " because such a component is already added to the game object!");
                return null;
            }
            if (DisallowsMultiple(componentType) && FindComponent(componentType) != null)
            {
                Debug.LogError("Can't add component '" + componentType.Name + "' to " + NameCore +
                               " because such a component is already added to the game object!");
                return null;
            }
            foreach (RequireComponent require in componentType.GetCustomAttributes(typeof(RequireComponent), true))
            {
                AddRequired(require.m_Type0);
                AddRequired(require.m_Type1);
                AddRequired(require.m_Type2);
            }
            var component = Component.Construct(componentType, this);
            if (component is MonoBehaviour behaviour) Lifecycle.Added(behaviour);
            return component;
        }

        /// <summary>Returns the component of Type type if the game object has one attached, null if it doesn't.</summary>
        public T GetComponent<T>() => (T)(object)FindComponent(typeof(T));

        /// <summary>Returns the component of Type type if the game object has one attached, null if it doesn't.</summary>
        public Component GetComponent(Type type) => FindComponent(type);

        /// <summary>Gets the component of the specified type, if it exists.</summary>
        public bool TryGetComponent<T>(out T component)
        {
            var found = FindComponent(typeof(T));
            component = found != null ? (T)(object)found : default;
            return found != null;
        }

        /// <summary>Returns all components of Type type in the GameObject.</summary>
        public T[] GetComponents<T>()
        {
            EnsureAlive();
            var found = new List<T>();
            CollectComponents(found);
            return found.ToArray();
        }

        /// <summary>Returns the component of Type type in the GameObject or any of its children using depth first search (active GameObjects only unless includeInactive).</summary>
        public T GetComponentInChildren<T>(bool includeInactive = false) => (T)(object)FindInChildren(typeof(T), includeInactive);

        /// <summary>Returns the component of Type type in the GameObject or any of its children using depth first search.</summary>
        public T GetComponentInChildren<T>() => GetComponentInChildren<T>(false);

        /// <summary>Returns the component of Type type in the GameObject or any of its parents (active GameObjects only unless includeInactive).</summary>
        public T GetComponentInParent<T>(bool includeInactive = false) => (T)(object)FindInParent(typeof(T), includeInactive);

        /// <summary>Returns the component of Type type in the GameObject or any of its parents.</summary>
        public T GetComponentInParent<T>() => GetComponentInParent<T>(false);

        /// <summary>Returns all components of Type type in the GameObject or any of its children (active GameObjects only unless includeInactive).</summary>
        public T[] GetComponentsInChildren<T>(bool includeInactive = false)
        {
            EnsureAlive();
            var found = new List<T>();
            CollectInChildren(transform, found, includeInactive);
            return found.ToArray();
        }

        /// <summary>Returns all components of Type type in the GameObject or any of its children.</summary>
        public T[] GetComponentsInChildren<T>() => GetComponentsInChildren<T>(false);

        /// <summary>Finds an active GameObject by name and returns it (null when none is active with that name).</summary>
        public static GameObject Find(string name)
        {
            if (name == null) throw new ArgumentNullException(nameof(name));
            if (name.IndexOf('/') >= 0) throw StandInError.Unsupported("GameObject.Find with a hierarchy path ('" + name + "')");
            var objects = World.Objects;
            for (int i = 0; i < objects.Count; i++)
                if (objects[i].IsAlive && objects[i].IsActiveInHierarchy && objects[i].NameCore == name) return objects[i];
            return null;
        }

        // ---- stand-in internals -----------------------------------------------------------------------------
        /// <summary>The components in the order they were added; the Transform is first.</summary>
        internal List<Component> ComponentList => m_Components;

        /// <summary>The stored active flag (held false while a clone is built or for a prefab asset).</summary>
        internal bool ActiveSelfCore => m_ActiveSelf;

        /// <summary>Active itself and every parent active.</summary>
        internal bool IsActiveInHierarchy
        {
            get
            {
                for (var t = (Transform)m_Components[0]; t != null; t = t.ParentCore)
                    if (!t.gameObject.m_ActiveSelf) return false;
                return true;
            }
        }

        internal Component FindComponent(Type type)
        {
            EnsureAlive();
            for (int i = 0; i < m_Components.Count; i++)
            {
                var c = m_Components[i];
                if (c.IsAlive && type.IsInstanceOfType(c)) return c;
            }
            return null;
        }

        internal Component FindInChildren(Type type, bool includeInactive)
        {
            EnsureAlive();
            if (includeInactive || IsActiveInHierarchy)
            {
                var own = FindComponent(type);
                if (own != null) return own;
            }
            var children = transform.ChildList;
            for (int i = 0; i < children.Count; i++)
            {
                var found = children[i].gameObject.FindInChildren(type, includeInactive);
                if (found != null) return found;
            }
            return null;
        }

        internal Component FindInParent(Type type, bool includeInactive)
        {
            EnsureAlive();
            for (var t = transform; t != null; t = t.ParentCore)
            {
                var go = t.gameObject;
                if (!includeInactive && !go.IsActiveInHierarchy) continue;
                var found = go.FindComponent(type);
                if (found != null) return found;
            }
            return null;
        }

        internal void CollectComponents<T>(List<T> into)
        {
            for (int i = 0; i < m_Components.Count; i++)
                if (m_Components[i].IsAlive && m_Components[i] is T match) into.Add(match);
        }

        static void CollectInChildren<T>(Transform t, List<T> into, bool includeInactive)
        {
            var go = t.gameObject;
            if (includeInactive || go.IsActiveInHierarchy) go.CollectComponents(into);
            var children = t.ChildList;
            for (int i = 0; i < children.Count; i++) CollectInChildren(children[i], into, includeInactive);
        }

        void AddRequired(Type required)
        {
            if (required == null || FindComponent(required) != null) return;
            AddComponent(required);
        }

        static bool DisallowsMultiple(Type type)
        {
            for (var t = type; t != null && t != typeof(MonoBehaviour); t = t.BaseType)
                if (Attribute.IsDefined(t, typeof(DisallowMultipleComponent), false)) return true;
            return false;
        }

        internal override void DestroyNow()
        {
            if (!IsAlive) return;
            Lifecycle.DestroyHierarchy(this);
        }
    }
}
