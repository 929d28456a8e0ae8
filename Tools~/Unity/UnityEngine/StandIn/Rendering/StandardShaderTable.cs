using P = HookeRope.StandIn.ShaderPropertyInfo;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the Built-in render pipeline's "Standard" shader — the Properties block of
    /// DefaultResourcesExtra/Standard.shader (Unity built-in shader source, MIT; read from a public mirror of the
    /// built-in shaders, see Tools~/Unity/STAND-IN.md). No Queue tag: render queue 2000 (Geometry). No [MainTexture] /
    /// [MainColor] tags: Material.mainTexture / color fall back to _MainTex / _Color.
    /// </summary>
    internal static class StandardShaderTable
    {
        /// <summary>The shader.</summary>
        internal static readonly ShaderDefinition Definition = new ShaderDefinition("Standard", 2000, RenderPipelinePackage.None,
            P.Color("_Color", 1f, 1f, 1f, 1f),
            P.Texture("_MainTex"),
            P.Range("_Cutoff", 0.5f),
            P.Range("_Glossiness", 0.5f),
            P.Range("_GlossMapScale", 1f),
            P.Float("_SmoothnessTextureChannel", 0f),
            P.Range("_Metallic", 0f),
            P.Texture("_MetallicGlossMap"),
            P.Float("_SpecularHighlights", 1f),
            P.Float("_GlossyReflections", 1f),
            P.Float("_BumpScale", 1f),
            P.Texture("_BumpMap"),
            P.Range("_Parallax", 0.02f),
            P.Texture("_ParallaxMap"),
            P.Range("_OcclusionStrength", 1f),
            P.Texture("_OcclusionMap"),
            P.Color("_EmissionColor", 0f, 0f, 0f),
            P.Texture("_EmissionMap"),
            P.Texture("_DetailMask"),
            P.Texture("_DetailAlbedoMap"),
            P.Float("_DetailNormalMapScale", 1f),
            P.Texture("_DetailNormalMap"),
            P.Float("_UVSec", 0f),
            P.Float("_Mode", 0f),
            P.Float("_SrcBlend", 1f),
            P.Float("_DstBlend", 0f),
            P.Float("_ZWrite", 1f));
    }
}
