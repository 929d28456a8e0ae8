namespace UnityEngine.Rendering
{
    /// <summary>Stand-in of UnityEngine.Rendering.RenderPipeline: the abstract pipeline a RenderPipelineAsset creates (never run by the stand-in).</summary>
    public abstract class RenderPipeline
    {
        /// <summary>Entry point method that defines custom rendering for this RenderPipeline.</summary>
        protected abstract void Render(ScriptableRenderContext context, Camera[] cameras);
    }
}
