using P = HookeRope.StandIn.ShaderPropertyInfo;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the Built-in render pipeline's "Legacy Shaders/Diffuse" shader — the Properties block of
    /// DefaultResources/Normal-Diffuse.shader (Unity built-in shader source, MIT; see Tools~/Unity/STAND-IN.md): a main
    /// colour and a base texture. No Queue tag: render queue 2000 (Geometry). No [MainTexture] / [MainColor] tags.
    /// </summary>
    internal static class LegacyDiffuseShaderTable
    {
        /// <summary>The shader.</summary>
        internal static readonly ShaderDefinition Definition = new ShaderDefinition("Legacy Shaders/Diffuse", 2000, RenderPipelinePackage.None,
            P.Color("_Color", 1f, 1f, 1f, 1f),
            P.Texture("_MainTex"));
    }
}
