namespace UnityEngine.Rendering
{
    /// <summary>Stand-in of UnityEngine.Rendering.ScriptableRenderContext: declared so RenderPipeline subclasses compile; it has no members here.</summary>
    public struct ScriptableRenderContext
    {
    }
}
