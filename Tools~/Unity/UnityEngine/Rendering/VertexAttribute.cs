namespace UnityEngine.Rendering
{
    /// <summary>Shim of UnityEngine.Rendering.VertexAttribute: possible attribute types that describe a vertex in a Mesh.</summary>
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
    }
}
