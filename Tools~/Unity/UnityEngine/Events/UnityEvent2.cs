namespace UnityEngine.Events
{
    /// <summary>Shim of UnityEngine.Events.UnityEvent&lt;T0,T1&gt;: two argument version of UnityEvent.</summary>
    [System.Serializable]
    public class UnityEvent<T0, T1> : UnityEventBase
    {
        /// <summary>Constructor.</summary>
        public UnityEvent() { }

        /// <summary>Add a non persistent listener to the UnityEvent.</summary>
        public void AddListener(UnityAction<T0, T1> call) => throw Shim.NotRun;

        /// <summary>Remove a non persistent listener from the UnityEvent.</summary>
        public void RemoveListener(UnityAction<T0, T1> call) => throw Shim.NotRun;

        /// <summary>Invoke all registered callbacks (runtime and persistent).</summary>
        public void Invoke(T0 arg0, T1 arg1) => throw Shim.NotRun;
    }
}
