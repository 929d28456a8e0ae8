namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Texture: base class for Texture handling.</summary>
    public class Texture : Object
    {
        /// <summary>Texture coordinate wrapping mode.</summary>
        public TextureWrapMode wrapMode { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Filtering mode of the Texture.</summary>
        public FilterMode filterMode { get => throw Shim.NotRun; set => throw Shim.NotRun; }
    }
}
