using System;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.RequireComponent: AddComponent first adds the required components that are missing.</summary>
    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)]
    public sealed class RequireComponent : Attribute
    {
        /// <summary>The first required component type.</summary>
        public Type m_Type0;

        /// <summary>The second required component type, or null.</summary>
        public Type m_Type1;

        /// <summary>The third required component type, or null.</summary>
        public Type m_Type2;

        /// <summary>Require a single component.</summary>
        public RequireComponent(Type requiredComponent) { m_Type0 = requiredComponent; }

        /// <summary>Require two components.</summary>
        public RequireComponent(Type requiredComponent, Type requiredComponent2) { m_Type0 = requiredComponent; m_Type1 = requiredComponent2; }

        /// <summary>Require three components.</summary>
        public RequireComponent(Type requiredComponent, Type requiredComponent2, Type requiredComponent3)
        {
            m_Type0 = requiredComponent;
            m_Type1 = requiredComponent2;
            m_Type2 = requiredComponent3;
        }
    }
}
