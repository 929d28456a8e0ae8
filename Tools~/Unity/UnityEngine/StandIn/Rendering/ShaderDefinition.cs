using System.Collections.Generic;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: a shader the stand-in knows by name — its Properties block, render queue and the package that ships it.</summary>
    internal sealed class ShaderDefinition
    {
        readonly Dictionary<string, ShaderPropertyInfo> _byName = new Dictionary<string, ShaderPropertyInfo>(System.StringComparer.Ordinal);

        /// <summary>Defines a shader.</summary>
        internal ShaderDefinition(string name, int renderQueue, RenderPipelinePackage package, params ShaderPropertyInfo[] properties)
        {
            Name = name;
            RenderQueue = renderQueue;
            Package = package;
            Properties = properties;
            for (int i = 0; i < properties.Length; i++) _byName.Add(properties[i].Name, properties[i]);
        }

        /// <summary>The name Shader.Find takes.</summary>
        internal string Name { get; }

        /// <summary>The shader's render queue (2000, Geometry, when its SubShader has no Queue tag).</summary>
        internal int RenderQueue { get; }

        /// <summary>The package that ships the shader (None: built into the editor).</summary>
        internal RenderPipelinePackage Package { get; }

        /// <summary>The Properties block in declaration order.</summary>
        internal IReadOnlyList<ShaderPropertyInfo> Properties { get; }

        /// <summary>The property called <paramref name="name"/>, or null.</summary>
        internal ShaderPropertyInfo Find(string name) => name != null && _byName.TryGetValue(name, out var p) ? p : null;

        /// <summary>The first property tagged [MainTexture], or null.</summary>
        internal ShaderPropertyInfo MainTexture
        {
            get
            {
                for (int i = 0; i < Properties.Count; i++)
                    if (Properties[i].IsMainTexture) return Properties[i];
                return null;
            }
        }

        /// <summary>The first property tagged [MainColor], or null.</summary>
        internal ShaderPropertyInfo MainColor
        {
            get
            {
                for (int i = 0; i < Properties.Count; i++)
                    if (Properties[i].IsMainColor) return Properties[i];
                return null;
            }
        }
    }
}
