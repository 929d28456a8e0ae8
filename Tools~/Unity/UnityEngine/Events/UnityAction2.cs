namespace UnityEngine.Events
{
    /// <summary>Stand-in of UnityEngine.Events.UnityAction&lt;T0,T1&gt;: two argument delegate used by UnityEvents.</summary>
    public delegate void UnityAction<T0, T1>(T0 arg0, T1 arg1);
}
