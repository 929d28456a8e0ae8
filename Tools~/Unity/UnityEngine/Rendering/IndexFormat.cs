namespace UnityEngine.Rendering
{
    /// <summary>Stand-in of UnityEngine.Rendering.IndexFormat: format of the mesh index buffer data.</summary>
    public enum IndexFormat
    {
        /// <summary>16 bit mesh index buffer format.</summary>
        UInt16 = 0,
        /// <summary>32 bit mesh index buffer format.</summary>
        UInt32 = 1,
    }
}
