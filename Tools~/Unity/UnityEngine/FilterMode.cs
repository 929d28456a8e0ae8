namespace UnityEngine
{
    /// <summary>Stand-in of UnityEngine.FilterMode: filtering mode for textures.</summary>
    public enum FilterMode
    {
        /// <summary>Point filtering - texture pixels become blocky up close.</summary>
        Point = 0,
        /// <summary>Bilinear filtering - texture samples are averaged.</summary>
        Bilinear = 1,
        /// <summary>Trilinear filtering - texture samples are averaged and also blended between mipmap levels.</summary>
        Trilinear = 2,
    }
}
