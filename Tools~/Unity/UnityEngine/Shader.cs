using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Shader: a named property table, no GPU program. Shader.Find knows the shaders the
    /// package asks for ("Standard", and with their package installed "Universal Render Pipeline/Lit" and
    /// "HDRP/Lit"); see HookeRope.StandIn.ShaderLibrary.
    /// </summary>
    public sealed class Shader : Object
    {
        internal Shader(ShaderDefinition definition)
        {
            Definition = definition;
            name = definition.Name;
        }

        /// <summary>Finds a shader with the given name. Returns null if the shader is not found.</summary>
        public static Shader Find(string name) => ShaderLibrary.Find(name);

        /// <summary>Render queue of this shader (Read Only).</summary>
        public int renderQueue
        {
            get { EnsureAlive(); return Definition.RenderQueue; }
        }

        /// <summary>The shader's property table.</summary>
        internal ShaderDefinition Definition { get; }
    }
}
