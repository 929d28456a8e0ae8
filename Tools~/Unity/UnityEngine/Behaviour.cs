using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.Behaviour: a component that can be enabled or disabled.</summary>
    public class Behaviour : Component
    {
        bool m_Enabled = true;

        /// <summary>Enabled Behaviours are Updated, disabled Behaviours are not.</summary>
        public bool enabled
        {
            get { EnsureAlive(); return m_Enabled; }
            set
            {
                EnsureAlive();
                if (m_Enabled == value) return;
                m_Enabled = value;
                if (this is MonoBehaviour behaviour) Lifecycle.EnabledChanged(behaviour);
            }
        }

        /// <summary>Reports whether a GameObject and its associated Behaviour is active and enabled.</summary>
        public bool isActiveAndEnabled => IsAlive && m_Enabled && Owner.IsActiveInHierarchy;
    }
}
