using P = HookeRope.StandIn.ShaderPropertyInfo;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: URP's "Universal Render Pipeline/Lit" — the Properties block of
    /// com.unity.render-pipelines.universal/Shaders/Lit.shader (Unity-Technologies/Graphics) as of URP 14 (Unity
    /// 2022.3): Unity 6's _AddPrecomputedVelocity and the hidden lightmap texture arrays are left out. _BaseMap is
    /// [MainTexture], _BaseColor [MainColor]; the obsolete _MainTex / _Color / _Glossiness… stay declared (hidden).
    /// No Queue tag: render queue 2000. Found only when the URP package is installed (ShaderLibrary).
    /// </summary>
    internal static class UniversalLitShaderTable
    {
        /// <summary>The shader.</summary>
        internal static readonly ShaderDefinition Definition = new ShaderDefinition("Universal Render Pipeline/Lit", 2000, RenderPipelinePackage.Universal,
            P.Float("_WorkflowMode", 1f),
            P.Texture("_BaseMap").MainTexture(),
            P.Color("_BaseColor", 1f, 1f, 1f, 1f).MainColor(),
            P.Range("_Cutoff", 0.5f),
            P.Range("_Smoothness", 0.5f),
            P.Float("_SmoothnessTextureChannel", 0f),
            P.Range("_Metallic", 0f),
            P.Texture("_MetallicGlossMap"),
            P.Color("_SpecColor", 0.2f, 0.2f, 0.2f),
            P.Texture("_SpecGlossMap"),
            P.Float("_SpecularHighlights", 1f),
            P.Float("_EnvironmentReflections", 1f),
            P.Float("_BumpScale", 1f),
            P.Texture("_BumpMap"),
            P.Range("_Parallax", 0.005f),
            P.Texture("_ParallaxMap"),
            P.Range("_OcclusionStrength", 1f),
            P.Texture("_OcclusionMap"),
            P.Color("_EmissionColor", 0f, 0f, 0f),
            P.Texture("_EmissionMap"),
            P.Texture("_DetailMask"),
            P.Range("_DetailAlbedoMapScale", 1f),
            P.Texture("_DetailAlbedoMap"),
            P.Range("_DetailNormalMapScale", 1f),
            P.Texture("_DetailNormalMap"),
            P.Float("_ClearCoatMask", 0f),
            P.Float("_ClearCoatSmoothness", 0f),
            P.Float("_Surface", 0f),
            P.Float("_Blend", 0f),
            P.Float("_Cull", 2f),
            P.Float("_AlphaClip", 0f),
            P.Float("_SrcBlend", 1f),
            P.Float("_DstBlend", 0f),
            P.Float("_SrcBlendAlpha", 1f),
            P.Float("_DstBlendAlpha", 0f),
            P.Float("_ZWrite", 1f),
            P.Float("_BlendModePreserveSpecular", 1f),
            P.Float("_AlphaToMask", 0f),
            P.Float("_ReceiveShadows", 1f),
            P.Float("_QueueOffset", 0f),
            P.Texture("_MainTex"),
            P.Color("_Color", 1f, 1f, 1f, 1f),
            P.Float("_GlossMapScale", 0f),
            P.Float("_Glossiness", 0f),
            P.Float("_GlossyReflections", 0f));
    }
}
