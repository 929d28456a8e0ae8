using System;
using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Renderer: enabled flag and shared materials (the array getter returns a copy, as
    /// Unity's does). bounds is the world AABB of the bounds the renderer was last notified of by its mesh.
    /// </summary>
    public class Renderer : Component
    {
        bool m_Enabled = true;
        Material[] m_Materials = Array.Empty<Material>();

        /// <summary>Makes the rendered 3D object visible if enabled.</summary>
        public bool enabled
        {
            get { EnsureAlive(); return m_Enabled; }
            set { EnsureAlive(); m_Enabled = value; }
        }

        /// <summary>The shared material of this object: the first material, or null when there is none. Setting it replaces the first material.</summary>
        public Material sharedMaterial
        {
            get { EnsureAlive(); return m_Materials.Length > 0 ? m_Materials[0] : null; }
            set
            {
                EnsureAlive();
                if (m_Materials.Length == 0) m_Materials = new Material[1];
                m_Materials[0] = value;
            }
        }

        /// <summary>All the shared materials of this object (a copy; assigning copies the array).</summary>
        public Material[] sharedMaterials
        {
            get { EnsureAlive(); return (Material[])m_Materials.Clone(); }
            set
            {
                EnsureAlive();
                if (value == null) throw new ArgumentNullException("m");
                m_Materials = (Material[])value.Clone();
            }
        }

        /// <summary>The bounding box of the renderer in world space: its mesh's notified bounds transformed by the Transform.</summary>
        public Bounds bounds
        {
            get
            {
                EnsureAlive();
                var local = LocalBoundsForCulling;
                if (local == null) return new Bounds(transform.position, Vector3.zero);
                return ToWorld(local.Value, transform);
            }
            set => throw StandInError.Unsupported("Renderer.bounds (set)");
        }

        /// <summary>Local bounds the renderer culls with (null when it has nothing to draw).</summary>
        internal virtual Bounds? LocalBoundsForCulling => throw StandInError.Unsupported(GetType().Name + ".bounds");

        static Bounds ToWorld(Bounds local, Transform t)
        {
            Vector3 c = local.center, e = local.extents;
            var world = new Bounds(t.TransformPoint(c), Vector3.zero);
            for (int i = 0; i < 8; i++)
            {
                var corner = new Vector3((i & 1) == 0 ? c.x - e.x : c.x + e.x, (i & 2) == 0 ? c.y - e.y : c.y + e.y, (i & 4) == 0 ? c.z - e.z : c.z + e.z);
                world.Encapsulate(t.TransformPoint(corner));
            }
            return world;
        }
    }
}
