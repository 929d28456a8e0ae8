namespace UnityEngine.Rendering
{
    /// <summary>Stand-in of UnityEngine.Rendering.VertexAttribute: possible attribute types that describe a vertex in a Mesh (values as Unity's GraphicsEnums.cs).</summary>
    public enum VertexAttribute
    {
        /// <summary>Vertex position.</summary>
        Position = 0,
        /// <summary>Vertex normal.</summary>
        Normal = 1,
        /// <summary>Vertex tangent.</summary>
        Tangent = 2,
        /// <summary>Vertex color.</summary>
        Color = 3,
        /// <summary>Primary texture coordinate (UV).</summary>
        TexCoord0 = 4,
        /// <summary>Additional texture coordinate.</summary>
        TexCoord1 = 5,
        /// <summary>Additional texture coordinate.</summary>
        TexCoord2 = 6,
        /// <summary>Additional texture coordinate.</summary>
        TexCoord3 = 7,
        /// <summary>Additional texture coordinate.</summary>
        TexCoord4 = 8,
        /// <summary>Additional texture coordinate.</summary>
        TexCoord5 = 9,
        /// <summary>Additional texture coordinate.</summary>
        TexCoord6 = 10,
        /// <summary>Additional texture coordinate.</summary>
        TexCoord7 = 11,
        /// <summary>Bone blend weights for skinned Meshes.</summary>
        BlendWeight = 12,
        /// <summary>Bone indices for skinned Meshes.</summary>
        BlendIndices = 13,
    }
}
