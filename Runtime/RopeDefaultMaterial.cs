using HookeRope.Fracture;
using UnityEngine;
using UnityEngine.Rendering;

namespace HookeRope
{
    /// <summary>
    /// The materials a rope gets when its renderer has none. The tube material comes from the active render pipeline
    /// (<see cref="RopeMaterialSource"/>: the SRP's default material or Lit shader, or Built-in "Standard", else
    /// "Legacy Shaders/Diffuse"), in its shader's default opaque state, so the rope never renders magenta while a
    /// shader is available. The burr strands at a broken end are real geometry (three triangles per strand, see
    /// <see cref="HookeRope.Geometry.TubeVertex"/> and the core mesh builder), so they need no alpha test: their
    /// material is a copy of the tube material with the burr texture as colour map (<see cref="CreateBurr"/>), drawn
    /// with the tube's shader, keywords and render queue. Nothing here depends on a shader_feature keyword that a
    /// player build may strip. Textures and colours are written by property name for every pipeline's lit shader
    /// (<see cref="SetBaseMap"/>, <see cref="SetBaseColor"/>), not through <see cref="Material.mainTexture"/>,
    /// which only reaches a property named _MainTex or tagged [MainTexture]. In a player, Shader.Find only finds
    /// shaders that the build includes; material assets assigned to the renderer are always safe.
    /// </summary>
    public static class RopeDefaultMaterial
    {
        /// <summary>Colour-map properties: URP Lit (_BaseMap), HDRP Lit (_BaseColorMap), Built-in Standard and legacy shaders (_MainTex).</summary>
        static readonly string[] s_BaseMapProperties = { "_BaseMap", "_BaseColorMap", "_MainTex" };

        /// <summary>Colour properties: URP and HDRP Lit (_BaseColor), Built-in Standard and legacy shaders (_Color).</summary>
        static readonly string[] s_BaseColorProperties = { "_BaseColor", "_Color" };

        /// <summary>
        /// Creates the burr-strand material (caller owns and destroys it; DontSave): a copy of
        /// <paramref name="tubeMaterial"/> (same shader, keywords and render queue, so it draws wherever the tube
        /// draws) with <paramref name="burrTexture"/> (may be null) in its colour-map properties. No keyword and no
        /// alpha-clip property is touched: the strands are opaque triangles. If the tube material itself clips alpha
        /// (a user's asset), the copy clips the burr texture's alpha too, with a variant the build keeps for that asset.
        /// Null when <paramref name="tubeMaterial"/> is null.
        /// </summary>
        public static Material CreateBurr(Material tubeMaterial, Texture burrTexture)
        {
            if (tubeMaterial == null) return null;
            var material = new Material(tubeMaterial)
            {
                name = "Elastic Rope Burr (generated)",
                hideFlags = HideFlags.DontSave,
            };
            if (burrTexture != null) SetBaseMap(material, burrTexture);
            return material;
        }

        /// <summary>
        /// Creates the tube material for the active render pipeline (caller owns and destroys it; DontSave) with
        /// <paramref name="texture"/> (may be null) as its colour map, or null when no suitable shader is available
        /// (then <see cref="MissingShaderAdvice"/> says why and what to do).
        /// </summary>
        public static Material Create(Texture texture) => Create(texture, GraphicsSettings.currentRenderPipeline, Shader.Find);

        /// <summary>
        /// <see cref="Create(Texture)"/> for <paramref name="pipeline"/> (null: Built-in) with shaders looked up by
        /// <paramref name="findShader"/>: the seam through which tests play player builds without a shader.
        /// </summary>
        internal static Material Create(Texture texture, RenderPipelineAsset pipeline, System.Func<string, Shader> findShader)
        {
            var material = RopeMaterialSource.Create(pipeline, findShader);
            if (material == null) return null;
            material.name = "Elastic Rope (generated)";
            material.hideFlags = HideFlags.DontSave;
            if (texture != null) SetBaseMap(material, texture);
            return material;
        }

        /// <summary>
        /// Why no rope material could be generated for <paramref name="pipeline"/> (null: Built-in) and how to fix it:
        /// the shaders tried and the two remedies (assign material assets, or add a shader to Always Included Shaders).
        /// </summary>
        public static string MissingShaderAdvice(RenderPipelineAsset pipeline) =>
            "no shader for the generated rope material (" + (pipeline == null ? "Built-in pipeline" : "render pipeline '" + pipeline.name + "'") +
            ": no default material or shader, and none of " + RopeMaterialSource.ShadersTried(pipeline) +
            " is in this build), so the rope draws without materials. Fix: assign material assets to the MeshRenderer " +
            "(Element 0 tube, Element 1 burr strands; the build then keeps their shaders), or add one of those shaders " +
            "to Project Settings > Graphics > Always Included Shaders.";

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

        /// <summary>
        /// The package's burr texture (256 × 64 RGBA32, 16 strands, polyamide beige) with its full mip chain (9 levels), all
        /// from the core generator (each level the 2 × 2 box average of the one above): at 1 m in a headset a fibre covers a
        /// few pixels, and without mipmaps the sampler would skip over the triangles and shimmer. HideAndDontSave (never
        /// saved, not listed in the hierarchy), the caller destroys it.
        /// </summary>
        internal static Texture2D CreateBurrTexture()
        {
            const int width = 256, height = 64;
            var pixels = new byte[BurrTextureGenerator.MipChainByteCount(width, height)];
            BurrTextureGenerator.GenerateMipChain(width, height, 16, 1u, 214, 200, 160, pixels);
            var texture = new Texture2D(width, height, TextureFormat.RGBA32, mipChain: true)
            {
                name = "Elastic Rope Burr (generated)",
                hideFlags = HideFlags.HideAndDontSave,
                wrapMode = TextureWrapMode.Repeat,
                filterMode = FilterMode.Trilinear,
            };
            int levels = BurrTextureGenerator.MipCount(width, height);
            for (int level = 0; level < levels; level++)
                texture.SetPixelData(pixels, level, BurrTextureGenerator.MipOffset(width, height, level));
            texture.Apply(updateMipmaps: false, makeNoLongerReadable: true);
            return texture;
        }
    }
}
