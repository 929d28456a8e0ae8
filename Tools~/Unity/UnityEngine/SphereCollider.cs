using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.SphereCollider: a sphere-shaped primitive collider. Under a scaled Transform the sphere
    /// stays a sphere: its radius is scaled by the largest absolute component of the lossy scale.
    /// </summary>
    public class SphereCollider : Collider
    {
        Vector3 m_Center;
        float m_Radius = 0.5f;

        /// <summary>The center of the sphere in the object's local space.</summary>
        public Vector3 center
        {
            get { EnsureAlive(); return m_Center; }
            set { EnsureAlive(); m_Center = value; }
        }

        /// <summary>The radius of the sphere measured in the object's local space.</summary>
        public float radius
        {
            get { EnsureAlive(); return m_Radius; }
            set { EnsureAlive(); m_Radius = value; }
        }

        internal override WorldShape BuildShape(in ShapeFrame frame)
        {
            float scale = Math.Max(frame.AbsScale(0), Math.Max(frame.AbsScale(1), frame.AbsScale(2)));
            return WorldShape.Sphere(frame.Point(m_Center), Math.Abs(m_Radius) * scale);
        }
    }
}
