namespace UnityEngine.Rendering
{
    /// <summary>Stand-in of UnityEngine.Rendering.VertexAttributeFormat: data type of a VertexAttribute (values as Unity's GraphicsEnums.cs).</summary>
    public enum VertexAttributeFormat
    {
        /// <summary>32-bit float number.</summary>
        Float32 = 0,
        /// <summary>16-bit float number.</summary>
        Float16 = 1,
        /// <summary>8-bit unsigned normalized number.</summary>
        UNorm8 = 2,
        /// <summary>8-bit signed normalized number.</summary>
        SNorm8 = 3,
        /// <summary>16-bit unsigned normalized number.</summary>
        UNorm16 = 4,
        /// <summary>16-bit signed normalized number.</summary>
        SNorm16 = 5,
        /// <summary>8-bit unsigned integer.</summary>
        UInt8 = 6,
        /// <summary>8-bit signed integer.</summary>
        SInt8 = 7,
        /// <summary>16-bit unsigned integer.</summary>
        UInt16 = 8,
        /// <summary>16-bit signed integer.</summary>
        SInt16 = 9,
        /// <summary>32-bit unsigned integer.</summary>
        UInt32 = 10,
        /// <summary>32-bit signed integer.</summary>
        SInt32 = 11,
    }
}
