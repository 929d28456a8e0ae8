namespace UnityEngine.Rendering
{
    /// <summary>Shim of UnityEngine.Rendering.VertexAttributeDescriptor: information about a single VertexAttribute of a Mesh vertex.</summary>
    public struct VertexAttributeDescriptor
    {
        /// <summary>Create a VertexAttributeDescriptor structure.</summary>
        public VertexAttributeDescriptor(VertexAttribute attribute = VertexAttribute.Position, VertexAttributeFormat format = VertexAttributeFormat.Float32, int dimension = 3, int stream = 0) => throw Shim.NotRun;
    }
}
