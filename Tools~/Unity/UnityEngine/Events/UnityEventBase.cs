namespace UnityEngine.Events
{
    /// <summary>Shim of UnityEngine.Events.UnityEventBase: abstract base class for UnityEvents.</summary>
    public abstract class UnityEventBase
    {
        /// <summary>Get the number of registered persistent listeners.</summary>
        public int GetPersistentEventCount() => throw Shim.NotRun;

        /// <summary>Remove all non-persistent (ie created from script) listeners from the event.</summary>
        public void RemoveAllListeners() => throw Shim.NotRun;
    }
}
