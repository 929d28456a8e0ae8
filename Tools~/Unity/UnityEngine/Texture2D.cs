namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.Texture2D.</summary>
    public sealed class Texture2D : Texture
    {
        /// <summary>Create a new empty texture.</summary>
        public Texture2D(int width, int height, TextureFormat textureFormat, bool mipChain) => throw Shim.NotRun;

        /// <summary>Set pixel values from raw preformatted data.</summary>
        public void SetPixelData<T>(T[] data, int mipLevel, int sourceDataStartIndex = 0) => throw Shim.NotRun;

        /// <summary>Copies changes you've made in a CPU texture to the GPU.</summary>
        public void Apply(bool updateMipmaps = true, bool makeNoLongerReadable = false) => throw Shim.NotRun;
    }
}
