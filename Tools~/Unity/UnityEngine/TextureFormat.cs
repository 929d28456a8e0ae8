namespace UnityEngine
{
    /// <summary>Shim of UnityEngine.TextureFormat (the formats the package uses).</summary>
    public enum TextureFormat
    {
        /// <summary>Color with alpha texture format, 8-bits per channel.</summary>
        RGBA32 = 4,
    }
}
