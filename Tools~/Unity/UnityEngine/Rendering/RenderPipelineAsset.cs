namespace UnityEngine.Rendering
{
    /// <summary>
    /// Stand-in of UnityEngine.Rendering.RenderPipelineAsset: an asset that produces a specific RenderPipeline. As in
    /// Unity 2022.3 (RenderPipelineAsset.cs) the base defaultMaterial and defaultShader are null and subclasses must
    /// implement CreatePipeline; the stand-in never creates a pipeline (nothing renders).
    /// </summary>
    public abstract class RenderPipelineAsset : ScriptableObject
    {
        /// <summary>Return the default Material for this pipeline (null in the base class).</summary>
        public virtual Material defaultMaterial => null;

        /// <summary>Return the default Shader for this pipeline (null in the base class).</summary>
        public virtual Shader defaultShader => null;

        /// <summary>Create a IRenderPipeline specific to this asset.</summary>
        protected abstract RenderPipeline CreatePipeline();

        /// <summary>Default implementation of OnValidate for RenderPipelineAsset (no pipeline to rebuild in the stand-in).</summary>
        protected virtual void OnValidate() { }

        /// <summary>Default implementation of OnDisable for RenderPipelineAsset (no pipeline to clean up in the stand-in).</summary>
        protected virtual void OnDisable() { }
    }
}
