using System.Numerics;
using HookeRope.Lab.Figures;
using HookeRope.Lab.Simulation;
using SharpGLTF.Memory;
using SharpGLTF.Schema2;

namespace HookeRope.Lab.Output
{
    /// <summary>
    /// Writes a captured tube mesh as a binary glTF (.glb) with SharpGLTF.Core (no Toolkit): primitive 0 the tube and caps
    /// with the material "rope" (a colour, no texture), primitive 1 (when a broken end has burr strands) with the material
    /// "burr fibres", the package's burr material: the rope's colour times the package's burr texture
    /// (<see cref="BurrTexturePng"/>, embedded in the .glb's binary chunk as a PNG) as its base-colour texture, sampled
    /// with repeat wrap and trilinear mipmap filtering (the viewer builds the mip chain, as glTF carries level 0 only),
    /// opaque (the texture's alpha triangles are not a cut-out, as in the package). Texture coordinates are flipped to
    /// glTF's convention (origin at the image's top-left: v_glTF = 1 − v), so the strands' base (v = 1) reads the
    /// texture's top row, where the triangles are wide, and their tips (v = 0) the bottom. Tangents are copied as the core
    /// writes them (no normal map is exported; a viewer that normal-maps the mesh should regenerate them from these uvs).
    /// </summary>
    public static class GltfExport
    {
        /// <summary>Floats per interleaved vertex: position 3, normal 3, tangent 4, uv 2.</summary>
        public const int Stride = 12;

        /// <summary>Name of the tube and caps' material.</summary>
        public const string TubeMaterialName = "rope";

        /// <summary>Name of the burr strands' material.</summary>
        public const string StrandMaterialName = "burr fibres";

        /// <summary>Name of the embedded burr image.</summary>
        public const string BurrImageName = "burr texture";

        /// <summary>Base colour factor of both materials (linear RGBA): the rope's colour, which the strands' texture tints.</summary>
        public static readonly Vector4 RopeColour = new Vector4(0.85f, 0.55f, 0.1f, 1f);

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
                uvs[2 * i + 1] = 1f - v[o + 11];
            }
            var model = ModelRoot.CreateModel();
            var gltfMesh = model.CreateMesh(name);
            var position = Vertices(model, positions, count, DimensionType.VEC3);
            var normal = Vertices(model, normals, count, DimensionType.VEC3);
            var tangent = Vertices(model, tangents, count, DimensionType.VEC4);
            var uv = Vertices(model, uvs, count, DimensionType.VEC2);
            int tube = mesh.TubeIndexCount > 0 && mesh.TubeIndexCount <= mesh.Indices.Length ? mesh.TubeIndexCount : mesh.Indices.Length;
            // Submesh 0: tube and caps; submesh 1: the burr fibres, with their own material (issue 17).
            AddPrimitive(model, gltfMesh, mesh.Indices, 0, tube, NewMaterial(model, TubeMaterialName), position, normal, tangent, uv);
            if (tube < mesh.Indices.Length)
                AddPrimitive(model, gltfMesh, mesh.Indices, tube, mesh.Indices.Length - tube, StrandMaterial(model), position, normal, tangent, uv);
            model.UseScene("rope").CreateNode(name).Mesh = gltfMesh;
            model.SaveGLB(path);
        }

        static Material NewMaterial(ModelRoot model, string name)
        {
            var material = model.CreateMaterial(name);
            material.InitializePBRMetallicRoughness();
            var channel = material.FindChannel("BaseColor").Value;
            channel.Color = RopeColour;
            return material;
        }

        /// <summary>The package's burr material: the rope's colour, with the burr texture (PNG, in the binary chunk) on TEXCOORD_0.</summary>
        static Material StrandMaterial(ModelRoot model)
        {
            var material = NewMaterial(model, StrandMaterialName);
            var image = model.UseImage(new MemoryImage(BurrTexturePng.Encode()));
            image.Name = BurrImageName;
            material.FindChannel("BaseColor").Value.SetTexture(0, image, null, TextureWrapMode.REPEAT, TextureWrapMode.REPEAT,
                TextureMipMapFilter.LINEAR_MIPMAP_LINEAR, TextureInterpolationFilter.LINEAR);
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
