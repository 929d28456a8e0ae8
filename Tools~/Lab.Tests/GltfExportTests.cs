using System;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using HookeRope.Fracture;
using HookeRope.Lab.Figures;
using HookeRope.Lab.Output;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using NUnit.Framework;
using SharpGLTF.Schema2;
using SkiaSharp;

namespace HookeRope.Lab.Tests
{
    /// <summary>
    /// Issue 17 item 5: the glTF export of a broken rope carries the burr texture. The .glb of the built-in fracture run,
    /// read back with SharpGLTF, has one embedded PNG that decodes to the core generator's pixels, on the strand material
    /// only, with a trilinear repeat sampler, and the strands' texture coordinates address it the way the package does.
    /// </summary>
    [TestFixture]
    public sealed class GltfExportTests : TempFolderTest
    {
        const int W = FigureTexture.BurrWidth, H = FigureTexture.BurrHeight;

        ModelRoot ExportedFracture()
        {
            int code = InvokeLab(out _, out string error, "run", "fracture", "--gltf", "--out", dir);
            Assert.That(code, Is.EqualTo(0), error);
            // self-contained: the .glb alone in a folder of its own loads with its image
            string alone = Path.Combine(dir, "alone");
            Directory.CreateDirectory(alone);
            string glb = Path.Combine(alone, "fracture.glb");
            File.Copy(Path.Combine(dir, "fracture-t1.500.glb"), glb);
            var model = ModelRoot.Load(glb);
            Assert.That(Directory.GetFiles(alone), Has.Length.EqualTo(1), "nothing written beside the .glb");
            return model;
        }

        /// <summary>The core generator's level 0 (RGBA32, row 0 = v = 0), as the runtime uploads it.</summary>
        static byte[] GeneratorPixels()
        {
            var rgba = new byte[BurrTextureGenerator.ByteCount(W, H)];
            BurrTextureGenerator.Generate(W, H, FigureTexture.BurrTriangles, 1u, 214, 200, 160, rgba);
            return rgba;
        }

        /// <summary>PNG bytes decoded to unpremultiplied RGBA32, image row 0 (the top) first.</summary>
        static byte[] Decode(ReadOnlyMemory<byte> png, out int width, out int height)
        {
            using (var stream = new MemoryStream(png.ToArray()))
            using (var codec = SKCodec.Create(stream))
            {
                Assert.That(codec, Is.Not.Null, "the embedded image is a file Skia decodes");
                Assert.That(codec.EncodedFormat, Is.EqualTo(SKEncodedImageFormat.Png));
                width = codec.Info.Width;
                height = codec.Info.Height;
                var info = new SKImageInfo(width, height, SKColorType.Rgba8888, SKAlphaType.Unpremul);
                var pixels = new byte[info.BytesSize];
                var handle = GCHandle.Alloc(pixels, GCHandleType.Pinned);
                try
                {
                    Assert.That(codec.GetPixels(info, handle.AddrOfPinnedObject()), Is.EqualTo(SKCodecResult.Success));
                }
                finally
                {
                    handle.Free();
                }
                return pixels;
            }
        }

        [Test]
        public void TheStrandMaterialCarriesTheBurrTextureWithATrilinearSamplerAndTheTubeMaterialNone()
        {
            var model = ExportedFracture();
            var primitives = model.LogicalMeshes[0].Primitives;
            Assert.That(primitives.Count, Is.EqualTo(2), "tube and caps, strands");
            Material tube = primitives[0].Material, strands = primitives[1].Material;
            Assert.That(tube.Name, Is.EqualTo(GltfExport.TubeMaterialName));
            Assert.That(strands.Name, Is.EqualTo(GltfExport.StrandMaterialName));
            Assert.That(tube, Is.Not.SameAs(strands), "a separate material for the strands");
            Assert.That(model.LogicalMaterials.Count, Is.EqualTo(2));

            MaterialChannel tubeColour = tube.FindChannel("BaseColor").Value, strandColour = strands.FindChannel("BaseColor").Value;
            Assert.That(tubeColour.Texture, Is.Null, "the tube is a plain colour");
            Assert.That(tube.Channels.All(c => c.Texture == null), Is.True, "no texture on any channel of the tube");
            Assert.That(tubeColour.Color, Is.EqualTo(GltfExport.RopeColour));
            // the package's burr material: a copy of the tube material with the burr texture as its colour map, opaque
            Assert.That(strandColour.Color, Is.EqualTo(GltfExport.RopeColour));
            Assert.That(strands.Alpha, Is.EqualTo(AlphaMode.OPAQUE));
            Texture texture = strandColour.Texture;
            Assert.That(texture, Is.Not.Null, "the strands' base colour is textured");
            Assert.That(strandColour.TextureCoordinate, Is.EqualTo(0), "on TEXCOORD_0");
            Assert.That(model.LogicalTextures.Count, Is.EqualTo(1));
            Assert.That(model.LogicalImages.Count, Is.EqualTo(1));
            Assert.That(texture.PrimaryImage, Is.SameAs(model.LogicalImages[0]));
            Assert.That(texture.PrimaryImage.Name, Is.EqualTo(GltfExport.BurrImageName));
            Assert.That(texture.PrimaryImage.Content.IsPng, Is.True, "embedded as a PNG");
            // the runtime's sampler: repeat, trilinear (Unity's FilterMode.Trilinear over the mip chain)
            TextureSampler sampler = texture.Sampler;
            Assert.That(sampler, Is.Not.Null);
            Assert.That(sampler.MinFilter, Is.EqualTo(TextureMipMapFilter.LINEAR_MIPMAP_LINEAR));
            Assert.That(sampler.MagFilter, Is.EqualTo(TextureInterpolationFilter.LINEAR));
            Assert.That(sampler.WrapS, Is.EqualTo(TextureWrapMode.REPEAT));
            Assert.That(sampler.WrapT, Is.EqualTo(TextureWrapMode.REPEAT));
        }

        [Test]
        public void TheEmbeddedImageDecodesToTheGeneratorsPixelsTopRowFirst()
        {
            var model = ExportedFracture();
            var png = model.LogicalImages[0].Content.Content;
            var image = Decode(png, out int width, out int height);
            Assert.That(width, Is.EqualTo(W));
            Assert.That(height, Is.EqualTo(H));
            var generated = GeneratorPixels();
            int differing = 0;
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W * 4; x++)
                    if (image[y * W * 4 + x] != generated[(H - 1 - y) * W * 4 + x]) differing++;
            TestContext.WriteLine($"embedded PNG {png.Length} B, {width} × {height}; {differing} of {W * H * 4} bytes differ from the generator");
            Assert.That(differing, Is.EqualTo(0), "lossless: every RGBA byte of the generator, image row y = texture row H − 1 − y");
            // the orientation a glTF viewer sees: the triangles' bases (alpha 1) along the image's top, the gaps at its bottom
            double top = 0, bottom = 0;
            for (int x = 0; x < W; x++) { top += image[x * 4 + 3]; bottom += image[((H - 1) * W + x) * 4 + 3]; }
            Assert.That(top / (255.0 * W), Is.GreaterThan(0.9), "top row: the triangles' bases");
            Assert.That(bottom / (255.0 * W), Is.LessThan(0.1), "bottom row: past the apexes");
        }

        [Test]
        public void TheStrandsAddressTheTextureAsThePackageDoes()
        {
            // the core's own mesh of the same run, and its export
            var result = ScenarioRunner.Run(BuiltInScenarios.Resolve("fracture"));
            Assert.That(result.Meshes.Count, Is.EqualTo(1));
            MeshSnapshot mesh = result.Meshes[0];
            string path = Path.Combine(dir, "fracture.glb");
            GltfExport.Write(mesh, "fracture", path);
            var model = ModelRoot.Load(path);
            var primitives = model.LogicalMeshes[0].Primitives;
            var image = Decode(model.LogicalImages[0].Content.Content, out _, out _);
            var generated = GeneratorPixels();
            var uv = primitives[1].GetVertexAccessor("TEXCOORD_0").AsVector2Array();
            var strandIndices = primitives[1].GetIndices();
            Assert.That(strandIndices.Count, Is.EqualTo(mesh.Indices.Length - mesh.TubeIndexCount));
            Assert.That(strandIndices.Count, Is.EqualTo(2 * 126 * 9), "two broken ends of 126 fibres (R = 10 mm), three faces each");
            int compared = 0, differing = 0;
            float least = float.MaxValue, most = float.MinValue;
            for (int k = 0; k < strandIndices.Count; k += 3)
            {
                int[] corner = { (int)strandIndices[k], (int)strandIndices[k + 1], (int)strandIndices[k + 2] };
                Assert.That(corner[0], Is.EqualTo(mesh.Indices[mesh.TubeIndexCount + k]), "the strands' own triangles");
                foreach (int c in corner)
                {
                    least = Math.Min(least, Math.Min(uv[c].X, uv[c].Y));
                    most = Math.Max(most, Math.Max(uv[c].X, uv[c].Y));
                }
                // points inside the face: the texel a glTF viewer reads at the exported uv (origin at the image's top-left)
                // is the texel the package reads at the core's uv (Unity: origin bottom-left, the generator's row 0)
                for (int i = 1; i < 6; i++)
                {
                    for (int j = 1; i + j < 6; j++)
                    {
                        float wa = i / 6.1f, wb = j / 6.1f, wc = 1f - wa - wb;
                        float uGltf = wa * uv[corner[0]].X + wb * uv[corner[1]].X + wc * uv[corner[2]].X;
                        float vGltf = wa * uv[corner[0]].Y + wb * uv[corner[1]].Y + wc * uv[corner[2]].Y;
                        float uCore = wa * CoreU(mesh, corner[0]) + wb * CoreU(mesh, corner[1]) + wc * CoreU(mesh, corner[2]);
                        float vCore = wa * CoreV(mesh, corner[0]) + wb * CoreV(mesh, corner[1]) + wc * CoreV(mesh, corner[2]);
                        int viewer = (Texel(vGltf, H) * W + Texel(uGltf, W)) * 4;
                        int package = (Texel(vCore, H) * W + Texel(uCore, W)) * 4;
                        for (int ch = 0; ch < 4; ch++)
                            if (image[viewer + ch] != generated[package + ch]) differing++;
                        compared++;
                    }
                }
            }
            TestContext.WriteLine($"{strandIndices.Count / 3} strand faces, {compared} texel look-ups, {differing} channel values differ; strand uv in [{least}, {most}]");
            Assert.That(differing, Is.EqualTo(0));
            Assert.That(least, Is.GreaterThanOrEqualTo(0f), "strand uvs in [0, 1]: one copy of the texture per face");
            Assert.That(most, Is.LessThanOrEqualTo(1f));
            // the tube keeps its own coordinates: u around in [0, 1], v along the rest arc (finite, repeat wrap)
            var tubeUv = primitives[0].GetVertexAccessor("TEXCOORD_0").AsVector2Array();
            foreach (var p in tubeUv)
            {
                Assert.That(p.X, Is.InRange(0f, 1f));
                Assert.That(float.IsFinite(p.Y), Is.True);
            }
        }

        static float CoreU(MeshSnapshot mesh, int vertex) => mesh.Vertices[vertex * GltfExport.Stride + 10];

        static float CoreV(MeshSnapshot mesh, int vertex) => mesh.Vertices[vertex * GltfExport.Stride + 11];

        /// <summary>Nearest texel of a coordinate in [0, 1] over <paramref name="size"/> texels.</summary>
        static int Texel(float coordinate, int size) => Math.Min(size - 1, Math.Max(0, (int)(coordinate * size)));
    }
}
