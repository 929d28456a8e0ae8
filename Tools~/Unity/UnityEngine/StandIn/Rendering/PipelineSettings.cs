using UnityEngine.Rendering;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the render pipeline assets of GraphicsSettings.defaultRenderPipeline and
    /// QualitySettings.renderPipeline (null: Built-in render pipeline). World.Reset clears both.
    /// </summary>
    internal static class PipelineSettings
    {
        static PipelineSettings() => World.WorldReset += Reset;

        /// <summary>GraphicsSettings.defaultRenderPipeline.</summary>
        internal static RenderPipelineAsset Default { get; set; }

        /// <summary>QualitySettings.renderPipeline (the active quality level's override).</summary>
        internal static RenderPipelineAsset QualityOverride { get; set; }

        /// <summary>GraphicsSettings.currentRenderPipeline: the quality level's asset if set, else the default one.</summary>
        internal static RenderPipelineAsset Current => QualityOverride != null ? QualityOverride : Default;

        static void Reset()
        {
            Default = null;
            QualityOverride = null;
        }
    }
}
