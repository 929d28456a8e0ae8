namespace UnityEngine.Events
{
    /// <summary>Stand-in of UnityEngine.Events.PersistentListenerMode: the mode that a listener is operating in.</summary>
    [System.Serializable]
    public enum PersistentListenerMode
    {
        /// <summary>The listener will use the function binding specified by the event.</summary>
        EventDefined = 0,
        /// <summary>The listener will bind to zero argument functions.</summary>
        Void = 1,
        /// <summary>The listener will bind to one argument Object functions.</summary>
        Object = 2,
        /// <summary>The listener will bind to one argument int functions.</summary>
        Int = 3,
        /// <summary>The listener will bind to one argument float functions.</summary>
        Float = 4,
        /// <summary>The listener will bind to one argument string functions.</summary>
        String = 5,
        /// <summary>The listener will bind to one argument bool functions.</summary>
        Bool = 6,
    }
}
