using System;

namespace UnityEngine.Events
{
    /// <summary>Stand-in of UnityEngine.Events.UnityEvent&lt;T0,T1&gt;: two argument version of UnityEvent.</summary>
    [Serializable]
    public class UnityEvent<T0, T1> : UnityEventBase
    {
        static readonly Type[] s_Types = { typeof(T0), typeof(T1) };

        /// <summary>Constructor.</summary>
        public UnityEvent() { }

        /// <summary>Add a non persistent listener to the UnityEvent.</summary>
        public void AddListener(UnityAction<T0, T1> call) => AddRuntime(call);

        /// <summary>Remove a non persistent listener from the UnityEvent.</summary>
        public void RemoveListener(UnityAction<T0, T1> call) => RemoveRuntime(call);

        /// <summary>Invoke all registered callbacks (runtime and persistent).</summary>
        public void Invoke(T0 arg0, T1 arg1)
        {
            if (HasPersistentCalls) InvokePersistent(new object[] { arg0, arg1 });
            var runtime = RuntimeSnapshot();
            for (int i = 0; i < runtime.Length; i++)
                if (!IsDestroyedTarget(runtime[i])) ((UnityAction<T0, T1>)runtime[i])(arg0, arg1);
        }

        internal override Type[] EventTypes => s_Types;
    }
}
