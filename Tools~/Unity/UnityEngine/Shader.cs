namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Shader.</summary>
    public sealed class Shader : Object
    {
        /// <summary>Finds a shader with the given name. Returns null if the shader is not found.</summary>
        public static Shader Find(string name) => throw Shim.NotRun;
    }
}
