using System;
using System.Runtime.InteropServices;
using System.Text.RegularExpressions;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.TestTools;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// The stand-in's rendering data holders against documented Unity facts: Mesh uploads read back as uploaded
    /// (layout packed in VertexAttribute order, sub-mesh ranges computed unless DontRecalculateBounds, flags and
    /// user notification recorded), Renderer.sharedMaterials returns a copy, Material(Material) copies, keywords and
    /// render queue, Texture2D.SetPixelData size checks and Apply(…, makeNoLongerReadable), the active render
    /// pipeline, Shader.Find, Color, Bounds, Gizmos and the built-in primitive meshes.
    /// </summary>
    [TestFixture]
    public sealed class RenderingFactsTests
    {
        [SetUp] public void SetUp() => World.Reset();
        [TearDown] public void TearDown() => World.Reset();

        /// <summary>The package's interleaved vertex: position, normal, tangent (xyzw), uv — 48 bytes.</summary>
        [StructLayout(LayoutKind.Sequential)]
        struct Vertex
        {
            public Vector3 Position;
            public Vector3 Normal;
            public float TX, TY, TZ, TW;
            public float U, V;

            public Vertex(float x, float y, float z)
            {
                Position = new Vector3(x, y, z);
                Normal = new Vector3(0f, 1f, 0f);
                TX = 1f; TY = 0f; TZ = 0f; TW = 1f;
                U = x; V = z;
            }
        }

        static readonly VertexAttributeDescriptor[] s_Layout =
        {
            // Deliberately not in VertexAttribute order: Unity packs each stream in that order regardless.
            new VertexAttributeDescriptor(VertexAttribute.TexCoord0, VertexAttributeFormat.Float32, 2),
            new VertexAttributeDescriptor(VertexAttribute.Position, VertexAttributeFormat.Float32, 3),
            new VertexAttributeDescriptor(VertexAttribute.Tangent, VertexAttributeFormat.Float32, 4),
            new VertexAttributeDescriptor(VertexAttribute.Normal, VertexAttributeFormat.Float32, 3),
        };

        static Vertex[] Quad() => new[]
        {
            new Vertex(0f, 0f, 0f), new Vertex(1f, 0f, 0f), new Vertex(1f, 0f, 2f), new Vertex(0f, 0f, 2f),
            new Vertex(5f, 5f, 5f), new Vertex(6f, 5f, 5f), new Vertex(6f, 5f, 6f),
        };

        static Mesh UploadedMesh(MeshUpdateFlags flags = MeshUpdateFlags.Default)
        {
            var vertices = Quad();
            var mesh = new Mesh();
            mesh.SetVertexBufferParams(vertices.Length, s_Layout);
            mesh.SetVertexBufferData(vertices, 0, 0, vertices.Length, 0, flags);
            var indices = new[] { 0, 2, 1, 0, 3, 2, 4, 6, 5 };
            mesh.SetIndexBufferParams(indices.Length, IndexFormat.UInt32);
            mesh.SetIndexBufferData(indices, 0, 0, indices.Length, flags);
            mesh.subMeshCount = 2;
            mesh.SetSubMesh(0, new SubMeshDescriptor(0, 6), flags);
            mesh.SetSubMesh(1, new SubMeshDescriptor(6, 3), flags);
            return mesh;
        }

        static void AssertVector(Vector3 actual, Vector3 expected, float tolerance = 1e-6f)
        {
            Assert.That(actual.x, Is.EqualTo(expected.x).Within(tolerance), "x of " + actual);
            Assert.That(actual.y, Is.EqualTo(expected.y).Within(tolerance), "y of " + actual);
            Assert.That(actual.z, Is.EqualTo(expected.z).Within(tolerance), "z of " + actual);
        }

        sealed class TestPipelineAsset : RenderPipelineAsset
        {
            public Material Material;
            public Shader Shader;
            public override Material defaultMaterial => Material;
            public override Shader defaultShader => Shader;
            protected override RenderPipeline CreatePipeline() => null;
        }

        // ---- Mesh ------------------------------------------------------------------------------------------------

        [Test]
        public void VertexLayoutIsPackedInVertexAttributeOrder()
        {
            var mesh = UploadedMesh();
            Assert.That(mesh.vertexCount, Is.EqualTo(7));
            Assert.That(mesh.vertexAttributeCount, Is.EqualTo(4));
            Assert.That(mesh.GetVertexAttribute(0).attribute, Is.EqualTo(VertexAttribute.Position));
            Assert.That(mesh.GetVertexAttributeOffset(VertexAttribute.Position), Is.EqualTo(0));
            Assert.That(mesh.GetVertexAttributeOffset(VertexAttribute.Normal), Is.EqualTo(12));
            Assert.That(mesh.GetVertexAttributeOffset(VertexAttribute.Tangent), Is.EqualTo(24));
            Assert.That(mesh.GetVertexAttributeOffset(VertexAttribute.TexCoord0), Is.EqualTo(40));
            Assert.That(mesh.GetVertexAttributeOffset(VertexAttribute.Color), Is.EqualTo(-1));
            Assert.That(mesh.GetVertexAttributeStream(VertexAttribute.Color), Is.EqualTo(-1));
            Assert.That(mesh.GetVertexBufferStride(0), Is.EqualTo(48));
            Assert.That(mesh.vertexBufferCount, Is.EqualTo(1));
        }

        [Test]
        public void StreamsHaveTheirOwnStride()
        {
            // The GetVertexBufferStride documentation example: position + normal in stream 0, colour in stream 1.
            var mesh = new Mesh();
            mesh.SetVertexBufferParams(10,
                new VertexAttributeDescriptor(VertexAttribute.Position, VertexAttributeFormat.Float32, 3, 0),
                new VertexAttributeDescriptor(VertexAttribute.Normal, VertexAttributeFormat.Float32, 3, 0),
                new VertexAttributeDescriptor(VertexAttribute.Color, VertexAttributeFormat.UNorm8, 4, 1));
            Assert.That(mesh.vertexBufferCount, Is.EqualTo(2));
            Assert.That(mesh.GetVertexBufferStride(0), Is.EqualTo(24));
            Assert.That(mesh.GetVertexBufferStride(1), Is.EqualTo(4));
            Assert.That(mesh.GetVertexAttributeOffset(VertexAttribute.Color), Is.EqualTo(0));
            Assert.That(mesh.GetVertexAttributeStream(VertexAttribute.Color), Is.EqualTo(1));
        }

        [TestCase(VertexAttributeFormat.Float32, 0)]
        [TestCase(VertexAttributeFormat.Float32, 5)]
        [TestCase(VertexAttributeFormat.UNorm8, 3)]
        [TestCase(VertexAttributeFormat.Float16, 3)]
        public void InvalidAttributeSizeIsRejected(VertexAttributeFormat format, int dimension)
        {
            var mesh = new Mesh();
            Assert.That(() => mesh.SetVertexBufferParams(3, new VertexAttributeDescriptor(VertexAttribute.Position, format, dimension)),
                Throws.ArgumentException);
        }

        [Test]
        public void UploadedVerticesReadBack()
        {
            var mesh = UploadedMesh();
            var expected = Quad();
            var vertices = mesh.vertices;
            var normals = mesh.normals;
            Assert.That(vertices.Length, Is.EqualTo(expected.Length));
            for (int i = 0; i < expected.Length; i++)
            {
                AssertVector(vertices[i], expected[i].Position);
                AssertVector(normals[i], expected[i].Normal);
            }
            var raw = MemoryMarshal.Cast<byte, float>(mesh.VertexStreamBytes(0));
            Assert.That(raw[10], Is.EqualTo(expected[0].U), "u of vertex 0 sits at byte 40");
            Assert.That(raw[12 + 11], Is.EqualTo(expected[1].V), "v of vertex 1 sits at byte 48 + 44");
        }

        [Test]
        public void Float16PositionsAreDecoded()
        {
            var mesh = new Mesh();
            mesh.SetVertexBufferParams(1, new VertexAttributeDescriptor(VertexAttribute.Position, VertexAttributeFormat.Float16, 4));
            // 1.5, -2, 0.25, 1 as IEEE 754 binary16.
            mesh.SetVertexBufferData(new ushort[] { 0x3E00, 0xC000, 0x3400, 0x3C00 }, 0, 0, 4);
            AssertVector(mesh.vertices[0], new Vector3(1.5f, -2f, 0.25f));
        }

        [Test]
        public void PartialUploadLandsAtMeshBufferStart()
        {
            var mesh = UploadedMesh();
            var replacement = new[] { new Vertex(9f, 8f, 7f) };
            mesh.SetVertexBufferData(replacement, 0, 5, 1);
            AssertVector(mesh.vertices[5], new Vector3(9f, 8f, 7f));
            AssertVector(mesh.vertices[4], Quad()[4].Position);
        }

        [TestCase(-1, 0, 1)]
        [TestCase(0, -1, 1)]
        [TestCase(0, 0, -1)]
        [TestCase(5, 0, 3)]
        public void BadStartOrCountThrowsArgumentOutOfRange(int dataStart, int meshBufferStart, int count)
        {
            var mesh = UploadedMesh();
            Assert.That(() => mesh.SetVertexBufferData(Quad(), dataStart, meshBufferStart, count),
                Throws.InstanceOf<ArgumentOutOfRangeException>());
            Assert.That(() => mesh.SetIndexBufferData(new[] { 0, 1, 2 }, dataStart, meshBufferStart, count),
                Throws.InstanceOf<ArgumentOutOfRangeException>());
        }

        [Test]
        public void UploadPastTheVertexBufferLogsAnErrorAndIsIgnored()
        {
            var mesh = UploadedMesh();
            LogAssert.Expect(LogType.Error, new Regex("^SetVertexData\\(\\) with out-of-bounds arguments"));
            mesh.SetVertexBufferData(Quad(), 0, 1, 7);
            AssertVector(mesh.vertices[1], Quad()[1].Position);
        }

        [Test]
        public void IndicesAreValidatedUnlessDontValidateIndices()
        {
            var mesh = UploadedMesh();
            Assert.That(() => mesh.SetIndexBufferData(new[] { 0, 1, 7 }, 0, 0, 3), Throws.ArgumentException);
            Assert.That(mesh.GetIndices(0), Is.EqualTo(new[] { 0, 2, 1, 0, 3, 2 }), "a rejected upload changes nothing");
            mesh.SetIndexBufferData(new[] { 0, 1, 7 }, 0, 0, 3, MeshUpdateFlags.DontValidateIndices);
            Assert.That(mesh.GetIndices(0), Is.EqualTo(new[] { 0, 1, 7, 0, 3, 2 }));
        }

        [Test]
        public void SubMeshesReadBackTheirIndices()
        {
            var mesh = UploadedMesh();
            Assert.That(mesh.subMeshCount, Is.EqualTo(2));
            Assert.That(mesh.indexFormat, Is.EqualTo(IndexFormat.UInt32));
            Assert.That(mesh.GetTriangles(0), Is.EqualTo(new[] { 0, 2, 1, 0, 3, 2 }));
            Assert.That(mesh.GetTriangles(1), Is.EqualTo(new[] { 4, 6, 5 }));
            Assert.That(mesh.triangles, Is.EqualTo(new[] { 0, 2, 1, 0, 3, 2, 4, 6, 5 }));
            Assert.That(mesh.GetIndexStart(1), Is.EqualTo(6u));
            Assert.That(mesh.GetIndexCount(1), Is.EqualTo(3u));
            Assert.That(() => mesh.GetSubMesh(2), Throws.InstanceOf<IndexOutOfRangeException>());
            Assert.That(() => mesh.SetSubMesh(2, new SubMeshDescriptor(0, 3)), Throws.InstanceOf<IndexOutOfRangeException>());
        }

        [Test]
        public void TrianglesOfAMissingSubMeshLogAnErrorAndAreEmpty()
        {
            var mesh = UploadedMesh();
            LogAssert.Expect(LogType.Error, "Failed getting triangles. Submesh index is out of bounds.");
            Assert.That(mesh.GetTriangles(2), Is.Empty);
        }

        [Test]
        public void SetSubMeshComputesTheVertexRangeAndBounds()
        {
            var mesh = UploadedMesh();
            var second = mesh.GetSubMesh(1);
            Assert.That(second.firstVertex, Is.EqualTo(4));
            Assert.That(second.vertexCount, Is.EqualTo(3));
            AssertVector(second.bounds.min, new Vector3(5f, 5f, 5f));
            AssertVector(second.bounds.max, new Vector3(6f, 5f, 6f));
            Assert.That(mesh.bounds, Is.EqualTo(new Bounds()), "SetSubMesh leaves the Mesh bounds alone");
        }

        [Test]
        public void DontRecalculateBoundsKeepsTheDescriptorAsGiven()
        {
            var mesh = UploadedMesh(MeshUpdateFlags.DontRecalculateBounds);
            var given = new SubMeshDescriptor(6, 3) { bounds = new Bounds(Vector3.one, Vector3.one), firstVertex = 1, vertexCount = 2 };
            mesh.SetSubMesh(1, given, MeshUpdateFlags.DontRecalculateBounds);
            var stored = mesh.GetSubMesh(1);
            Assert.That(stored.firstVertex, Is.EqualTo(1));
            Assert.That(stored.vertexCount, Is.EqualTo(2));
            Assert.That(stored.bounds, Is.EqualTo(new Bounds(Vector3.one, Vector3.one)));
        }

        [Test]
        public void ShrinkingSubMeshCountTruncatesTheIndexBuffer()
        {
            var mesh = UploadedMesh();
            mesh.subMeshCount = 1;
            Assert.That(mesh.triangles, Is.EqualTo(new[] { 0, 2, 1, 0, 3, 2 }));
            mesh.subMeshCount = 2;
            Assert.That(mesh.GetIndexCount(1), Is.EqualTo(0u));
        }

        [Test]
        public void BoundsReadBackAsSetAndRecalculateFromVertices()
        {
            var mesh = UploadedMesh();
            var set = new Bounds(new Vector3(1f, 2f, 3f), new Vector3(4f, 5f, 6f));
            mesh.bounds = set;
            Assert.That(mesh.bounds, Is.EqualTo(set));
            mesh.RecalculateBounds();
            AssertVector(mesh.bounds.min, Vector3.zero);
            AssertVector(mesh.bounds.max, new Vector3(6f, 5f, 6f));
        }

        [Test]
        public void UpdateFlagsAndUserNotificationAreRecorded()
        {
            var mesh = UploadedMesh();
            var flags = MeshUpdateFlags.DontValidateIndices | MeshUpdateFlags.DontRecalculateBounds | MeshUpdateFlags.DontResetBoneBounds;
            mesh.bounds = new Bounds(Vector3.one, Vector3.one);
            mesh.SetVertexBufferData(Quad(), 0, 0, 7, 0, flags);
            var log = mesh.UpdateLog;
            Assert.That(log.Last.Call, Is.EqualTo("SetVertexBufferData"));
            Assert.That(log.Last.Flags, Is.EqualTo(flags));
            Assert.That(log.Last.NotifiedUsers, Is.True);
            Assert.That(log.UsersUpToDate, Is.True);
            Assert.That(log.BoundsSeenByUsers, Is.EqualTo(new Bounds(Vector3.one, Vector3.one)));

            int notifications = log.NotificationCount;
            mesh.SetVertexBufferData(Quad(), 0, 0, 7, 0, flags | MeshUpdateFlags.DontNotifyMeshUsers);
            Assert.That(log.Last.NotifiedUsers, Is.False);
            Assert.That(log.UsersUpToDate, Is.False, "DontNotifyMeshUsers leaves the renderers stale");
            Assert.That(log.NotificationCount, Is.EqualTo(notifications));
            mesh.MarkModified();
            Assert.That(log.UsersUpToDate, Is.True, "MarkModified notifies");
            Assert.That(log.LastOf("SetSubMesh").Flags, Is.EqualTo(MeshUpdateFlags.Default));
        }

        [Test]
        public void RendererBoundsFollowWhatTheMeshNotified()
        {
            var go = new GameObject("Mesh", typeof(MeshFilter), typeof(MeshRenderer));
            go.transform.position = new Vector3(10f, 0f, 0f);
            var mesh = UploadedMesh();
            go.GetComponent<MeshFilter>().sharedMesh = mesh;
            mesh.bounds = new Bounds(Vector3.zero, new Vector3(2f, 2f, 2f));
            var renderer = go.GetComponent<MeshRenderer>();
            AssertVector(renderer.bounds.center, new Vector3(10f, 0f, 0f));
            AssertVector(renderer.bounds.size, new Vector3(2f, 2f, 2f));
        }

        [Test]
        public void DestroyedMeshIsReleased()
        {
            var mesh = UploadedMesh();
            mesh.MarkDynamic();
            Assert.That(mesh.IsDynamic, Is.True);
            Object.DestroyImmediate(mesh);
            Assert.That(mesh == null, Is.True);
            Assert.That(mesh.IsReleased, Is.True);
            Assert.That(() => mesh.vertexCount, Throws.InstanceOf<MissingReferenceException>());
        }

        // ---- Renderer and materials -------------------------------------------------------------------------------

        [Test]
        public void SharedMaterialsReturnsACopy()
        {
            var go = new GameObject("Renderer", typeof(MeshFilter), typeof(MeshRenderer));
            var renderer = go.GetComponent<MeshRenderer>();
            Assert.That(renderer.enabled, Is.True);
            Assert.That(renderer.sharedMaterials, Is.Empty);
            Assert.That(renderer.sharedMaterial, Is.Null);
            var a = new Material(Shader.Find("Standard"));
            var b = new Material(Shader.Find("Standard"));
            var assigned = new[] { a, b };
            renderer.sharedMaterials = assigned;
            assigned[0] = b;
            var read = renderer.sharedMaterials;
            Assert.That(read, Is.EqualTo(new[] { a, b }), "assigning copies the array");
            read[1] = a;
            Assert.That(renderer.sharedMaterials[1], Is.SameAs(b), "reading returns a copy");
            Assert.That(renderer.sharedMaterials, Is.Not.SameAs(renderer.sharedMaterials));
            Assert.That(renderer.sharedMaterial, Is.SameAs(a));
            renderer.sharedMaterial = b;
            Assert.That(renderer.sharedMaterials, Is.EqualTo(new[] { b, b }));
            Assert.That(() => renderer.sharedMaterials = null, Throws.InstanceOf<ArgumentNullException>());
        }

        [Test]
        public void MaterialCopyConstructorCopiesEverything()
        {
            var source = new Material(Shader.Find("Standard")) { name = "Source" };
            source.SetFloat("_Cutoff", 0.25f);
            source.SetColor("_Color", Color.red);
            var texture = new Texture2D(4, 4, TextureFormat.RGBA32, false);
            source.SetTexture("_MainTex", texture);
            source.EnableKeyword("_ALPHATEST_ON");
            source.renderQueue = 2450;
            source.SetFloat("_NotInTheShader", 3f);

            var copy = new Material(source);
            Assert.That(copy.shader, Is.SameAs(source.shader));
            Assert.That(copy.GetFloat("_Cutoff"), Is.EqualTo(0.25f));
            Assert.That(copy.GetColor("_Color"), Is.EqualTo(Color.red));
            Assert.That(copy.GetTexture("_MainTex"), Is.SameAs(texture));
            Assert.That(copy.IsKeywordEnabled("_ALPHATEST_ON"), Is.True);
            Assert.That(copy.renderQueue, Is.EqualTo(2450));
            Assert.That(copy.GetFloat("_NotInTheShader"), Is.EqualTo(3f));

            copy.SetFloat("_Cutoff", 0.75f);
            copy.DisableKeyword("_ALPHATEST_ON");
            Assert.That(source.GetFloat("_Cutoff"), Is.EqualTo(0.25f), "the copy is independent");
            Assert.That(source.IsKeywordEnabled("_ALPHATEST_ON"), Is.True);
            Assert.That(() => new Material((Material)null), Throws.InstanceOf<ArgumentNullException>());
            Assert.That(() => new Material((Shader)null), Throws.InstanceOf<ArgumentNullException>());
        }

        [Test]
        public void KeywordsAreRecorded()
        {
            var material = new Material(Shader.Find("Standard"));
            Assert.That(material.shaderKeywords, Is.Empty);
            material.EnableKeyword("_NORMALMAP");
            material.EnableKeyword("_ALPHATEST_ON");
            material.EnableKeyword("_ALPHATEST_ON");
            Assert.That(material.shaderKeywords, Is.EqualTo(new[] { "_ALPHATEST_ON", "_NORMALMAP" }));
            material.DisableKeyword("_NORMALMAP");
            Assert.That(material.IsKeywordEnabled("_NORMALMAP"), Is.False);
            Assert.That(material.shaderKeywords, Is.EqualTo(new[] { "_ALPHATEST_ON" }));
        }

        [Test]
        public void RenderQueueDefaultsToTheShadersAndResetsWithTheShader()
        {
            var material = new Material(Shader.Find("Standard"));
            Assert.That(material.renderQueue, Is.EqualTo(2000), "Standard has no Queue tag: Geometry");
            material.renderQueue = 2450;
            Assert.That(material.renderQueue, Is.EqualTo(2450));
            material.renderQueue = -1;
            Assert.That(material.renderQueue, Is.EqualTo(2000), "-1 uses the shader's queue");
            material.renderQueue = 2450;
            ShaderLibrary.Install(RenderPipelinePackage.Universal);
            material.shader = Shader.Find("Universal Render Pipeline/Lit");
            Assert.That(material.renderQueue, Is.EqualTo(2000), "changing the shader resets the queue");
        }

        [Test]
        public void PropertiesComeFromEachPipelinesLitShader()
        {
            ShaderLibrary.Install(RenderPipelinePackage.Universal | RenderPipelinePackage.HighDefinition);
            var standard = new Material(Shader.Find("Standard"));
            var urp = new Material(Shader.Find("Universal Render Pipeline/Lit"));
            var hdrp = new Material(Shader.Find("HDRP/Lit"));
            Assert.That(standard.HasProperty("_Color") && standard.HasProperty("_MainTex") && standard.HasProperty("_Cutoff"), Is.True);
            Assert.That(standard.HasProperty("_BaseColor") || standard.HasProperty("_AlphaClip"), Is.False);
            Assert.That(urp.HasProperty("_BaseMap") && urp.HasProperty("_BaseColor") && urp.HasProperty("_Cutoff") && urp.HasProperty("_AlphaClip"), Is.True);
            Assert.That(urp.HasProperty("_BaseColorMap") || urp.HasProperty("_AlphaCutoffEnable"), Is.False);
            Assert.That(hdrp.HasProperty("_BaseColorMap") && hdrp.HasProperty("_BaseColor") && hdrp.HasProperty("_AlphaCutoffEnable") && hdrp.HasProperty("_AlphaCutoff"), Is.True);
            Assert.That(hdrp.HasProperty("_BaseMap") || hdrp.HasProperty("_AlphaClip"), Is.False);

            Assert.That(urp.GetFloat("_Cutoff"), Is.EqualTo(0.5f), "shader default");
            Assert.That(hdrp.GetColor("_BaseColor"), Is.EqualTo(Color.white), "shader default");

            // Material.mainTexture / color follow [MainTexture] / [MainColor], else _MainTex / _Color.
            var texture = new Texture2D(2, 2, TextureFormat.RGBA32, false);
            urp.mainTexture = texture;
            Assert.That(urp.GetTexture("_BaseMap"), Is.SameAs(texture));
            Assert.That(urp.GetTexture("_MainTex"), Is.Null);
            hdrp.color = Color.green;
            Assert.That(hdrp.GetColor("_BaseColor"), Is.EqualTo(Color.green));
            standard.mainTexture = texture;
            standard.color = Color.red;
            Assert.That(standard.GetTexture("_MainTex"), Is.SameAs(texture));
            Assert.That(standard.GetColor("_Color"), Is.EqualTo(Color.red));
        }

        [Test]
        public void WritingAPropertyTheShaderLacksIsStoredSilently()
        {
            var material = new Material(Shader.Find("Standard"));
            material.SetFloat("_AlphaClip", 1f);
            Assert.That(material.HasProperty("_AlphaClip"), Is.False);
            Assert.That(material.GetFloat("_AlphaClip"), Is.EqualTo(1f));
            LogAssert.Expect(LogType.Error, "Material '' with Shader 'Standard' doesn't have a float or range property '_Missing'");
            Assert.That(material.GetFloat("_Missing"), Is.EqualTo(0f));
        }

        [Test]
        public void ShaderFindKnowsTheBuiltInShaderAndInstalledPipelines()
        {
            Assert.That(Shader.Find("No/Such Shader"), Is.Null);
            Assert.That(Shader.Find(null), Is.Null);
            var standard = Shader.Find("Standard");
            Assert.That(standard, Is.Not.Null);
            Assert.That(standard.name, Is.EqualTo("Standard"));
            Assert.That(Shader.Find("Standard"), Is.SameAs(standard), "one shared instance per shader");
            Assert.That(Shader.Find("Universal Render Pipeline/Lit"), Is.Null, "URP is not installed");
            Assert.That(Shader.Find("HDRP/Lit"), Is.Null, "HDRP is not installed");
            ShaderLibrary.Install(RenderPipelinePackage.Universal);
            Assert.That(Shader.Find("Universal Render Pipeline/Lit"), Is.Not.Null);
            World.Reset();
            Assert.That(Shader.Find("Universal Render Pipeline/Lit"), Is.Null, "World.Reset uninstalls");
        }

        // ---- render pipeline --------------------------------------------------------------------------------------

        [Test]
        public void CurrentRenderPipelineFollowsDefaultAndQualitySettings()
        {
            Assert.That(GraphicsSettings.currentRenderPipeline, Is.Null, "Built-in by default");
            var asset = ScriptableObject.CreateInstance<TestPipelineAsset>();
            GraphicsSettings.defaultRenderPipeline = asset;
            Assert.That(GraphicsSettings.currentRenderPipeline, Is.SameAs(asset));
            var quality = ScriptableObject.CreateInstance<TestPipelineAsset>();
            QualitySettings.renderPipeline = quality;
            Assert.That(GraphicsSettings.currentRenderPipeline, Is.SameAs(quality), "the quality level's asset wins");
            QualitySettings.renderPipeline = null;
            Assert.That(GraphicsSettings.currentRenderPipeline, Is.SameAs(asset));
            World.Reset();
            Assert.That(GraphicsSettings.currentRenderPipeline, Is.Null, "World.Reset returns to Built-in");
        }

        [Test]
        public void RenderPipelineAssetDefaultsAreNull()
        {
            var asset = ScriptableObject.CreateInstance<TestPipelineAsset>();
            RenderPipelineAsset baseView = asset;
            Assert.That(baseView.defaultMaterial, Is.Null);
            Assert.That(baseView.defaultShader, Is.Null);
            asset.Shader = Shader.Find("Standard");
            asset.Material = new Material(asset.Shader);
            Assert.That(baseView.defaultShader, Is.SameAs(asset.Shader));
            Assert.That(baseView.defaultMaterial, Is.SameAs(asset.Material));
        }

        // ---- textures -----------------------------------------------------------------------------------------------

        [Test]
        public void Texture2DRecordsSizeFormatAndSampler()
        {
            var texture = new Texture2D(256, 64, TextureFormat.RGBA32, true)
            {
                wrapMode = TextureWrapMode.Clamp,
                filterMode = FilterMode.Point,
            };
            Assert.That(texture.width, Is.EqualTo(256));
            Assert.That(texture.height, Is.EqualTo(64));
            Assert.That(texture.format, Is.EqualTo(TextureFormat.RGBA32));
            Assert.That(texture.mipmapCount, Is.EqualTo(9), "256 → 1: nine levels");
            Assert.That(new Texture2D(256, 64, TextureFormat.RGBA32, false).mipmapCount, Is.EqualTo(1));
            Assert.That(texture.wrapMode, Is.EqualTo(TextureWrapMode.Clamp));
            Assert.That(texture.wrapModeV, Is.EqualTo(TextureWrapMode.Clamp));
            Assert.That(texture.filterMode, Is.EqualTo(FilterMode.Point));
            Assert.That(texture.isReadable, Is.True);
            Assert.That(() => new Texture2D(0, 4, TextureFormat.RGBA32, false), Throws.InstanceOf<UnityException>());
        }

        [Test]
        public void SetPixelDataChecksTheSizeOfTheMipLevel()
        {
            var texture = new Texture2D(4, 2, TextureFormat.RGBA32, true);
            Assert.That(() => texture.SetPixelData(new byte[31], 0), Throws.InstanceOf<UnityException>(), "4 × 2 × 4 = 32 bytes needed");
            Assert.That(() => texture.SetPixelData(new byte[32], 0, 1), Throws.InstanceOf<UnityException>(), "31 bytes left after the start index");
            Assert.That(() => texture.SetPixelData(new byte[32], 0, -1), Throws.InstanceOf<UnityException>());
            Assert.That(() => texture.SetPixelData(new byte[0], 0), Throws.InstanceOf<UnityException>());
            Assert.That(() => texture.SetPixelData(new byte[32], 3), Throws.ArgumentException, "levels 0 … 2");
            // The SetPixelData documentation example: one array holding mip 0 then mip 1.
            var data = new byte[32 + 8];
            for (int i = 0; i < data.Length; i++) data[i] = (byte)i;
            texture.SetPixelData(data, 0);
            texture.SetPixelData(data, 1, 32);
            texture.SetPixelData(new uint[1], 2);
            texture.Apply(false);
            Assert.That(texture.Uploaded[0], Is.EqualTo(data.AsSpan(0, 32).ToArray()));
            Assert.That(texture.Uploaded[1], Is.EqualTo(data.AsSpan(32, 8).ToArray()));
        }

        [Test]
        public void ApplyMakeNoLongerReadableDropsTheCpuCopy()
        {
            var texture = new Texture2D(2, 2, TextureFormat.RGBA32, false) { name = "Burr" };
            var pixels = new byte[16];
            pixels[5] = 200;
            texture.SetPixelData(pixels, 0);
            texture.Apply(false, true);
            Assert.That(texture.isReadable, Is.False);
            Assert.That(texture.ApplyCount, Is.EqualTo(1));
            Assert.That(texture.Uploaded[0][5], Is.EqualTo(200), "the GPU copy was uploaded");
            Assert.That(() => texture.SetPixelData(pixels, 0),
                Throws.InstanceOf<UnityException>().With.Message.EqualTo(
                    "Texture 'Burr' is not readable, the texture memory can not be accessed from scripts. You can make the texture readable in the Texture Import Settings."));
            Assert.That(() => texture.Apply(), Throws.InstanceOf<UnityException>());
        }

        // ---- value types, gizmos, primitives ------------------------------------------------------------------------

        [Test]
        public void ColorMatchesUnity()
        {
            Assert.That(Color.yellow, Is.EqualTo(new Color(1f, 235f / 255f, 4f / 255f, 1f)));
            Assert.That(new Color(0.1f, 0.2f, 0.3f).a, Is.EqualTo(1f));
            Assert.That(Color.Lerp(Color.black, Color.white, 2f), Is.EqualTo(Color.white), "t is clamped");
            Assert.That(Color.Lerp(Color.red, Color.blue, 0.25f), Is.EqualTo(new Color(0.75f, 0f, 0.25f, 1f)));
            Assert.That(Color.red == new Color(1f, 0f, 0f, 1f + 1e-6f), Is.True, "== tolerates 1e-5 in length");
            Assert.That(Color.red == new Color(1f, 0f, 0f, 0.99f), Is.False);
            Assert.That(Color.cyan.ToString(), Is.EqualTo("RGBA(0.000, 1.000, 1.000, 1.000)"));
        }

        [Test]
        public void BoundsMatchUnity()
        {
            var bounds = new Bounds(new Vector3(1f, 2f, 3f), new Vector3(2f, 4f, 6f));
            AssertVector(bounds.extents, new Vector3(1f, 2f, 3f));
            AssertVector(bounds.min, new Vector3(0f, 0f, 0f));
            AssertVector(bounds.max, new Vector3(2f, 4f, 6f));
            bounds.SetMinMax(new Vector3(-1f, -1f, -1f), new Vector3(3f, 1f, 1f));
            AssertVector(bounds.center, new Vector3(1f, 0f, 0f));
            AssertVector(bounds.size, new Vector3(4f, 2f, 2f));
            bounds.Encapsulate(new Vector3(0f, 5f, 0f));
            AssertVector(bounds.max, new Vector3(3f, 5f, 1f));
            Assert.That(bounds.Contains(new Vector3(3f, 5f, 1f)), Is.True, "faces are inside");
            Assert.That(bounds.Contains(new Vector3(3.01f, 0f, 0f)), Is.False);
        }

        [Test]
        public void GizmoCallsAreRecordedWithTheCurrentColour()
        {
            Assert.That(Gizmos.color, Is.EqualTo(Color.white));
            Gizmos.color = Color.cyan;
            Gizmos.DrawLine(Vector3.zero, Vector3.up);
            Gizmos.color = Color.yellow;
            Gizmos.DrawWireSphere(Vector3.one, 0.25f);
            var commands = GizmoLog.Commands;
            Assert.That(commands.Count, Is.EqualTo(2));
            Assert.That(commands[0].Shape, Is.EqualTo(GizmoShape.Line));
            Assert.That(commands[0].Color, Is.EqualTo(Color.cyan));
            AssertVector(commands[0].To, Vector3.up);
            Assert.That(commands[1].Shape, Is.EqualTo(GizmoShape.WireSphere));
            Assert.That(commands[1].Radius, Is.EqualTo(0.25f));
            World.Reset();
            Assert.That(GizmoLog.Commands, Is.Empty);
            Assert.That(Gizmos.color, Is.EqualTo(Color.white));
        }

        [TestCase(PrimitiveType.Cube, 1f, 1f, 1f)]
        [TestCase(PrimitiveType.Sphere, 1f, 1f, 1f)]
        [TestCase(PrimitiveType.Capsule, 1f, 2f, 1f)]
        [TestCase(PrimitiveType.Cylinder, 1f, 2f, 1f)]
        [TestCase(PrimitiveType.Plane, 10f, 0f, 10f)]
        [TestCase(PrimitiveType.Quad, 1f, 1f, 0f)]
        public void PrimitiveMeshesHaveUnitysDimensionsAndFaceOutward(PrimitiveType type, float x, float y, float z)
        {
            var mesh = PrimitiveMeshes.Get(type);
            Assert.That(mesh.name, Is.EqualTo(type.ToString()));
            Assert.That(PrimitiveMeshes.Get(type), Is.SameAs(mesh), "shared");
            Assert.That(PrimitiveMeshes.TypeOf(mesh), Is.EqualTo(type));
            AssertVector(mesh.bounds.center, Vector3.zero, 1e-5f);
            AssertVector(mesh.bounds.size, new Vector3(x, y, z), 1e-5f);
            var vertices = mesh.vertices;
            var normals = mesh.normals;
            var triangles = mesh.triangles;
            Assert.That(triangles.Length % 3, Is.EqualTo(0));
            for (int t = 0; t < triangles.Length; t += 3)
            {
                Vector3 a = vertices[triangles[t]], b = vertices[triangles[t + 1]], c = vertices[triangles[t + 2]];
                var face = Vector3.Cross(b - a, c - a);
                var normal = normals[triangles[t]] + normals[triangles[t + 1]] + normals[triangles[t + 2]];
                Assert.That(Vector3.Dot(face, normal), Is.GreaterThan(0f), "triangle " + t / 3 + " winds clockwise seen from outside");
            }
        }

        [TestCase(PrimitiveType.Cube, 24, 12)]
        [TestCase(PrimitiveType.Plane, 121, 200)]
        [TestCase(PrimitiveType.Quad, 4, 2)]
        public void FlatPrimitivesHaveOneVertexPerFaceCorner(PrimitiveType type, int vertices, int triangles)
        {
            var mesh = PrimitiveMeshes.Get(type);
            Assert.That(mesh.vertexCount, Is.EqualTo(vertices));
            Assert.That(mesh.triangles.Length / 3, Is.EqualTo(triangles));
        }

        [Test]
        public void DefaultMaterialIsASharedStandardMaterial()
        {
            var material = BuiltinMaterials.Default;
            Assert.That(material.name, Is.EqualTo("Default-Material"));
            Assert.That(material.shader.name, Is.EqualTo("Standard"));
            Assert.That(BuiltinMaterials.Default, Is.SameAs(material));
        }
    }
}
