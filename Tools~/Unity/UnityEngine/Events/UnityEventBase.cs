using System;
using System.Collections.Generic;

namespace UnityEngine.Events
{
    /// <summary>
    /// Stand-in of UnityEngine.Events.UnityEventBase: abstract base class for UnityEvents. Serialized like Unity's (one
    /// field, m_PersistentCalls, holding the listeners bound in the Inspector); listeners added from code are not
    /// serialized. Invoke calls the persistent listeners first, then the runtime ones, over a snapshot taken when
    /// the invocation starts (reference source Runtime/Export/UnityEvent/UnityEvent.cs, InvokableCallList).
    /// </summary>
    [Serializable]
    public abstract class UnityEventBase
    {
        [SerializeField] PersistentCallGroup m_PersistentCalls = new PersistentCallGroup();
        readonly List<Delegate> m_RuntimeCalls = new List<Delegate>();

        /// <summary>Get the number of registered persistent listeners.</summary>
        public int GetPersistentEventCount() => Persistent.Count;

        /// <summary>Get the target component of the listener at index index.</summary>
        public Object GetPersistentTarget(int index) => index >= 0 && index < Persistent.Count ? Persistent[index].Target : null;

        /// <summary>Get the target method name of the listener at index index.</summary>
        public string GetPersistentMethodName(int index) => index >= 0 && index < Persistent.Count ? Persistent[index].MethodName ?? string.Empty : string.Empty;

        /// <summary>Remove all non-persistent (ie created from script) listeners from the event.</summary>
        public void RemoveAllListeners()
        {
            m_RuntimeCalls.Clear();
            m_RuntimeSnapshot = null;
        }

        /// <inheritdoc/>
        public override string ToString() => base.ToString() + " " + GetType().FullName;

        // ---- stand-in internals -----------------------------------------------------------------------------
        List<PersistentCall> Persistent => (m_PersistentCalls ??= new PersistentCallGroup()).Calls;

        /// <summary>The parameter types of the event (for persistent listeners in EventDefined mode).</summary>
        internal abstract Type[] EventTypes { get; }

        internal void AddRuntime(Delegate call)
        {
            if (call == null) throw new ArgumentNullException(nameof(call));
            m_RuntimeCalls.Add(call);
            m_RuntimeSnapshot = null;
        }

        internal void RemoveRuntime(Delegate call)
        {
            if (call == null) return;
            m_RuntimeCalls.RemoveAll(d => d.Target == call.Target && d.Method.Equals(call.Method));
            m_RuntimeSnapshot = null;
        }

        // Unity's InvokableCallList.PrepareInvoke keeps the list of calls to execute and rebuilds it only after a
        // listener was added or removed, so an Invoke allocates nothing once warm; the stand-in keeps a snapshot alike.
        [NonSerialized] Delegate[] m_RuntimeSnapshot;

        /// <summary>Whether any persistent listener is bound (the arguments array is made only then).</summary>
        internal bool HasPersistentCalls => Persistent.Count > 0;

        /// <summary>Runs the persistent listeners over a snapshot.</summary>
        internal void InvokePersistent(object[] arguments)
        {
            var persistent = Persistent.ToArray();
            for (int i = 0; i < persistent.Length; i++) persistent[i].Invoke(EventTypes, arguments);
        }

        /// <summary>The runtime listeners as they were when the invocation starts (rebuilt only after AddListener/RemoveListener).</summary>
        internal Delegate[] RuntimeSnapshot() => m_RuntimeSnapshot ??= m_RuntimeCalls.ToArray();

        /// <summary>A runtime listener whose target is a destroyed Object is skipped.</summary>
        internal static bool IsDestroyedTarget(Delegate call) => call.Target is Object target && target == null;
    }
}
