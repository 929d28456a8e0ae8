using HookeRope.StandIn;

namespace UnityEngine.Rendering
{
    /// <summary>Stand-in of UnityEngine.Rendering.GraphicsSettings: the render pipeline settings the package reads.</summary>
    public sealed class GraphicsSettings : Object
    {
        GraphicsSettings() { }

        /// <summary>The RenderPipelineAsset that defines the active render pipeline: QualitySettings.renderPipeline if set, else defaultRenderPipeline (null: Built-in).</summary>
        public static RenderPipelineAsset currentRenderPipeline => PipelineSettings.Current;

        /// <summary>The RenderPipelineAsset that defines the default render pipeline (null: Built-in).</summary>
        public static RenderPipelineAsset defaultRenderPipeline
        {
            get => PipelineSettings.Default;
            set => PipelineSettings.Default = value;
        }
    }
}
