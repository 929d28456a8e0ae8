using System;
using System.Collections.Generic;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Component: the base class of everything attached to a GameObject. Components are
    /// created only by <see cref="GameObject.AddComponent(Type)"/> (and GameObject's constructors); their name is
    /// their GameObject's name.
    /// </summary>
    public class Component : Object
    {
        [ThreadStatic] static GameObject s_Constructing;
        readonly GameObject m_GameObject;

        /// <summary>Created by AddComponent only: picks up the GameObject it is being added to.</summary>
        public Component()
        {
            m_GameObject = s_Constructing;
            if (m_GameObject is null)
                throw StandInError.Unsupported("new " + GetType().Name + "() outside AddComponent (Unity creates components only through AddComponent)");
        }

        /// <summary>The Transform attached to this GameObject.</summary>
        public Transform transform => gameObject.transform;

        /// <summary>The game object this component is attached to.</summary>
        public GameObject gameObject
        {
            get { EnsureAlive(); return m_GameObject; }
        }

        /// <summary>Gets a reference to a component of type T on the same GameObject as the component specified.</summary>
        public T GetComponent<T>() => gameObject.GetComponent<T>();

        /// <summary>Returns the component of type if the GameObject has one attached, null if it doesn't.</summary>
        public Component GetComponent(Type type) => gameObject.GetComponent(type);

        /// <summary>Gets the component of the specified type, if it exists.</summary>
        public bool TryGetComponent<T>(out T component) => gameObject.TryGetComponent(out component);

        /// <summary>Returns all components of Type type in the GameObject.</summary>
        public T[] GetComponents<T>() => gameObject.GetComponents<T>();

        /// <summary>Returns the component of Type type in the GameObject or any of its children using depth first search.</summary>
        public T GetComponentInChildren<T>(bool includeInactive = false) => gameObject.GetComponentInChildren<T>(includeInactive);

        /// <summary>Returns the component of Type type in the GameObject or any of its children using depth first search.</summary>
        public T GetComponentInChildren<T>() => gameObject.GetComponentInChildren<T>(false);

        /// <summary>Returns the component of Type type in the GameObject or any of its parents.</summary>
        public T GetComponentInParent<T>(bool includeInactive = false) => gameObject.GetComponentInParent<T>(includeInactive);

        /// <summary>Returns the component of Type type in the GameObject or any of its parents.</summary>
        public T GetComponentInParent<T>() => gameObject.GetComponentInParent<T>(false);

        /// <summary>Returns all components of Type type in the GameObject or any of its children.</summary>
        public T[] GetComponentsInChildren<T>(bool includeInactive = false) => gameObject.GetComponentsInChildren<T>(includeInactive);

        // ---- stand-in internals -----------------------------------------------------------------------------
        internal override string NameCore { get => m_GameObject.NameCore; set => m_GameObject.NameCore = value; }

        /// <summary>The GameObject even after destruction (for the stand-in's own bookkeeping).</summary>
        internal GameObject Owner => m_GameObject;

        /// <summary>Called right after the component joined its GameObject, before any Unity message; overrides call the base.</summary>
        internal virtual void OnStandInAttached() { }

        /// <summary>Creates a component of <paramref name="type"/> on <paramref name="owner"/> and attaches it (no messages).</summary>
        internal static Component Construct(Type type, GameObject owner)
        {
            var previous = s_Constructing;
            s_Constructing = owner;
            Component component;
            try
            {
                component = (Component)Activator.CreateInstance(type, nonPublic: true);
            }
            catch (System.Reflection.TargetInvocationException e) when (e.InnerException != null)
            {
                throw e.InnerException;
            }
            finally
            {
                s_Constructing = previous;
            }
            owner.ComponentList.Add(component);
            component.OnStandInAttached();
            return component;
        }

        internal override void DestroyNow()
        {
            if (!IsAlive) return;
            Lifecycle.DestroyComponent(this);
        }
    }
}
