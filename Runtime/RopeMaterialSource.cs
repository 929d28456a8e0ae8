using System;
using UnityEngine;
using UnityEngine.Rendering;

namespace HookeRope
{
    /// <summary>
    /// Where a generated rope material gets its shader, for a given render pipeline and shader lookup, in order:
    /// <list type="number">
    /// <item>a Scriptable Render Pipeline (URP, HDRP, custom): a copy of its
    /// <see cref="RenderPipelineAsset.defaultMaterial"/> (URP and HDRP return one in the Editor only), else a material
    /// on its <see cref="RenderPipelineAsset.defaultShader"/> (URP finds "Universal Render Pipeline/Lit" by name, also
    /// in players), else on "Universal Render Pipeline/Lit" or "HDRP/Lit" found by name. Never a Built-in shader,
    /// which an SRP draws magenta;</item>
    /// <item>the Built-in pipeline (no pipeline asset): "Standard", else "Legacy Shaders/Diffuse" (a new project lists
    /// it under Project Settings &gt; Graphics &gt; Always Included Shaders, so a player finds it even when no scene
    /// material uses Standard).</item>
    /// </list>
    /// Every material is left in its shader's default state (opaque, no keyword enabled by this code), which needs no
    /// shader_feature variant beyond the shader's base one and no HDRP material validation. Null when nothing is
    /// found: a player only finds shaders that the build includes (Shader.Find).
    /// </summary>
    internal static class RopeMaterialSource
    {
        /// <summary>Lit shaders of the Unity SRPs, tried by name when the pipeline exposes neither a default material nor a default shader.</summary>
        static readonly string[] s_PipelineLitShaders = { "Universal Render Pipeline/Lit", "HDRP/Lit" };

        /// <summary>Built-in pipeline shaders, best first: Standard, then the always-included-by-default Legacy Diffuse.</summary>
        static readonly string[] s_BuiltInShaders = { "Standard", "Legacy Shaders/Diffuse" };

        /// <summary>
        /// A new material (caller owns it) for <paramref name="pipeline"/> (null: Built-in) with shaders looked up by
        /// <paramref name="findShader"/> (Shader.Find in the package), or null when no shader is available.
        /// </summary>
        internal static Material Create(RenderPipelineAsset pipeline, Func<string, Shader> findShader)
        {
            if (findShader == null) throw new ArgumentNullException(nameof(findShader));
            if (pipeline == null) return FromFirstFound(s_BuiltInShaders, findShader);
            var source = pipeline.defaultMaterial;
            if (source != null) return new Material(source);
            var shader = pipeline.defaultShader;
            return shader != null ? new Material(shader) : FromFirstFound(s_PipelineLitShaders, findShader);
        }

        /// <summary>The shaders tried by name for <paramref name="pipeline"/> (null: Built-in), quoted and comma-separated, for messages.</summary>
        internal static string ShadersTried(RenderPipelineAsset pipeline) =>
            "\"" + string.Join("\", \"", pipeline == null ? s_BuiltInShaders : s_PipelineLitShaders) + "\"";

        static Material FromFirstFound(string[] names, Func<string, Shader> findShader)
        {
            for (int i = 0; i < names.Length; i++)
            {
                var shader = findShader(names[i]);
                if (shader != null) return new Material(shader);
            }
            return null;
        }
    }
}
