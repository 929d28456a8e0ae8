using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.CharacterController: a capsule collider moved by script (no Rigidbody). Move translates
    /// the Transform by the motion (none below minMoveDistance) and velocity is the displacement of the last Move over
    /// Time.deltaTime. The stand-in sweeps nothing: a Move whose capsule ends inside a sphere, capsule or box collider
    /// throws instead of sliding along it (Unity would stop or slide the character and set collisionFlags), so
    /// isGrounded and collisionFlags are always false and None here. The capsule stays upright (Unity's controller
    /// does not rotate its capsule); height is scaled by |lossyScale.y|, radius by the larger of |x| and |z|.
    /// </summary>
    public class CharacterController : Collider
    {
        Vector3 m_Center, m_Velocity;
        float m_Radius = 0.5f, m_Height = 2f, m_MinMoveDistance = 0.001f;

        /// <summary>Supplies the movement of a GameObject with an attached CharacterController component; returns where it collided during the move.</summary>
        public CollisionFlags Move(Vector3 motion)
        {
            EnsureAlive();
            if (!(float.IsFinite(motion.x) && float.IsFinite(motion.y) && float.IsFinite(motion.z)))
                throw StandInError.Unsupported("CharacterController.Move with a non-finite motion " + motion);
            if (motion.magnitude < m_MinMoveDistance)
            {
                m_Velocity = Vector3.zero;
                return CollisionFlags.None;
            }
            var t = transform;
            t.position += motion;
            SyncTransform();
            ControllerOverlap.ThrowIfInsideAnotherCollider(this);
            float dt = Time.deltaTime;
            m_Velocity = dt > 0f ? motion / dt : Vector3.zero;
            return CollisionFlags.None;
        }

        /// <summary>The current relative velocity of the Character: the displacement of the last Move over Time.deltaTime (m/s).</summary>
        public Vector3 velocity { get { EnsureAlive(); return m_Velocity; } }

        /// <summary>Was the CharacterController touching the ground during the last move? (The stand-in resolves no collision: false.)</summary>
        public bool isGrounded { get { EnsureAlive(); return false; } }

        /// <summary>What part of the capsule collided with the environment during the last CharacterController.Move call (the stand-in: None).</summary>
        public CollisionFlags collisionFlags { get { EnsureAlive(); return CollisionFlags.None; } }

        /// <summary>The radius of the character's capsule.</summary>
        public float radius { get { EnsureAlive(); return m_Radius; } set { EnsureAlive(); m_Radius = value; } }

        /// <summary>The height of the character's capsule.</summary>
        public float height { get { EnsureAlive(); return m_Height; } set { EnsureAlive(); m_Height = value; } }

        /// <summary>The center of the character's capsule relative to the transform's position.</summary>
        public Vector3 center { get { EnsureAlive(); return m_Center; } set { EnsureAlive(); m_Center = value; } }

        /// <summary>Gets or sets the minimum move distance of the character controller (m; default 0.001): a smaller Move does not move it at all.</summary>
        public float minMoveDistance { get { EnsureAlive(); return m_MinMoveDistance; } set { EnsureAlive(); m_MinMoveDistance = value; } }

        internal override WorldShape BuildShape(in ShapeFrame frame)
        {
            float radius = Math.Abs(m_Radius) * Math.Max(frame.AbsScale(0), frame.AbsScale(2));
            float halfSegment = Math.Max(0f, 0.5f * Math.Abs(m_Height) * frame.AbsScale(1) - radius);
            var center = frame.Position + Vector3.Scale(frame.Scale, m_Center);
            return WorldShape.Capsule(center, new Vector3(0f, 1f, 0f), halfSegment, radius);
        }
    }
}
