using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: what Shader.Find can find. The stand-in models an Editor project on the Built-in render
    /// pipeline with no SRP package installed: "Standard" and "Legacy Shaders/Diffuse" are always found; "Universal Render Pipeline/Lit" and
    /// "HDRP/Lit" only after a test calls <see cref="Install"/> for their package (in Unity, a package's shaders are
    /// findable in the Editor whenever the package is installed, whichever pipeline is active). Any other name
    /// returns null. Each name maps to one shared Shader instance, as in Unity. World.Reset uninstalls the packages.
    /// </summary>
    internal static class ShaderLibrary
    {
        static readonly ShaderDefinition[] s_Known =
        {
            StandardShaderTable.Definition,
            LegacyDiffuseShaderTable.Definition,
            UniversalLitShaderTable.Definition,
            HighDefinitionLitShaderTable.Definition,
        };

        static readonly Dictionary<string, Shader> s_Loaded = new Dictionary<string, Shader>(System.StringComparer.Ordinal);

        static ShaderLibrary() => World.WorldReset += Reset;

        /// <summary>Packages whose shaders are findable.</summary>
        internal static RenderPipelinePackage Installed { get; private set; }

        /// <summary>Makes the shaders of <paramref name="package"/> findable (until World.Reset).</summary>
        internal static void Install(RenderPipelinePackage package) => Installed |= package;

        /// <summary>Shader.Find: the shared shader called <paramref name="name"/>, or null when unknown or its package is not installed.</summary>
        internal static Shader Find(string name)
        {
            if (name == null) return null;
            for (int i = 0; i < s_Known.Length; i++)
            {
                var definition = s_Known[i];
                if (definition.Name != name) continue;
                if (definition.Package != RenderPipelinePackage.None && (Installed & definition.Package) == 0) return null;
                if (!s_Loaded.TryGetValue(name, out var shader) || shader == null)
                {
                    shader = new Shader(definition);
                    s_Loaded[name] = shader;
                }
                return shader;
            }
            return null;
        }

        static void Reset()
        {
            Installed = RenderPipelinePackage.None;
        }
    }
}
