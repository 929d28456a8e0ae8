using System.Collections.Generic;
using System.Runtime.InteropServices;
using UnityEngine;
using UnityEngine.Rendering;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the shared built-in meshes GameObject.CreatePrimitive puts in the MeshFilter, one instance
    /// per PrimitiveType (named "Cube", "Sphere", …, as Unity's), built with the public Mesh API from
    /// <see cref="PrimitiveGeometry"/>: Position and Normal (float32 × 3) in stream 0, UInt16 indices, one Triangles
    /// sub-mesh, bounds recalculated from the vertices. World.Reset drops the cache.
    /// </summary>
    internal static class PrimitiveMeshes
    {
        static readonly Dictionary<PrimitiveType, Mesh> s_Meshes = new Dictionary<PrimitiveType, Mesh>();

        static PrimitiveMeshes() => World.WorldReset += s_Meshes.Clear;

        [StructLayout(LayoutKind.Sequential)]
        struct PositionNormal
        {
            public Vector3 Position;
            public Vector3 Normal;
        }

        /// <summary>The shared mesh of <paramref name="type"/>.</summary>
        internal static Mesh Get(PrimitiveType type)
        {
            if (s_Meshes.TryGetValue(type, out var mesh) && mesh != null) return mesh;
            mesh = Build(type);
            s_Meshes[type] = mesh;
            return mesh;
        }

        /// <summary>The primitive type whose shared mesh <paramref name="mesh"/> is, or null for any other mesh.</summary>
        internal static PrimitiveType? TypeOf(Mesh mesh)
        {
            if (mesh is null) return null;
            foreach (var pair in s_Meshes)
                if (ReferenceEquals(pair.Value, mesh)) return pair.Key;
            return null;
        }

        static Mesh Build(PrimitiveType type)
        {
            var geometry = PrimitiveGeometry.Of(type);
            int count = geometry.Positions.Count;
            var vertices = new PositionNormal[count];
            for (int i = 0; i < count; i++) vertices[i] = new PositionNormal { Position = geometry.Positions[i], Normal = geometry.Normals[i] };
            var indices = new ushort[geometry.Triangles.Count];
            for (int i = 0; i < indices.Length; i++) indices[i] = (ushort)geometry.Triangles[i];

            var mesh = new Mesh { name = type.ToString() };
            mesh.SetVertexBufferParams(count,
                new VertexAttributeDescriptor(VertexAttribute.Position, VertexAttributeFormat.Float32, 3),
                new VertexAttributeDescriptor(VertexAttribute.Normal, VertexAttributeFormat.Float32, 3));
            mesh.SetVertexBufferData(vertices, 0, 0, count);
            mesh.SetIndexBufferParams(indices.Length, IndexFormat.UInt16);
            mesh.SetIndexBufferData(indices, 0, 0, indices.Length);
            mesh.subMeshCount = 1;
            mesh.SetSubMesh(0, new SubMeshDescriptor(0, indices.Length));
            mesh.RecalculateBounds();
            return mesh;
        }
    }
}
