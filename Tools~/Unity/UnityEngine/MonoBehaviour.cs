using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.MonoBehaviour: the base class of scripts. The stand-in's player loop sends Unity's
    /// messages (Awake, OnEnable, Start, FixedUpdate, Update, LateUpdate, OnDisable, OnDestroy) by name.
    /// </summary>
    public class MonoBehaviour : Behaviour
    {
        Action m_FixedUpdate, m_Update, m_LateUpdate;
        bool m_Bound;

        /// <summary>Awake has run.</summary>
        internal bool AwakeCalled;

        /// <summary>OnEnable has run and OnDisable has not run since.</summary>
        internal bool EnableCalled;

        /// <summary>Start has run.</summary>
        internal bool StartCalled;

        internal Action FixedUpdateCall { get { Bind(); return m_FixedUpdate; } }

        internal Action UpdateCall { get { Bind(); return m_Update; } }

        internal Action LateUpdateCall { get { Bind(); return m_LateUpdate; } }

        /// <summary>Binds the per-frame messages once, so the loop calls them without reflection or allocation.</summary>
        void Bind()
        {
            if (m_Bound) return;
            m_Bound = true;
            m_FixedUpdate = Messages.Bind(this, "FixedUpdate");
            m_Update = Messages.Bind(this, "Update");
            m_LateUpdate = Messages.Bind(this, "LateUpdate");
        }
    }
}
