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
