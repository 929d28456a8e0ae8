using System;

namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.RequireComponent: the RequireComponent attribute automatically adds required components as dependencies.</summary>
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true, Inherited = true)]
    public sealed class RequireComponent : Attribute
    {
        /// <summary>Require a single component.</summary>
        public RequireComponent(Type requiredComponent) { }

        /// <summary>Require two components.</summary>
        public RequireComponent(Type requiredComponent, Type requiredComponent2) { }
    }
}
