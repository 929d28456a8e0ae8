using System;

namespace UnityEngine.Events
{
    /// <summary>
    /// Stand-in of Unity's internal ArgumentCache: the stored argument of a persistent listener bound in the
    /// Inspector (field names as Unity serializes them, reference source Runtime/Export/UnityEvent/UnityEvent.cs).
    /// </summary>
    [Serializable]
    internal sealed class ArgumentCache
    {
        [SerializeField] Object m_ObjectArgument;
        [SerializeField] string m_ObjectArgumentAssemblyTypeName;
        [SerializeField] int m_IntArgument;
        [SerializeField] float m_FloatArgument;
        [SerializeField] string m_StringArgument;
        [SerializeField] bool m_BoolArgument;

        internal Object ObjectArgument => m_ObjectArgument;
        internal string ObjectArgumentTypeName => m_ObjectArgumentAssemblyTypeName;
        internal int IntArgument => m_IntArgument;
        internal float FloatArgument => m_FloatArgument;
        internal string StringArgument => m_StringArgument;
        internal bool BoolArgument => m_BoolArgument;
    }
}
