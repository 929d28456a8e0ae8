using UnityEngine;
using UnityEngine.Rendering;

namespace HookeRope
{
    /// <summary>
    /// The material a rope gets when its renderer has none: a copy of the active render pipeline's default
    /// material (URP Lit, HDRP Lit, or a custom pipeline's), or a Standard-shader material in the Built-in
    /// pipeline, so the rope never renders magenta. The texture goes into <see cref="Material.mainTexture"/>,
    /// which every pipeline maps to its main colour map (_BaseMap or _MainTex).
    /// </summary>
    public static class RopeDefaultMaterial
    {
        /// <summary>Render queue of alpha-tested geometry (Unity's AlphaTest queue).</summary>
        const int AlphaTestQueue = 2450;

        /// <summary>
        /// Creates the burr-strand material: <see cref="Create"/> with <paramref name="burrTexture"/> and alpha
        /// clipping turned on the way each pipeline's lit shader expects it (_ALPHATEST_ON with _Cutoff for
        /// Built-in Standard, _AlphaClip for URP Lit, _AlphaCutoffEnable/_AlphaCutoff for HDRP Lit; unknown
        /// properties are ignored), so only the texture's triangles are drawn. Null when no shader is available.
        /// </summary>
        public static Material CreateBurr(Texture burrTexture)
        {
            var material = Create(burrTexture);
            if (material == null) return null;
            material.name = "Elastic Rope Burr (generated)";
            material.EnableKeyword("_ALPHATEST_ON");
            material.SetFloat("_Cutoff", 0.5f);
            material.SetFloat("_AlphaClip", 1f);
            material.SetFloat("_AlphaCutoffEnable", 1f);
            material.SetFloat("_AlphaCutoff", 0.5f);
            material.renderQueue = AlphaTestQueue;
            return material;
        }

        /// <summary>Creates the material (caller owns and destroys it), or null when no suitable shader is available.</summary>
        public static Material Create(Texture texture)
        {
            var pipeline = GraphicsSettings.currentRenderPipeline;
            Material source = pipeline != null ? pipeline.defaultMaterial : null;
            Material material;
            if (source != null)
            {
                material = new Material(source);
            }
            else
            {
                var shader = Shader.Find("Standard");
                if (shader == null) return null;
                material = new Material(shader);
            }
            material.name = "Elastic Rope (generated)";
            material.hideFlags = HideFlags.DontSave;
            if (texture != null) material.mainTexture = texture;
            return material;
        }
    }
}
