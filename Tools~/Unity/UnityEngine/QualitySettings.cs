using HookeRope.StandIn;
using UnityEngine.Rendering;

namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.QualitySettings: only the current quality level's render pipeline override.</summary>
    public sealed class QualitySettings : Object
    {
        QualitySettings() { }

        /// <summary>The RenderPipelineAsset that overrides the default render pipeline for the current quality level (null: none).</summary>
        public static RenderPipelineAsset renderPipeline
        {
            get => PipelineSettings.QualityOverride;
            set => PipelineSettings.QualityOverride = value;
        }
    }
}
