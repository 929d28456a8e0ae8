using System;
using System.Collections.Generic;

namespace UnityEngine.Events
{
    /// <summary>Stand-in of Unity's internal PersistentCallGroup: the listeners bound in the Inspector, as serialized.</summary>
    [Serializable]
    internal sealed class PersistentCallGroup
    {
        [SerializeField] List<PersistentCall> m_Calls = new List<PersistentCall>();

        /// <summary>The persistent listeners in order.</summary>
        internal List<PersistentCall> Calls => m_Calls ??= new List<PersistentCall>();
    }
}
