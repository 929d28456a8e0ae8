using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.MeshCollider: a collider built from a mesh. The stand-in has geometry only for the
    /// Plane (10 × 10 in local XZ) and Quad (1 × 1 in local XY) primitive meshes — flat rectangles through the
    /// object's origin; any other mesh is reported as unsupported as soon as a query or contact check needs it.
    /// </summary>
    public class MeshCollider : Collider
    {
        Mesh m_SharedMesh;

        /// <summary>The mesh object used for collision detection.</summary>
        public Mesh sharedMesh
        {
            get { EnsureAlive(); return m_SharedMesh; }
            set { EnsureAlive(); m_SharedMesh = value; }
        }

        /// <summary>Like Unity, a MeshCollider added to an object with a MeshFilter takes the filter's mesh.</summary>
        internal override void OnStandInAttached()
        {
            base.OnStandInAttached();
            var filter = GetComponent<MeshFilter>();
            if (filter is object) m_SharedMesh = filter.sharedMesh;
        }

        internal override WorldShape BuildShape(in ShapeFrame frame)
        {
            var mesh = m_SharedMesh;
            if (mesh is null || !mesh.IsAlive) return WorldShape.Nothing;
            var primitive = PrimitiveMeshes.TypeOf(mesh);
            if (primitive == PrimitiveType.Plane)
                return WorldShape.Box(frame.Position, frame.Rotation, new Vector3(5f * frame.AbsScale(0), 0f, 5f * frame.AbsScale(2)));
            if (primitive == PrimitiveType.Quad)
                return WorldShape.Box(frame.Position, frame.Rotation, new Vector3(0.5f * frame.AbsScale(0), 0.5f * frame.AbsScale(1), 0f));
            return WorldShape.NotSupported(this);
        }

        /// <summary>
        /// World direction of the front faces of the primitive rectangle in <paramref name="frame"/> (Plane: local +Y,
        /// Quad: local −Z, reversed by a negative scale on that axis, as the inverse-transpose carries normals): raycasts
        /// skip back faces (Physics.queriesHitBackfaces is false by default). Zero for other meshes.
        /// </summary>
        internal Vector3 FrontNormal(in ShapeFrame frame)
        {
            var mesh = m_SharedMesh;
            if (mesh is null || !mesh.IsAlive) return Vector3.zero;
            var primitive = PrimitiveMeshes.TypeOf(mesh);
            if (primitive == PrimitiveType.Plane) return frame.Rotation * new Vector3(0f, frame.Scale.y < 0f ? -1f : 1f, 0f);
            if (primitive == PrimitiveType.Quad) return frame.Rotation * new Vector3(0f, 0f, frame.Scale.z < 0f ? 1f : -1f);
            return Vector3.zero;
        }

        internal override string UnsupportedGeometry() =>
            "MeshCollider " + Describe() + " with the mesh '" + (m_SharedMesh is null ? "" : m_SharedMesh.name) +
            "' (the stand-in has geometry only for the Plane and Quad primitive meshes)";
    }
}
