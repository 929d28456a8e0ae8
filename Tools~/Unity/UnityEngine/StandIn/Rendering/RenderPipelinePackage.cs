using System;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: the render-pipeline packages whose shaders Shader.Find can see (the stand-in models a project with none installed unless a test installs one).</summary>
    [Flags]
    internal enum RenderPipelinePackage
    {
        /// <summary>Built-in shaders only.</summary>
        None = 0,
        /// <summary>com.unity.render-pipelines.universal: "Universal Render Pipeline/Lit".</summary>
        Universal = 1,
        /// <summary>com.unity.render-pipelines.high-definition: "HDRP/Lit".</summary>
        HighDefinition = 2,
    }
}
