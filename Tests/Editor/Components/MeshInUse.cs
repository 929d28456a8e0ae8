using System;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// The part of a generated rope mesh that is drawn: RopeMeshRenderer sizes the vertex buffer for the most the tube can
    /// need (its ring budget), so <see cref="Mesh.vertexCount"/> is that capacity and the sub-meshes name the vertices in
    /// use (firstVertex 0, vertexCount = the tube's).
    /// </summary>
    static class MeshInUse
    {
        /// <summary>The vertex positions the sub-meshes use (the first GetSubMesh(0).vertexCount of <see cref="Mesh.vertices"/>).</summary>
        public static Vector3[] Vertices(Mesh mesh)
        {
            var all = mesh.vertices;
            var used = new Vector3[mesh.GetSubMesh(0).vertexCount];
            Array.Copy(all, used, used.Length);
            return used;
        }
    }
}
