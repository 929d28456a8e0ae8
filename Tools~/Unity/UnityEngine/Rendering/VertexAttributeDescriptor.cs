using System;

namespace UnityEngine.Rendering
{
    /// <summary>Stand-in of UnityEngine.Rendering.VertexAttributeDescriptor: information about a single VertexAttribute of a Mesh vertex.</summary>
    public struct VertexAttributeDescriptor : IEquatable<VertexAttributeDescriptor>
    {
        /// <summary>The vertex attribute.</summary>
        public VertexAttribute attribute { get; set; }

        /// <summary>Format of the vertex attribute.</summary>
        public VertexAttributeFormat format { get; set; }

        /// <summary>Dimensionality of the vertex attribute.</summary>
        public int dimension { get; set; }

        /// <summary>Which vertex buffer stream the attribute should be in.</summary>
        public int stream { get; set; }

        /// <summary>Create a VertexAttributeDescriptor structure.</summary>
        public VertexAttributeDescriptor(VertexAttribute attribute = VertexAttribute.Position, VertexAttributeFormat format = VertexAttributeFormat.Float32, int dimension = 3, int stream = 0)
        {
            this.attribute = attribute;
            this.format = format;
            this.dimension = dimension;
            this.stream = stream;
        }

        /// <summary>Returns "(attr=… fmt=… dim=… stream=…)" as Unity does.</summary>
        public override string ToString() => $"(attr={attribute} fmt={format} dim={dimension} stream={stream})";

        /// <summary>Hash of all four fields.</summary>
        public override int GetHashCode()
        {
            unchecked
            {
                int hash = 17;
                hash = hash * 23 + (int)attribute;
                hash = hash * 23 + (int)format;
                hash = hash * 23 + dimension;
                return hash * 23 + stream;
            }
        }

        /// <summary>True when <paramref name="other"/> is a descriptor with the same fields.</summary>
        public override bool Equals(object other) => other is VertexAttributeDescriptor descriptor && Equals(descriptor);

        /// <summary>True when all four fields are equal.</summary>
        public bool Equals(VertexAttributeDescriptor other) =>
            attribute == other.attribute && format == other.format && dimension == other.dimension && stream == other.stream;

        /// <summary>Field-wise equality.</summary>
        public static bool operator ==(VertexAttributeDescriptor lhs, VertexAttributeDescriptor rhs) => lhs.Equals(rhs);

        /// <summary>Field-wise inequality.</summary>
        public static bool operator !=(VertexAttributeDescriptor lhs, VertexAttributeDescriptor rhs) => !lhs.Equals(rhs);
    }
}
