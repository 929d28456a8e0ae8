using UnityEngine;
using UnityEngine.Rendering;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// A render-pipeline asset for material tests: it reports the default material and shader it was made with
    /// (null: none, as URP and HDRP report in a player) and creates no pipeline. The caller destroys it.
    /// </summary>
    sealed class TestPipelineAsset : RenderPipelineAsset
    {
        Material _defaultMaterial;
        Shader _defaultShader;

        /// <summary>The material the pipeline reports (URP and HDRP: their Lit material, in the Editor only).</summary>
        public override Material defaultMaterial => _defaultMaterial;

        /// <summary>The shader the pipeline reports.</summary>
        public override Shader defaultShader => _defaultShader;

        /// <summary>A new asset called "Test SRP" reporting <paramref name="material"/> and <paramref name="shader"/>.</summary>
        public static TestPipelineAsset Make(Material material, Shader shader)
        {
            var asset = CreateInstance<TestPipelineAsset>();
            asset.name = "Test SRP";
            asset._defaultMaterial = material;
            asset._defaultShader = shader;
            return asset;
        }

        /// <summary>No pipeline: nothing renders through this asset.</summary>
        protected override RenderPipeline CreatePipeline() => null;
    }
}
