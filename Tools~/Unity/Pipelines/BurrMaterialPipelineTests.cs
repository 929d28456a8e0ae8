using System;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.Rendering;
using HookeRope.Tests.Components;

namespace HookeRope.StandIn.Pipelines
{
    /// <summary>
    /// Stand-in only (it installs the SRP packages' shaders, which the package's own tests cannot): the generated rope
    /// materials on URP's and HDRP's real Lit property tables, in the configurations a player meets. URP in the Editor
    /// (defaultMaterial = its Lit.mat, played by a fresh Lit material) and in a player (defaultMaterial null,
    /// defaultShader = Shader.Find("Universal Render Pipeline/Lit")); HDRP in a player (default material and shader
    /// both editor-only, so "HDRP/Lit" is found by name). The tube's colour lands in _BaseColor, the burr texture in
    /// _BaseMap / _BaseColorMap, the burr stays opaque: no _ALPHATEST_ON, _AlphaClip / _AlphaCutoffEnable at their
    /// shader default 0, render queue 2000.
    /// </summary>
    [TestFixture]
    public sealed class BurrMaterialPipelineTests
    {
        [SetUp] public void SetUp() => World.Reset();
        [TearDown] public void TearDown() => World.Reset();

        static TestPipelineAsset Pipeline(Material material, Shader shader) => TestPipelineAsset.Make(material, shader);

        static (Material Tube, Material Burr, Texture Texture) Generate(RenderPipelineAsset pipeline)
        {
            var texture = RopeDefaultMaterial.CreateBurrTexture();
            var tube = RopeDefaultMaterial.Create(null, pipeline, Shader.Find);
            Assert.That(tube, Is.Not.Null);
            RopeDefaultMaterial.SetBaseColor(tube, new Color(0.93f, 0.5f, 0.12f, 1f));
            return (tube, RopeDefaultMaterial.CreateBurr(tube, texture), texture);
        }

        static void AssertOpaque(Material burr, Material tube)
        {
            Assert.That(burr.shader, Is.SameAs(tube.shader));
            Assert.That(burr.IsKeywordEnabled("_ALPHATEST_ON"), Is.False);
            Assert.That(burr.shaderKeywords, Is.Empty);
            Assert.That(burr.renderQueue, Is.EqualTo(2000));
            Assert.That(burr.GetColor("_BaseColor").g, Is.EqualTo(0.5f).Within(1e-6f), "the rope's colour");
        }

        [Test]
        public void BurrTextureUploadsTheCoresMipChain()
        {
            // issue 17 item 3: 256 × 64 with all 9 levels, each the core's 2 × 2 box average (SetPixelData per level from
            // its offset in one array, Apply(updateMipmaps: false) so Unity's own filter does not replace them), trilinear
            var texture = RopeDefaultMaterial.CreateBurrTexture();
            var chain = new byte[HookeRope.Fracture.BurrTextureGenerator.MipChainByteCount(256, 64)];
            HookeRope.Fracture.BurrTextureGenerator.GenerateMipChain(256, 64, 16, 1u, 214, 200, 160, chain);
            Assert.That(texture.mipmapCount, Is.EqualTo(9));
            Assert.That(texture.filterMode, Is.EqualTo(FilterMode.Trilinear));
            Assert.That(texture.LastApplyUpdatedMipmaps, Is.False);
            Assert.That(texture.isReadable, Is.False);
            for (int level = 0; level < 9; level++)
            {
                int offset = HookeRope.Fracture.BurrTextureGenerator.MipOffset(256, 64, level);
                int bytes = Math.Max(1, 256 >> level) * Math.Max(1, 64 >> level) * 4;
                Assert.That(texture.Uploaded[level].Length, Is.EqualTo(bytes), "level " + level);
                Assert.That(texture.Uploaded[level].AsSpan().SequenceEqual(chain.AsSpan(offset, bytes)), Is.True, "level " + level);
            }
            UnityEngine.Object.DestroyImmediate(texture);
        }

        [TestCase(true)]
        [TestCase(false)]
        public void UniversalEditorAndPlayerGiveOpaqueLit(bool editor)
        {
            ShaderLibrary.Install(RenderPipelinePackage.Universal);
            var lit = Shader.Find("Universal Render Pipeline/Lit");
            var pipeline = editor ? Pipeline(new Material(lit) { name = "Lit" }, lit) : Pipeline(null, lit);
            var (tube, burr, texture) = Generate(pipeline);
            Assert.That(tube.shader.name, Is.EqualTo("Universal Render Pipeline/Lit"));
            AssertOpaque(burr, tube);
            Assert.That(burr.GetFloat("_AlphaClip"), Is.EqualTo(0f), "shader default: no alpha clipping");
            Assert.That(burr.GetFloat("_Surface"), Is.EqualTo(0f), "shader default: opaque surface");
            Assert.That(burr.GetTexture("_BaseMap"), Is.SameAs(texture));
            Assert.That(tube.GetTexture("_BaseMap"), Is.Null);
        }

        [Test]
        public void HighDefinitionPlayerFindsLitByNameAndStaysOpaque()
        {
            ShaderLibrary.Install(RenderPipelinePackage.HighDefinition);
            var (tube, burr, texture) = Generate(Pipeline(null, null));
            Assert.That(tube.shader.name, Is.EqualTo("HDRP/Lit"));
            AssertOpaque(burr, tube);
            Assert.That(burr.GetFloat("_AlphaCutoffEnable"), Is.EqualTo(0f), "shader default: no alpha cutoff");
            Assert.That(burr.GetFloat("_SurfaceType"), Is.EqualTo(0f), "shader default: opaque");
            Assert.That(burr.GetTexture("_BaseColorMap"), Is.SameAs(texture));
        }

        [Test]
        public void AnSrpNeverFallsBackToBuiltInShaders()
        {
            Assert.That(Shader.Find("Standard"), Is.Not.Null);
            Assert.That(RopeDefaultMaterial.Create(null, Pipeline(null, null), Shader.Find), Is.Null, "no SRP package installed");
        }
    }
}
