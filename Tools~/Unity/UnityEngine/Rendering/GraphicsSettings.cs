namespace UnityEngine.Rendering
{
    /// <summary>Shim of UnityEngine.Rendering.GraphicsSettings: script interface for Graphics Settings.</summary>
    public sealed class GraphicsSettings : Object
    {
        /// <summary>The RenderPipelineAsset that defines the active render pipeline for the current quality level.</summary>
        public static RenderPipelineAsset currentRenderPipeline => throw Shim.NotRun;
    }
}
