namespace UnityEngine.Rendering
{
    /// <summary>Shim of UnityEngine.Rendering.RenderPipelineAsset: an asset that produces a specific IRenderPipeline.</summary>
    public abstract class RenderPipelineAsset : ScriptableObject
    {
        /// <summary>Return the default Material for this pipeline.</summary>
        public virtual Material defaultMaterial => throw Shim.NotRun;

        /// <summary>Return the default Shader for this pipeline.</summary>
        public virtual Shader defaultShader => throw Shim.NotRun;
    }
}
