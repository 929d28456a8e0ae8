using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.CapsuleCollider: a capsule-shaped primitive collider. Under a scaled Transform the height
    /// is scaled by the lossy scale along the capsule's axis and the radius by the larger of the two other axes.
    /// </summary>
    public class CapsuleCollider : Collider
    {
        Vector3 m_Center;
        float m_Radius = 0.5f, m_Height = 2f;
        int m_Direction = 1;

        /// <summary>The center of the capsule, measured in the object's local space.</summary>
        public Vector3 center
        {
            get { EnsureAlive(); return m_Center; }
            set { EnsureAlive(); m_Center = value; }
        }

        /// <summary>The radius of the sphere, measured in the object's local space.</summary>
        public float radius
        {
            get { EnsureAlive(); return m_Radius; }
            set { EnsureAlive(); m_Radius = value; }
        }

        /// <summary>The height of the capsule measured in the object's local space.</summary>
        public float height
        {
            get { EnsureAlive(); return m_Height; }
            set { EnsureAlive(); m_Height = value; }
        }

        /// <summary>The direction of the capsule (0, 1, 2 = X, Y, Z axis).</summary>
        public int direction
        {
            get { EnsureAlive(); return m_Direction; }
            set
            {
                EnsureAlive();
                if (value < 0 || value > 2) throw StandInError.Unsupported("CapsuleCollider.direction = " + value + " (0, 1 or 2)");
                m_Direction = value;
            }
        }

        internal override WorldShape BuildShape(in ShapeFrame frame)
        {
            int a = m_Direction, b = (m_Direction + 1) % 3, c = (m_Direction + 2) % 3;
            float radius = Math.Abs(m_Radius) * Math.Max(frame.AbsScale(b), frame.AbsScale(c));
            float halfSegment = Math.Max(0f, 0.5f * Math.Abs(m_Height) * frame.AbsScale(a) - radius);
            var localAxis = a == 0 ? new Vector3(1f, 0f, 0f) : a == 1 ? new Vector3(0f, 1f, 0f) : new Vector3(0f, 0f, 1f);
            return WorldShape.Capsule(frame.Point(m_Center), frame.Rotation * localAxis, halfSegment, radius);
        }
    }
}
