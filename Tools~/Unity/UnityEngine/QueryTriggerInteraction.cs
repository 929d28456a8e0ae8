namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.QueryTriggerInteraction: overrides the global Physics.queriesHitTriggers.</summary>
    public enum QueryTriggerInteraction
    {
        /// <summary>Queries use the global Physics.queriesHitTriggers setting.</summary>
        UseGlobal = 0,
        /// <summary>Queries never report Trigger hits.</summary>
        Ignore = 1,
        /// <summary>Queries always report Trigger hits.</summary>
        Collide = 2,
    }
}
