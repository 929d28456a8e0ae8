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
        public void RemoveAllListeners() => m_RuntimeCalls.Clear();

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
        }

        internal void RemoveRuntime(Delegate call)
        {
            if (call == null) return;
            m_RuntimeCalls.RemoveAll(d => d.Target == call.Target && d.Method.Equals(call.Method));
        }

        /// <summary>Runs the persistent listeners, then a snapshot of the runtime ones; runtime listeners on destroyed objects are skipped.</summary>
        internal void InvokeAll(object[] arguments, Action<Delegate> invokeRuntime)
        {
            var persistent = Persistent.ToArray();
            var runtime = m_RuntimeCalls.ToArray();
            for (int i = 0; i < persistent.Length; i++) persistent[i].Invoke(EventTypes, arguments);
            for (int i = 0; i < runtime.Length; i++)
            {
                if (runtime[i].Target is Object target && target == null) continue;
                invokeRuntime(runtime[i]);
            }
        }
    }
}
