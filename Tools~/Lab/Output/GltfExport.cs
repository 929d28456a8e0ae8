using System.Numerics;
using HookeRope.Lab.Simulation;
using SharpGLTF.Memory;
using SharpGLTF.Schema2;

namespace HookeRope.Lab.Output
{
    /// <summary>Writes a captured tube mesh as a binary glTF (.glb) with SharpGLTF.Core (no Toolkit).</summary>
    public static class GltfExport
    {
        /// <summary>Floats per interleaved vertex: position 3, normal 3, tangent 4, uv 2.</summary>
        public const int Stride = 12;

        /// <summary>Writes <paramref name="mesh"/> to <paramref name="path"/> (.glb).</summary>
        public static void Write(MeshSnapshot mesh, string name, string path)
        {
            int count = mesh.Vertices.Length / Stride;
            var positions = new float[count * 3];
            var normals = new float[count * 3];
            var tangents = new float[count * 4];
            var uvs = new float[count * 2];
            var v = mesh.Vertices;
            for (int i = 0; i < count; i++)
            {
                int o = i * Stride;
                positions[3 * i] = v[o];
                positions[3 * i + 1] = v[o + 1];
                positions[3 * i + 2] = v[o + 2];
                var n = new Vector3(v[o + 3], v[o + 4], v[o + 5]);
                n = n.LengthSquared() > 1e-12f ? Vector3.Normalize(n) : Vector3.UnitY;
                normals[3 * i] = n.X;
                normals[3 * i + 1] = n.Y;
                normals[3 * i + 2] = n.Z;
                var t = new Vector3(v[o + 6], v[o + 7], v[o + 8]);
                t = t.LengthSquared() > 1e-12f ? Vector3.Normalize(t) : Vector3.UnitX;
                tangents[4 * i] = t.X;
                tangents[4 * i + 1] = t.Y;
                tangents[4 * i + 2] = t.Z;
                tangents[4 * i + 3] = v[o + 9] < 0 ? -1f : 1f;
                uvs[2 * i] = v[o + 10];
                uvs[2 * i + 1] = v[o + 11];
            }
            var model = ModelRoot.CreateModel();
            var gltfMesh = model.CreateMesh(name);
            var position = Vertices(model, positions, count, DimensionType.VEC3);
            var normal = Vertices(model, normals, count, DimensionType.VEC3);
            var tangent = Vertices(model, tangents, count, DimensionType.VEC4);
            var uv = Vertices(model, uvs, count, DimensionType.VEC2);
            int tube = mesh.TubeIndexCount > 0 && mesh.TubeIndexCount <= mesh.Indices.Length ? mesh.TubeIndexCount : mesh.Indices.Length;
            // Submesh 0: tube and caps; submesh 1: the burr fibres, with their own material (issue 17).
            AddPrimitive(model, gltfMesh, mesh.Indices, 0, tube, NewMaterial(model, "rope", new Vector4(0.85f, 0.55f, 0.1f, 1f)), position, normal, tangent, uv);
            if (tube < mesh.Indices.Length)
                AddPrimitive(model, gltfMesh, mesh.Indices, tube, mesh.Indices.Length - tube,
                    NewMaterial(model, "burr fibres", new Vector4(0.84f, 0.78f, 0.63f, 1f)), position, normal, tangent, uv);
            model.UseScene("rope").CreateNode(name).Mesh = gltfMesh;
            model.SaveGLB(path);
        }

        static Material NewMaterial(ModelRoot model, string name, Vector4 colour)
        {
            var material = model.CreateMaterial(name);
            material.InitializePBRMetallicRoughness();
            var baseColor = material.FindChannel("BaseColor");
            if (baseColor.HasValue)
            {
                var channel = baseColor.Value;
                channel.Color = colour;
            }
            return material;
        }

        static void AddPrimitive(ModelRoot model, Mesh gltfMesh, int[] allIndices, int start, int length, Material material,
            Accessor position, Accessor normal, Accessor tangent, Accessor uv)
        {
            var primitive = gltfMesh.CreatePrimitive();
            primitive.SetVertexAccessor("POSITION", position);
            primitive.SetVertexAccessor("NORMAL", normal);
            primitive.SetVertexAccessor("TANGENT", tangent);
            primitive.SetVertexAccessor("TEXCOORD_0", uv);
            var indexBytes = new byte[length * 4];
            System.Buffer.BlockCopy(allIndices, start * 4, indexBytes, 0, indexBytes.Length);
            var indices = model.CreateAccessor();
            indices.SetIndexData(model.UseBufferView(indexBytes, 0, null, 0, BufferMode.ELEMENT_ARRAY_BUFFER), 0, length, IndexEncodingType.UNSIGNED_INT);
            primitive.SetIndexAccessor(indices);
            primitive.DrawPrimitiveType = PrimitiveType.TRIANGLES;
            primitive.Material = material;
        }

        static Accessor Vertices(ModelRoot model, float[] data, int count, DimensionType dimensions)
        {
            var bytes = new byte[data.Length * 4];
            System.Buffer.BlockCopy(data, 0, bytes, 0, bytes.Length);
            var accessor = model.CreateAccessor();
            accessor.SetVertexData(model.UseBufferView(bytes, 0, null, 0, BufferMode.ARRAY_BUFFER), 0, count,
                new AttributeFormat(dimensions, EncodingType.FLOAT));
            return accessor;
        }
    }
}
