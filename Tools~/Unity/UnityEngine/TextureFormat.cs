namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.TextureFormat: the uncompressed 8-bit formats of the stand-in's subset (values as Unity's).</summary>
    public enum TextureFormat
    {
        /// <summary>Alpha-only texture format, 8 bit integer.</summary>
        Alpha8 = 1,
        /// <summary>Three channel (RGB) texture format, 8-bits unsigned integer per channel.</summary>
        RGB24 = 3,
        /// <summary>Four channel (RGBA) texture format, 8-bits unsigned integer per channel.</summary>
        RGBA32 = 4,
        /// <summary>Color with alpha texture format, 8-bits per channel.</summary>
        ARGB32 = 5,
    }
}
