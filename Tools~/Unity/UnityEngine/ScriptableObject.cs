using System;
using System.Reflection;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.ScriptableObject: a data object that lives outside GameObjects. As in Unity, an
    /// instance made with <see cref="CreateInstance(Type)"/> receives Awake and OnEnable at once, in Edit and in Play
    /// mode (no [ExecuteAlways] needed), and OnDisable then OnDestroy when it is destroyed.
    /// </summary>
    public class ScriptableObject : Object
    {
        bool m_Enabled;

        /// <summary>Creates an instance of a scriptable object.</summary>
        public static ScriptableObject CreateInstance(Type type)
        {
            var instance = Construct(type);
            instance.SendCreateMessages();
            return instance;
        }

        /// <summary>Creates an instance of a scriptable object.</summary>
        public static T CreateInstance<T>() where T : ScriptableObject => (T)CreateInstance(typeof(T));

        // ---- stand-in internals -----------------------------------------------------------------------------
        /// <summary>A new instance of <paramref name="type"/> that has received no message yet.</summary>
        internal static ScriptableObject Construct(Type type)
        {
            if (type == null) throw new ArgumentNullException(nameof(type));
            if (!typeof(ScriptableObject).IsAssignableFrom(type) || type.IsAbstract)
                throw new ArgumentException("Instance of " + type.Name + " couldn't be created because it is abstract or not a ScriptableObject.", nameof(type));
            try
            {
                return (ScriptableObject)Activator.CreateInstance(type, nonPublic: true);
            }
            catch (TargetInvocationException e) when (e.InnerException != null)
            {
                throw e.InnerException;
            }
        }

        /// <summary>Awake, then OnEnable, as Unity sends them to a new instance.</summary>
        internal void SendCreateMessages()
        {
            Send("Awake");
            if (!IsAlive) return;
            m_Enabled = true;
            Send("OnEnable");
        }

        internal override void DestroyNow()
        {
            if (!IsAlive) return;
            if (m_Enabled)
            {
                m_Enabled = false;
                Send("OnDisable");
            }
            Send("OnDestroy");
            base.DestroyNow();
        }

        void Send(string message)
        {
            MethodInfo method = null;
            const BindingFlags Declared = BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly;
            for (var t = GetType(); t != null && t != typeof(ScriptableObject) && method == null; t = t.BaseType)
                method = t.GetMethod(message, Declared, null, Type.EmptyTypes, null);
            if (method == null) return;
            try
            {
                method.Invoke(this, null);
            }
            catch (TargetInvocationException e)
            {
                Debug.LogException(e.InnerException ?? e, this);
            }
        }
    }
}
