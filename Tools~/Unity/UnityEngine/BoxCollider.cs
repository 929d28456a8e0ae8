using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.BoxCollider: a box-shaped primitive collider, scaled per axis by the Transform's lossy scale.</summary>
    public class BoxCollider : Collider
    {
        Vector3 m_Center;
        Vector3 m_Size = new Vector3(1f, 1f, 1f);

        /// <summary>The center of the box, measured in the object's local space.</summary>
        public Vector3 center
        {
            get { EnsureAlive(); return m_Center; }
            set { EnsureAlive(); m_Center = value; }
        }

        /// <summary>The size of the box, measured in the object's local space.</summary>
        public Vector3 size
        {
            get { EnsureAlive(); return m_Size; }
            set { EnsureAlive(); m_Size = value; }
        }

        internal override WorldShape BuildShape(in ShapeFrame frame)
        {
            var half = new Vector3(0.5f * Math.Abs(m_Size.x) * frame.AbsScale(0), 0.5f * Math.Abs(m_Size.y) * frame.AbsScale(1),
                0.5f * Math.Abs(m_Size.z) * frame.AbsScale(2));
            return WorldShape.Box(frame.Point(m_Center), frame.Rotation, half);
        }
    }
}
