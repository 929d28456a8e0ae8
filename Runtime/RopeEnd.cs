using System;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// What one end of an <see cref="ElasticRope"/> is attached to: nothing (a free end), a Transform the end
    /// follows (an anchor or an XR hand: the rope cannot move it), or a Rigidbody the rope pulls and is pulled
    /// by (two-way, e.g. the harness D-ring of a worker rig), or a rig without a Rigidbody (a CharacterController, a
    /// kinematic XR rig) that the rope carries as a point mass of <see cref="RigMass"/> kg and tells where to move
    /// (<see cref="ElasticRope.EndRigDisplacement"/>). With a Rigidbody, <see cref="Point"/> (optional) marks where on
    /// the body the rope is fixed; without one, the body's position is used.
    /// </summary>
    [Serializable]
    public sealed class RopeEnd
    {
        [SerializeField, Tooltip("Transform this end follows (anchor, XR hand), or, with a Rigidbody, the attachment point on that body (e.g. a D-ring child). Empty = free end or the body's position.")]
        Transform m_Point;

        [SerializeField, Tooltip("Rigidbody this end pulls two-way (its mass in kg joins the rope; rope force is applied to it in N). Empty = kinematic or free end.")]
        Rigidbody m_Body;

        [SerializeField, Min(0f), Tooltip("Mass of a rig without a Rigidbody (CharacterController, kinematic XR rig) at Point, in kg; used when Body is empty. The rope carries the rig as a load of this mass and reports where it must move each step. 0 = off: the Point is followed as an anchor.")]
        float m_RigMass;

        /// <summary>The Transform this end follows, or the attachment point on <see cref="Body"/>; null when neither.</summary>
        public Transform Point { get => m_Point; set => m_Point = value; }

        /// <summary>The Rigidbody this end pulls two-way; null for a kinematic or free end.</summary>
        public Rigidbody Body { get => m_Body; set => m_Body = value; }

        /// <summary>
        /// Mass in kg (finite, ≥ 0) of a rig without a Rigidbody at <see cref="Point"/>, used when <see cref="Body"/> is
        /// empty: the rope carries the rig as a load of this mass (<see cref="RopeEndKind.KinematicRig"/>). 0 = off.
        /// Negative or non-finite → ArgumentOutOfRangeException.
        /// </summary>
        public float RigMass
        {
            get => m_RigMass;
            set
            {
                if (!(value >= 0f) || float.IsInfinity(value)) throw new ArgumentOutOfRangeException(nameof(value), value, "RigMass must be finite and in [0, +inf) kg (0 = off)");
                m_RigMass = value;
            }
        }

        /// <summary>What the end is attached to, derived from which fields are set.</summary>
        public RopeEndKind Kind =>
            m_Body != null ? RopeEndKind.Rigidbody
            : m_Point == null ? RopeEndKind.Free
            : m_RigMass > 0f && !float.IsInfinity(m_RigMass) ? RopeEndKind.KinematicRig
            : RopeEndKind.Transform;

        /// <summary>
        /// World position (m) of the attachment as it is drawn this frame: the Point's Transform, else the body's
        /// Transform (interpolated by Unity when the body interpolates). Only for attached ends.
        /// </summary>
        internal Vector3 DrawnPosition() => m_Point != null ? m_Point.position : m_Body.transform.position;

        /// <summary>
        /// World position (m) of a Rigidbody attachment in the physics pose (Rigidbody.position and rotation, not the
        /// possibly interpolated Transform): the Point carried rigidly with the body, else the body's position. For a
        /// Transform end, the Point's position.
        /// </summary>
        internal Vector3 PhysicsPosition()
        {
            if (m_Body == null) return m_Point.position;
            if (m_Point == null) return m_Body.position;
            var bodyTransform = m_Body.transform;
            var local = Quaternion.Inverse(bodyTransform.rotation) * (m_Point.position - bodyTransform.position);
            return m_Body.position + m_Body.rotation * local;
        }

        /// <summary>World position of the attachment in metres, or <paramref name="fallback"/> for a free end.</summary>
        public Vector3 WorldPosition(Vector3 fallback)
        {
            if (m_Point != null) return m_Point.position;
            if (m_Body != null) return m_Body.position;
            return fallback;
        }
    }
}
