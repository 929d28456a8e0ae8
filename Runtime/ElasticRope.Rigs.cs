using UnityEngine;

namespace HookeRope
{
    // Rigs without a Rigidbody (issue 13 item 1): the force on each attachment, the event after every step, and where
    // a rig carried by the rope (RopeEndKind.KinematicRig) must move. Documentation~/index.md, "Rigs without a Rigidbody".
    public sealed partial class ElasticRope
    {
        [SerializeField, Tooltip("Raised after every step with the forces (world, N) the rope applied on its start and end attachments over that step. Rig scripts move a CharacterController here (EndRigDisplacement).")]
        RopeForcesUnityEvent m_OnStepped = new RopeForcesUnityEvent();

        /// <summary>
        /// Raised after every step (allocation-free) with <see cref="StartForce"/> and <see cref="EndForce"/> (N, world).
        /// A rig without a Rigidbody moves itself here by <see cref="StartRigDisplacement"/> or <see cref="EndRigDisplacement"/>.
        /// </summary>
        public RopeForcesUnityEvent OnStepped => m_OnStepped;

        /// <summary>
        /// Force in newtons (world axes) the rope applied on the start attachment over the last step: a Transform end
        /// the pin force (Rope.GetPinForce: the segments' pull plus the end particle's weight); a Rigidbody the force
        /// applied to it (Rope.GetLoadHostForce); a rig without a Rigidbody the rope's mean force on it,
        /// M·(Δv/Δt − g) (Rope.GetLoadForce); a free end zero. Zero before the first step.
        /// </summary>
        public Vector3 StartForce => _attachments.StartForce;

        /// <summary>Force in newtons (world axes) the rope applied on the end attachment over the last step; see <see cref="StartForce"/>.</summary>
        public Vector3 EndForce => _attachments.EndForce;

        /// <summary>
        /// Displacement in metres (world axes) a start rig without a Rigidbody (<see cref="RopeEndKind.KinematicRig"/>)
        /// must make for the last step, e.g. CharacterController.Move(StartRigDisplacement): where the rope carried the
        /// rig's mass minus where its Point was. Gravity is included; the rig applies no gravity of its own while
        /// attached. Zero for other kinds of end.
        /// </summary>
        public Vector3 StartRigDisplacement => m_Start.Kind == RopeEndKind.KinematicRig ? _attachments.StartRig.Displacement.ToVector3() : Vector3.zero;

        /// <summary>Displacement in metres (world axes) an end rig without a Rigidbody must make for the last step; see <see cref="StartRigDisplacement"/>.</summary>
        public Vector3 EndRigDisplacement => m_End.Kind == RopeEndKind.KinematicRig ? _attachments.EndRig.Displacement.ToVector3() : Vector3.zero;

        /// <summary>
        /// Velocity in m/s (world axes) of a start rig without a Rigidbody at the end of the last step. The next step
        /// starts from it plus the rig's deviation from <see cref="StartRigDisplacement"/> over the step (a wall that
        /// stopped the rig takes the blocked velocity away). Setting it replaces both for the next step (the rig's
        /// own velocity, or after a teleport). Non-finite → ArgumentException.
        /// </summary>
        public Vector3 StartRigVelocity
        {
            get => _attachments.StartRig.Velocity.ToVector3();
            set => _attachments.StartRig.SetVelocity(value.ToFloat3());
        }

        /// <summary>Velocity in m/s (world axes) of an end rig without a Rigidbody; see <see cref="StartRigVelocity"/>.</summary>
        public Vector3 EndRigVelocity
        {
            get => _attachments.EndRig.Velocity.ToVector3();
            set => _attachments.EndRig.SetVelocity(value.ToFloat3());
        }
    }
}
