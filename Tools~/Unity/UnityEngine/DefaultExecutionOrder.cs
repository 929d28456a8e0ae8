using System;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.DefaultExecutionOrder: specifies the script execution order for a MonoBehaviour-derived
    /// class relative to other MonoBehaviour-derived types. The stand-in's player loop sorts scripts by it (lower first,
    /// 0 for scripts without it; creation order among equals).
    /// </summary>
    [AttributeUsage(AttributeTargets.Class)]
    public class DefaultExecutionOrder : Attribute
    {
        /// <summary>Creates the attribute with the given execution order.</summary>
        public DefaultExecutionOrder(int order) { this.order = order; }

        /// <summary>The execution order of the MonoBehaviour type this attribute is applied to.</summary>
        public int order { get; private set; }
    }
}
