using System;
using System.Text.RegularExpressions;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.TestTools;
using Object = UnityEngine.Object;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in), issue 13 item 6: the generated rope materials in each
    /// render-pipeline configuration a player can meet (Built-in; Built-in player without Standard; an SRP asset with
    /// a default material, as URP and HDRP give in the Editor; an SRP player with only a default shader; an SRP player
    /// with nothing findable) have the promised state: the burr material is a copy of the tube material (same shader,
    /// render queue 2000, no keyword such as _ALPHATEST_ON), the burr texture in its colour map; an SRP never gets a
    /// Built-in shader; with no shader the renderer logs one error naming itself and the fix. Player shader inclusion
    /// is played through RopeDefaultMaterial's internal shader-lookup seam (the real Shader.Find answers as the Editor).
    /// </summary>
    [TestFixture]
    public sealed class RopeBurrMaterialTests
    {
        /// <summary>Unity's Geometry render queue: opaque objects.</summary>
        const int GeometryQueue = 2000;

        UnityRopeScene _scene;
        Texture2D _burrTexture;
        readonly System.Collections.Generic.List<Object> _created = new System.Collections.Generic.List<Object>();

        [SetUp]
        public void SetUp()
        {
            _scene = new UnityRopeScene();
            _scene.Begin();
            _burrTexture = Track(RopeDefaultMaterial.CreateBurrTexture());
        }

        [TearDown]
        public void TearDown()
        {
            _scene.End();
            for (int i = _created.Count - 1; i >= 0; i--)
                if (_created[i] != null) Object.DestroyImmediate(_created[i]);
            _created.Clear();
        }

        T Track<T>(T created) where T : Object
        {
            if (created != null) _created.Add(created);
            return created;
        }

        TestPipelineAsset Pipeline(Material material, Shader shader) => Track(TestPipelineAsset.Make(material, shader));

        /// <summary>Shader.Find as a player build that does not include the shaders named in <paramref name="excluded"/>.</summary>
        static Func<string, Shader> PlayerWithout(params string[] excluded) =>
            name => Array.IndexOf(excluded, name) >= 0 ? null : Shader.Find(name);

        /// <summary>The burr material's promised state against its tube material.</summary>
        void AssertOpaqueBurrCopyOf(Material tube, string colourMap)
        {
            var burr = Track(RopeDefaultMaterial.CreateBurr(tube, _burrTexture));
            Assert.That(burr, Is.Not.Null);
            Assert.That(burr, Is.Not.SameAs(tube), "a copy: the tube keeps its own colour map");
            Assert.That(burr.shader, Is.SameAs(tube.shader), "drawn by the tube's shader, found wherever the tube's is");
            Assert.That(burr.renderQueue, Is.EqualTo(GeometryQueue), "opaque Geometry queue, not AlphaTest 2450");
            Assert.That(burr.IsKeywordEnabled("_ALPHATEST_ON"), Is.False, "no shader_feature keyword a player could strip");
            Assert.That(burr.shaderKeywords.Length, Is.EqualTo(tube.shaderKeywords.Length), "the tube's keywords, none added");
            Assert.That(burr.GetTexture(colourMap), Is.SameAs(_burrTexture));
            Assert.That(burr.hideFlags & HideFlags.DontSave, Is.EqualTo(HideFlags.DontSave));
        }

        [Test]
        public void BuiltInEditorUsesStandardAndAnOpaqueBurrCopy()
        {
            var tube = Track(RopeDefaultMaterial.Create(null, null, Shader.Find));
            Assert.That(tube.shader.name, Is.EqualTo("Standard"));
            Assert.That(tube.renderQueue, Is.EqualTo(GeometryQueue));
            Assert.That(tube.shaderKeywords.Length, Is.EqualTo(0), "shader default state: no keyword");
            AssertOpaqueBurrCopyOf(tube, "_MainTex");
        }

        [Test]
        public void BuiltInPlayerWithoutStandardFallsBackToLegacyDiffuse()
        {
            var tube = Track(RopeDefaultMaterial.Create(null, null, PlayerWithout("Standard")));
            Assert.That(tube, Is.Not.Null, "Legacy Shaders/Diffuse is on the default Always Included Shaders list");
            Assert.That(tube.shader.name, Is.EqualTo("Legacy Shaders/Diffuse"));
            RopeDefaultMaterial.SetBaseColor(tube, new Color(0.93f, 0.5f, 0.12f, 1f));
            Assert.That(tube.GetColor("_Color").g, Is.EqualTo(0.5f).Within(1e-6f));
            AssertOpaqueBurrCopyOf(tube, "_MainTex");
        }

        [Test]
        public void PipelineDefaultMaterialIsCopiedAsTheEditorDoes()
        {
            // URP and HDRP return their Lit default material in the Editor; any lit shader plays it here.
            var source = Track(new Material(Shader.Find("Standard")) { name = "Pipeline Default" });
            var pipeline = Pipeline(source, null);
            var tube = Track(RopeDefaultMaterial.Create(null, pipeline, PlayerWithout("Standard", "Legacy Shaders/Diffuse")));
            Assert.That(tube, Is.Not.SameAs(source), "the pipeline's asset is never modified");
            Assert.That(tube.shader, Is.SameAs(source.shader));
            Assert.That(tube.name, Is.EqualTo("Elastic Rope (generated)"));
            AssertOpaqueBurrCopyOf(tube, "_MainTex");
        }

        [Test]
        public void PipelinePlayerWithOnlyADefaultShaderUsesIt()
        {
            var shader = Shader.Find("Legacy Shaders/Diffuse");
            var tube = Track(RopeDefaultMaterial.Create(null, Pipeline(null, shader), PlayerWithout()));
            Assert.That(tube.shader, Is.SameAs(shader));
            AssertOpaqueBurrCopyOf(tube, "_MainTex");
        }

        [Test]
        public void PipelinePlayerFindsTheHighDefinitionLitShaderByNameAfterUniversal()
        {
            // Only "HDRP/Lit" is in this player; a shader object that exists here plays it.
            var hdrpLit = Shader.Find("Legacy Shaders/Diffuse");
            Func<string, Shader> player = name => name == "HDRP/Lit" ? hdrpLit : null;
            var tube = Track(RopeDefaultMaterial.Create(null, Pipeline(null, null), player));
            Assert.That(tube.shader, Is.SameAs(hdrpLit));
        }

        [Test]
        public void PipelinePlayerWithoutLitShadersGetsNoMaterialAndNeverABuiltInShader()
        {
            var pipeline = Pipeline(null, null);
            var tube = RopeDefaultMaterial.Create(null, pipeline, PlayerWithout("Universal Render Pipeline/Lit", "HDRP/Lit"));
            Assert.That(tube, Is.Null, "Standard is findable, but an SRP draws it magenta");
            Assert.That(RopeDefaultMaterial.CreateBurr(null, _burrTexture), Is.Null);
            string advice = RopeDefaultMaterial.MissingShaderAdvice(pipeline);
            Assert.That(advice, Does.Contain("'Test SRP'"));
            Assert.That(advice, Does.Contain("\"Universal Render Pipeline/Lit\", \"HDRP/Lit\""));
            Assert.That(advice, Does.Contain("Element 0 tube, Element 1 burr strands"));
            Assert.That(advice, Does.Contain("Always Included Shaders"));
            Assert.That(RopeDefaultMaterial.MissingShaderAdvice(null), Does.Contain("\"Standard\", \"Legacy Shaders/Diffuse\""));
        }

        [Test]
        public void BuiltInPlayerWithNoShaderGetsNoMaterial()
        {
            Assert.That(RopeDefaultMaterial.Create(null, null, PlayerWithout("Standard", "Legacy Shaders/Diffuse")), Is.Null);
        }

        [Test]
        public void UserTubeMaterialGivesTheBurrItsShaderAndKeywords()
        {
            // A user's alpha-clipped asset: the build keeps that variant, so the copy may keep the keyword.
            var user = Track(new Material(Shader.Find("Standard")) { name = "User Rope" });
            user.EnableKeyword("_ALPHATEST_ON");
            user.renderQueue = 2450;
            var burr = Track(RopeDefaultMaterial.CreateBurr(user, _burrTexture));
            Assert.That(burr.shader, Is.SameAs(user.shader));
            Assert.That(burr.IsKeywordEnabled("_ALPHATEST_ON"), Is.True, "the user's own variant, kept by the build");
            Assert.That(burr.renderQueue, Is.EqualTo(2450));
            Assert.That(burr.GetTexture("_MainTex"), Is.SameAs(_burrTexture));
            Assert.That(user.GetTexture("_MainTex"), Is.Null, "the user's asset is untouched");
        }

        [Test]
        public void RendererWithoutAnyShaderLogsOneErrorAndDrawsTheMesh()
        {
            if (Shader.Find("Universal Render Pipeline/Lit") != null || Shader.Find("HDRP/Lit") != null)
                Assert.Ignore("an SRP package is installed: its Lit shader is found, so nothing is missing");
            var saved = GraphicsSettings.defaultRenderPipeline;
            GraphicsSettings.defaultRenderPipeline = Pipeline(null, null);
            try
            {
                var top = _scene.Point("Top", new Vector3(0f, 3f, 0f));
                var grip = _scene.Point("Grip", new Vector3(0.3f, 2f, 0f));
                var go = _scene.Track(new GameObject("Rope", typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer)));
                var rope = go.GetComponent<ElasticRope>();
                rope.StartAttachment.Point = top;
                rope.EndAttachment.Point = grip;
                rope.Rebuild();
                var renderer = go.GetComponent<RopeMeshRenderer>();
                LogAssert.Expect(LogType.Error, new Regex("^RopeMeshRenderer 'Rope': no shader for the generated rope material .*Always Included Shaders"));
                Assert.That(renderer.Render(1f), Is.True);
                Assert.That(renderer.Mesh.vertexCount, Is.GreaterThan(0), "the mesh is still built and pickable");
                var materials = go.GetComponent<MeshRenderer>().sharedMaterials;
                Assert.That(materials.Length, Is.EqualTo(2));
                Assert.That(materials[0] == null && materials[1] == null, Is.True, "no Built-in material under an SRP");
                renderer.enabled = false;
                renderer.enabled = true;
                Assert.That(renderer.Render(1f), Is.True, "re-enabled: the error is not repeated (an unexpected one fails the test)");
                LogAssert.NoUnexpectedReceived();
            }
            finally
            {
                GraphicsSettings.defaultRenderPipeline = saved;
            }
        }
    }
}
