using System;
using UnityEngine.Rendering;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the vertex layout a Mesh.SetVertexBufferParams call produces. Validation and packing follow
    /// the documentation of VertexAttributeDescriptor (2022.3): up to four streams; within a stream the attributes
    /// are laid out back to back in VertexAttribute order (Position, Normal, Tangent, Color, TexCoord0…7,
    /// BlendWeight, BlendIndices) whatever order they were passed in; each attribute's size (format × dimension)
    /// must be a multiple of 4 bytes; dimension 1…4. Invalid layouts throw ArgumentException like Unity's native
    /// check ("Invalid vertex attribute dimension value (0, should be [1,4])" is Unity's own wording).
    /// </summary>
    internal sealed class VertexLayout
    {
        /// <summary>Unity supports up to four vertex streams.</summary>
        internal const int MaxStreams = 4;

        readonly VertexAttributeDescriptor[] _attributes;
        readonly int[] _offsets;
        readonly int[] _strides = new int[MaxStreams];

        /// <summary>The empty layout of a new Mesh.</summary>
        internal static readonly VertexLayout Empty = new VertexLayout(Array.Empty<VertexAttributeDescriptor>());

        VertexLayout(VertexAttributeDescriptor[] sortedAttributes)
        {
            _attributes = sortedAttributes;
            _offsets = new int[sortedAttributes.Length];
            for (int i = 0; i < sortedAttributes.Length; i++)
            {
                int stream = sortedAttributes[i].stream;
                _offsets[i] = _strides[stream];
                _strides[stream] += AttributeSize(sortedAttributes[i]);
            }
        }

        /// <summary>Validates <paramref name="attributes"/> and packs them; throws ArgumentException as Unity does on a bad layout.</summary>
        internal static VertexLayout Create(VertexAttributeDescriptor[] attributes)
        {
            if (attributes == null) throw new ArgumentNullException(nameof(attributes));
            var sorted = (VertexAttributeDescriptor[])attributes.Clone();
            for (int i = 0; i < sorted.Length; i++)
            {
                var a = sorted[i];
                if (a.dimension < 1 || a.dimension > 4)
                    throw new ArgumentException($"Invalid vertex attribute dimension value ({a.dimension}, should be [1,4])");
                if (a.stream < 0 || a.stream >= MaxStreams)
                    throw new ArgumentException($"Invalid vertex attribute stream value ({a.stream}, should be [0,{MaxStreams - 1}])");
                if ((int)a.attribute < 0 || a.attribute > VertexAttribute.BlendIndices)
                    throw new ArgumentException($"Invalid vertex attribute value ({(int)a.attribute})");
                int formatSize = FormatSize(a.format);
                if ((formatSize * a.dimension) % 4 != 0)
                    throw new ArgumentException($"Invalid vertex attribute format+dimension value ({a.format} x {a.dimension}, data size must be multiple of 4)");
                for (int j = 0; j < i; j++)
                    if (sorted[j].attribute == a.attribute)
                        throw new ArgumentException($"Vertex attribute {a.attribute} is specified more than once");
            }
            // Within each stream, attributes follow VertexAttribute order (the documented layout rule).
            Array.Sort(sorted, (x, y) => x.stream != y.stream ? x.stream.CompareTo(y.stream) : x.attribute.CompareTo(y.attribute));
            return new VertexLayout(sorted);
        }

        /// <summary>Bytes of one component of <paramref name="format"/>.</summary>
        internal static int FormatSize(VertexAttributeFormat format)
        {
            switch (format)
            {
                case VertexAttributeFormat.Float32:
                case VertexAttributeFormat.UInt32:
                case VertexAttributeFormat.SInt32:
                    return 4;
                case VertexAttributeFormat.Float16:
                case VertexAttributeFormat.UNorm16:
                case VertexAttributeFormat.SNorm16:
                case VertexAttributeFormat.UInt16:
                case VertexAttributeFormat.SInt16:
                    return 2;
                case VertexAttributeFormat.UNorm8:
                case VertexAttributeFormat.SNorm8:
                case VertexAttributeFormat.UInt8:
                case VertexAttributeFormat.SInt8:
                    return 1;
                default:
                    throw new ArgumentException($"Invalid vertex attribute format value ({(int)format})");
            }
        }

        static int AttributeSize(VertexAttributeDescriptor a) => FormatSize(a.format) * a.dimension;

        /// <summary>Attributes in layout order (by stream, then VertexAttribute order).</summary>
        internal int Count => _attributes.Length;

        /// <summary>The attribute at layout position <paramref name="index"/>.</summary>
        internal VertexAttributeDescriptor this[int index] => _attributes[index];

        /// <summary>Layout position of <paramref name="attribute"/>, or -1.</summary>
        internal int IndexOf(VertexAttribute attribute)
        {
            for (int i = 0; i < _attributes.Length; i++)
                if (_attributes[i].attribute == attribute) return i;
            return -1;
        }

        /// <summary>Byte offset of the attribute at layout position <paramref name="index"/> within its stream.</summary>
        internal int OffsetAt(int index) => _offsets[index];

        /// <summary>Bytes per vertex in <paramref name="stream"/> (0 when the stream is unused or out of range).</summary>
        internal int Stride(int stream) => stream >= 0 && stream < MaxStreams ? _strides[stream] : 0;

        /// <summary>Number of vertex buffers: the highest stream in use plus one (0 for an empty layout).</summary>
        internal int StreamCount
        {
            get
            {
                for (int s = MaxStreams - 1; s >= 0; s--)
                    if (_strides[s] > 0) return s + 1;
                return 0;
            }
        }

        /// <summary>A copy of the attributes in layout order.</summary>
        internal VertexAttributeDescriptor[] ToArray() => (VertexAttributeDescriptor[])_attributes.Clone();

        /// <summary>True when both layouts have the same attributes in the same places.</summary>
        internal bool SameAs(VertexLayout other)
        {
            if (other._attributes.Length != _attributes.Length) return false;
            for (int i = 0; i < _attributes.Length; i++)
                if (_attributes[i] != other._attributes[i]) return false;
            return true;
        }
    }
}
