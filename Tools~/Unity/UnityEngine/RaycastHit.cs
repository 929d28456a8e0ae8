namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.RaycastHit: information returned about a raycast hit. The stand-in fills point,
    /// normal, distance and collider; triangleIndex is −1 (only MeshCollider hits name a triangle, and the stand-in's
    /// MeshCollider shapes are primitives). Texture, lightmap and barycentric coordinates are not in the subset.
    /// </summary>
    public struct RaycastHit
    {
        Vector3 m_Point;
        Vector3 m_Normal;
        float m_Distance;
        Collider m_Collider;

        internal RaycastHit(Vector3 point, Vector3 normal, float distance, Collider collider)
        {
            m_Point = point;
            m_Normal = normal;
            m_Distance = distance;
            m_Collider = collider;
        }

        /// <summary>The Collider that was hit (null once it is destroyed).</summary>
        public Collider collider => m_Collider != null ? m_Collider : null;

        /// <summary>Instance ID of the Collider that was hit.</summary>
        public int colliderInstanceID => m_Collider is object ? m_Collider.GetInstanceID() : 0;

        /// <summary>The impact point in world space where the ray hit the collider.</summary>
        public Vector3 point { get => m_Point; set => m_Point = value; }

        /// <summary>The normal of the surface the ray hit.</summary>
        public Vector3 normal { get => m_Normal; set => m_Normal = value; }

        /// <summary>The distance from the ray's origin to the impact point.</summary>
        public float distance { get => m_Distance; set => m_Distance = value; }

        /// <summary>The index of the triangle that was hit (−1: not a mesh hit).</summary>
        public int triangleIndex => -1;

        /// <summary>The Transform of the rigidbody or collider that was hit.</summary>
        public Transform transform
        {
            get
            {
                var body = rigidbody;
                if (body != null) return body.transform;
                var hit = collider;
                return hit != null ? hit.transform : null;
            }
        }

        /// <summary>The Rigidbody of the collider that was hit. If the collider is not attached to a rigidbody then it is null.</summary>
        public Rigidbody rigidbody
        {
            get
            {
                var hit = collider;
                return hit != null ? hit.attachedRigidbody : null;
            }
        }
    }
}
