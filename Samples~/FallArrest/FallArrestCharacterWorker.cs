using UnityEngine;

namespace HookeRope.Samples.FallArrest
{
    /// <summary>
    /// A worker rig without a Rigidbody, moved by a CharacterController, arrested by the lanyard whose End carries it
    /// (End Attachment: Point on the rig, Rig Mass = the worker's mass, Body empty). The rope integrates the rig's mass
    /// (gravity included) inside its own solve; after every step this script moves the controller by
    /// <see cref="ElasticRope.EndRigDisplacement"/>. The rig applies no gravity of its own while it is on the lanyard.
    /// </summary>
    [RequireComponent(typeof(CharacterController))]
    public sealed class FallArrestCharacterWorker : MonoBehaviour
    {
        [SerializeField, Tooltip("The lanyard whose End Attachment carries this rig (Rig Mass > 0, Body empty).")]
        ElasticRope m_Lanyard;

        CharacterController _controller;
        ElasticRope _listeningTo;

        /// <summary>The lanyard whose End Attachment carries this rig; setting it moves the listener over.</summary>
        public ElasticRope Lanyard
        {
            get => m_Lanyard;
            set { m_Lanyard = value; Listen(); }
        }

        void OnEnable() => Listen();

        void OnDisable() => StopListening();

        void Listen()
        {
            StopListening();
            if (!isActiveAndEnabled || m_Lanyard == null) return;
            _controller = GetComponent<CharacterController>();
            m_Lanyard.OnStepped.AddListener(MoveWithLanyard);
            _listeningTo = m_Lanyard;
        }

        void StopListening()
        {
            if (_listeningTo != null) _listeningTo.OnStepped.RemoveListener(MoveWithLanyard);
            _listeningTo = null;
        }

        /// <summary>After each rope step: go where the rope carried the worker's mass.</summary>
        void MoveWithLanyard(Vector3 startForce, Vector3 endForce) => _controller.Move(m_Lanyard.EndRigDisplacement);
    }
}
