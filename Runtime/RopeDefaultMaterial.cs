using HookeRope.Fracture;
using UnityEngine;
using UnityEngine.Rendering;

namespace HookeRope
{
    /// <summary>
    /// The material a rope gets when its renderer has none, built for the active render pipeline so the rope never
    /// renders magenta:
    /// <list type="number">
    /// <item>a Scriptable Render Pipeline (URP, HDRP, custom) is active
    /// (<see cref="GraphicsSettings.currentRenderPipeline"/> not null): a copy of its
    /// <see cref="RenderPipelineAsset.defaultMaterial"/> (URP and HDRP return it in the Editor only), else a new
    /// material on its <see cref="RenderPipelineAsset.defaultShader"/>, else on "Universal Render Pipeline/Lit" or
    /// "HDRP/Lit" found by name. Never the Built-in Standard shader, which an SRP draws magenta;</item>
    /// <item>the Built-in pipeline (no pipeline asset): a material on the "Standard" shader.</item>
    /// </list>
    /// Textures and colours are written by property name for every pipeline's lit shader (<see cref="SetBaseMap"/>,
    /// <see cref="SetBaseColor"/>), not through <see cref="Material.mainTexture"/>, which only reaches a property
    /// named _MainTex or tagged [MainTexture]. In a player, <see cref="Shader.Find"/> only finds shaders that the
    /// build includes; assign your own materials to be safe.
    /// </summary>
    public static class RopeDefaultMaterial
    {
        /// <summary>Render queue of alpha-tested geometry (Unity's AlphaTest queue).</summary>
        const int AlphaTestQueue = 2450;

        /// <summary>Lit shaders of the Unity pipelines, tried by name when an SRP exposes neither a default material nor a default shader.</summary>
        static readonly string[] s_PipelineLitShaders = { "Universal Render Pipeline/Lit", "HDRP/Lit" };

        /// <summary>Colour-map properties: URP Lit (_BaseMap), HDRP Lit (_BaseColorMap), Built-in Standard and legacy shaders (_MainTex).</summary>
        static readonly string[] s_BaseMapProperties = { "_BaseMap", "_BaseColorMap", "_MainTex" };

        /// <summary>Colour properties: URP and HDRP Lit (_BaseColor), Built-in Standard (_Color).</summary>
        static readonly string[] s_BaseColorProperties = { "_BaseColor", "_Color" };

        /// <summary>
        /// Creates the burr-strand material: <see cref="Create"/> with <paramref name="burrTexture"/> and alpha
        /// clipping turned on the way each pipeline's lit shader expects it (keyword _ALPHATEST_ON; _Cutoff for
        /// Built-in Standard and URP Lit, plus _AlphaClip for URP Lit; _AlphaCutoffEnable and _AlphaCutoff for HDRP
        /// Lit; properties a shader lacks are skipped), so only the texture's strands are drawn. HDRP validates
        /// material keywords and passes only in its material inspector or through its own HDMaterial API, so a
        /// generated HDRP burr material may draw unclipped: assign an alpha-clipped material there. Null when no
        /// shader is available.
        /// </summary>
        public static Material CreateBurr(Texture burrTexture)
        {
            var material = Create(burrTexture);
            if (material == null) return null;
            material.name = "Elastic Rope Burr (generated)";
            material.EnableKeyword("_ALPHATEST_ON");
            SetFloatIfPresent(material, "_Cutoff", 0.5f);
            SetFloatIfPresent(material, "_AlphaClip", 1f);
            SetFloatIfPresent(material, "_AlphaCutoffEnable", 1f);
            SetFloatIfPresent(material, "_AlphaCutoff", 0.5f);
            material.renderQueue = AlphaTestQueue;
            return material;
        }

        /// <summary>
        /// Creates the material (caller owns and destroys it) with <paramref name="texture"/> (may be null) as its
        /// colour map, or null when no suitable shader is available.
        /// </summary>
        public static Material Create(Texture texture)
        {
            var material = CreateForActivePipeline();
            if (material == null) return null;
            material.name = "Elastic Rope (generated)";
            material.hideFlags = HideFlags.DontSave;
            if (texture != null) SetBaseMap(material, texture);
            return material;
        }

        /// <summary>Writes <paramref name="texture"/> into every colour-map property the material's shader has (_BaseMap, _BaseColorMap, _MainTex).</summary>
        public static void SetBaseMap(Material material, Texture texture)
        {
            if (material == null) return;
            for (int i = 0; i < s_BaseMapProperties.Length; i++)
                if (material.HasProperty(s_BaseMapProperties[i])) material.SetTexture(s_BaseMapProperties[i], texture);
        }

        /// <summary>Writes <paramref name="color"/> into every base-colour property the material's shader has (_BaseColor, _Color).</summary>
        public static void SetBaseColor(Material material, Color color)
        {
            if (material == null) return;
            for (int i = 0; i < s_BaseColorProperties.Length; i++)
                if (material.HasProperty(s_BaseColorProperties[i])) material.SetColor(s_BaseColorProperties[i], color);
        }

        /// <summary>The package's burr texture (256 × 64 RGBA32, 16 strands, polyamide beige), from the core generator; HideAndDontSave (never saved, not listed in the hierarchy), the caller destroys it.</summary>
        internal static Texture2D CreateBurrTexture()
        {
            const int width = 256, height = 64;
            var pixels = new byte[BurrTextureGenerator.ByteCount(width, height)];
            BurrTextureGenerator.Generate(width, height, 16, 1u, 214, 200, 160, pixels);
            var texture = new Texture2D(width, height, TextureFormat.RGBA32, mipChain: false)
            {
                name = "Elastic Rope Burr (generated)",
                hideFlags = HideFlags.HideAndDontSave,
                wrapMode = TextureWrapMode.Repeat,
                filterMode = FilterMode.Bilinear,
            };
            texture.SetPixelData(pixels, 0);
            texture.Apply(updateMipmaps: false, makeNoLongerReadable: true);
            return texture;
        }

        static Material CreateForActivePipeline()
        {
            var pipeline = GraphicsSettings.currentRenderPipeline;
            if (pipeline == null)
            {
                var standard = Shader.Find("Standard");
                return standard != null ? new Material(standard) : null;
            }
            var source = pipeline.defaultMaterial;
            if (source != null) return new Material(source);
            var shader = pipeline.defaultShader;
            for (int i = 0; shader == null && i < s_PipelineLitShaders.Length; i++) shader = Shader.Find(s_PipelineLitShaders[i]);
            return shader != null ? new Material(shader) : null;
        }

        static void SetFloatIfPresent(Material material, string property, float value)
        {
            if (material.HasProperty(property)) material.SetFloat(property, value);
        }
    }
}
