namespace UnityEngine.Rendering
{
    /// <summary>Shim of UnityEngine.Rendering.VertexAttributeFormat (the formats the package uses).</summary>
    public enum VertexAttributeFormat
    {
        /// <summary>32-bit float number.</summary>
        Float32 = 0,
        /// <summary>16-bit float number.</summary>
        Float16 = 1,
    }
}
