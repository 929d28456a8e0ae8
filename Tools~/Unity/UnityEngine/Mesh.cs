using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using HookeRope.StandIn;
using UnityEngine.Rendering;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Mesh: a CPU data holder for the advanced mesh API (vertex/index buffer params and
    /// data, sub-meshes, bounds) with readback of what was uploaded (vertices, normals, triangles, indices, the
    /// vertex layout). Nothing is drawn. Argument checks written in C# in Unity 2022.3 (Mesh.cs) are reproduced with
    /// their exception types; checks done natively follow the documentation (see Tools~/Unity/STAND-IN.md (Rendering)).
    /// Every change is recorded with its MeshUpdateFlags in an internal log the stand-in's tests read.
    /// </summary>
    public sealed class Mesh : Object
    {
        const string SubMeshOutOfRange = "Specified sub mesh is out of range. Must be greater or equal to 0 and less than subMeshCount.";

        VertexLayout _layout = VertexLayout.Empty;
        readonly byte[][] _streams = new byte[VertexLayout.MaxStreams][];
        int _vertexCount;
        readonly IndexBuffer _indices = new IndexBuffer();
        readonly List<SubMeshDescriptor> _subMeshes = new List<SubMeshDescriptor> { new SubMeshDescriptor(0, 0) };
        Bounds _bounds;
        readonly MeshUpdateLog _log = new MeshUpdateLog();

        /// <summary>Creates an empty Mesh (no vertices, one empty sub-mesh).</summary>
        public Mesh()
        {
            for (int s = 0; s < _streams.Length; s++) _streams[s] = Array.Empty<byte>();
        }

        /// <summary>The bounding volume of the Mesh. Setting it notifies the Mesh's renderers.</summary>
        public Bounds bounds
        {
            get { EnsureAlive(); return _bounds; }
            set
            {
                EnsureAlive();
                _bounds = value;
                _log.Record("bounds", MeshUpdateFlags.Default, _bounds);
            }
        }

        /// <summary>The number of sub-meshes inside the Mesh object. Shrinking it truncates the index buffer at the first removed sub-mesh's indexStart.</summary>
        public int subMeshCount
        {
            get { EnsureAlive(); return _subMeshes.Count; }
            set
            {
                EnsureAlive();
                if (value < 0) throw new ArgumentException("Mesh.subMeshCount can't be negative (" + value + ").");
                if (value < _subMeshes.Count)
                {
                    _indices.Truncate(Math.Max(0, _subMeshes[value].indexStart));
                    _subMeshes.RemoveRange(value, _subMeshes.Count - value);
                }
                while (_subMeshes.Count < value) _subMeshes.Add(new SubMeshDescriptor(0, 0));
                _log.Record("subMeshCount", MeshUpdateFlags.Default, _bounds);
            }
        }

        /// <summary>Returns the number of vertices in the Mesh (Read Only).</summary>
        public int vertexCount
        {
            get { EnsureAlive(); return _vertexCount; }
        }

        /// <summary>Returns true if the Mesh is read/write enabled (always, for meshes created from script).</summary>
        public bool isReadable
        {
            get { EnsureAlive(); return true; }
        }

        /// <summary>Format of the mesh index buffer data.</summary>
        public IndexFormat indexFormat
        {
            get { EnsureAlive(); return _indices.Format; }
            set => throw StandInError.Unsupported("Mesh.indexFormat (set)");
        }

        /// <summary>Returns a copy of the vertex positions (decoded from the Position attribute; empty when the Mesh has none).</summary>
        public Vector3[] vertices
        {
            get { EnsureAlive(); return ReadChannel(VertexAttribute.Position); }
            set => throw StandInError.Unsupported("Mesh.vertices (set)");
        }

        /// <summary>Returns a copy of the vertex normals (decoded from the Normal attribute; empty when the Mesh has none).</summary>
        public Vector3[] normals
        {
            get { EnsureAlive(); return ReadChannel(VertexAttribute.Normal); }
            set => throw StandInError.Unsupported("Mesh.normals (set)");
        }

        /// <summary>Returns a copy of the texture coordinates of the first channel (decoded from the TexCoord0 attribute; empty when the Mesh has none).</summary>
        public Vector2[] uv
        {
            get
            {
                EnsureAlive();
                int a = _layout.IndexOf(VertexAttribute.TexCoord0);
                if (a < 0) return new Vector2[0];
                var attribute = _layout[a];
                var stream = _streams[attribute.stream];
                int stride = _layout.Stride(attribute.stream), offset = _layout.OffsetAt(a);
                var result = new Vector2[_vertexCount];
                for (int v = 0; v < _vertexCount; v++)
                    result[v] = new Vector2(VertexDecoder.Read(stream, v * stride + offset, attribute, 0), VertexDecoder.Read(stream, v * stride + offset, attribute, 1));
                return result;
            }
            set => throw StandInError.Unsupported("Mesh.uv (set)");
        }

        /// <summary>An array containing all triangles in the Mesh (all sub-meshes, base vertex applied).</summary>
        public int[] triangles
        {
            get
            {
                EnsureAlive();
                var all = new List<int>();
                for (int s = 0; s < _subMeshes.Count; s++) all.AddRange(TrianglesOf(s, true));
                return all.ToArray();
            }
            set => throw StandInError.Unsupported("Mesh.triangles (set)");
        }

        /// <summary>Optimize mesh for frequent updates (recorded; no effect without a GPU).</summary>
        public void MarkDynamic()
        {
            EnsureAlive();
            IsDynamic = true;
        }

        /// <summary>Notify Renderer components of mesh geometry change.</summary>
        public void MarkModified()
        {
            EnsureAlive();
            _log.Record("MarkModified", MeshUpdateFlags.Default, _bounds);
        }

        /// <summary>Recalculate the bounding volume of the Mesh and all of its sub-meshes from the vertices.</summary>
        public void RecalculateBounds() => RecalculateBounds(MeshUpdateFlags.Default);

        /// <summary>Recalculate the bounding volume of the Mesh and all of its sub-meshes from the vertices.</summary>
        public void RecalculateBounds(MeshUpdateFlags flags)
        {
            EnsureAlive();
            _bounds = VertexBounds(0, _vertexCount);
            for (int s = 0; s < _subMeshes.Count; s++) _subMeshes[s] = WithComputedVertexRange(_subMeshes[s]);
            _log.Record("RecalculateBounds", flags, _bounds);
        }

        // ---- vertex buffer -------------------------------------------------------------------------------------

        /// <summary>Sets the vertex buffer size and layout (vertex data is kept when the layout is unchanged, else zeroed).</summary>
        public void SetVertexBufferParams(int vertexCount, params VertexAttributeDescriptor[] attributes)
        {
            EnsureAlive();
            if (vertexCount < 0) throw new ArgumentException("Mesh vertex count can't be negative (" + vertexCount + ").");
            var layout = VertexLayout.Create(attributes);
            bool keep = layout.SameAs(_layout);
            for (int s = 0; s < VertexLayout.MaxStreams; s++)
            {
                int size = vertexCount * layout.Stride(s);
                if (keep && _streams[s].Length == size) continue;
                var bytes = size == 0 ? Array.Empty<byte>() : new byte[size];
                if (keep) Buffer.BlockCopy(_streams[s], 0, bytes, 0, Math.Min(size, _streams[s].Length));
                _streams[s] = bytes;
            }
            _layout = layout;
            _vertexCount = vertexCount;
            _log.Record("SetVertexBufferParams", MeshUpdateFlags.Default, _bounds);
        }

        /// <summary>Sets the data of the vertex buffer of the Mesh: copies count elements of T (raw bytes) to vertex meshBufferStart of the stream.</summary>
        public void SetVertexBufferData<T>(T[] data, int dataStart, int meshBufferStart, int count, int stream = 0, MeshUpdateFlags flags = MeshUpdateFlags.Default) where T : struct
        {
            EnsureAlive();
            if (data == null) throw new ArgumentNullException(nameof(data));
            if (!RawBytes.IsBlittable<T>())
                throw new ArgumentException("Array passed to SetVertexBufferData must be blittable.\n" + typeof(T) + " contains references.");
            if (dataStart < 0 || meshBufferStart < 0 || count < 0 || dataStart + count > data.Length)
                throw new ArgumentOutOfRangeException($"Bad start/count arguments (dataStart:{dataStart} meshBufferStart:{meshBufferStart} count:{count})");
            if (stream < 0 || stream >= VertexLayout.MaxStreams)
            {
                Debug.LogError($"SetVertexBufferData: stream {stream} is out of range; it must be within 0 to {VertexLayout.MaxStreams - 1}.", this);
                return;
            }
            var buffer = _streams[stream];
            long offset = (long)meshBufferStart * _layout.Stride(stream);
            long byteCount = (long)count * RawBytes.SizeOf<T>();
            if (offset + byteCount > buffer.Length)
            {
                Debug.LogError($"SetVertexData() with out-of-bounds arguments; would need to copy {byteCount} bytes at offset {offset} into a {buffer.Length} byte buffer", this);
                return;
            }
            RawBytes.Of(data, dataStart, count).CopyTo(new Span<byte>(buffer, (int)offset, (int)byteCount));
            _log.Record("SetVertexBufferData", flags, _bounds);
        }

        /// <summary>Returns the number of vertex attributes that the mesh has.</summary>
        public int vertexAttributeCount
        {
            get { EnsureAlive(); return _layout.Count; }
        }

        /// <summary>Returns information about a vertex attribute based on its index (layout order).</summary>
        public VertexAttributeDescriptor GetVertexAttribute(int index)
        {
            EnsureAlive();
            if (index < 0 || index >= _layout.Count)
                throw new ArgumentOutOfRangeException(nameof(index), index, "Vertex attribute index is out of range (mesh has " + _layout.Count + " attributes).");
            return _layout[index];
        }

        /// <summary>Get information about vertex attributes of a Mesh (layout order).</summary>
        public VertexAttributeDescriptor[] GetVertexAttributes()
        {
            EnsureAlive();
            return _layout.ToArray();
        }

        /// <summary>Checks if a specific vertex data attribute exists on this Mesh.</summary>
        public bool HasVertexAttribute(VertexAttribute attr)
        {
            EnsureAlive();
            return _layout.IndexOf(attr) >= 0;
        }

        /// <summary>Get dimension of a specific vertex data attribute on this Mesh (0 when absent).</summary>
        public int GetVertexAttributeDimension(VertexAttribute attr)
        {
            EnsureAlive();
            int i = _layout.IndexOf(attr);
            return i < 0 ? 0 : _layout[i].dimension;
        }

        /// <summary>Get format of a specific vertex data attribute on this Mesh (Float32 when absent).</summary>
        public VertexAttributeFormat GetVertexAttributeFormat(VertexAttribute attr)
        {
            EnsureAlive();
            int i = _layout.IndexOf(attr);
            return i < 0 ? VertexAttributeFormat.Float32 : _layout[i].format;
        }

        /// <summary>Gets the vertex buffer stream index of a specific vertex data attribute on this Mesh (-1 when absent).</summary>
        public int GetVertexAttributeStream(VertexAttribute attr)
        {
            EnsureAlive();
            int i = _layout.IndexOf(attr);
            return i < 0 ? -1 : _layout[i].stream;
        }

        /// <summary>Get offset within a vertex buffer stream of a specific vertex data attribute on this Mesh (-1 when absent).</summary>
        public int GetVertexAttributeOffset(VertexAttribute attr)
        {
            EnsureAlive();
            int i = _layout.IndexOf(attr);
            return i < 0 ? -1 : _layout.OffsetAt(i);
        }

        /// <summary>Gets the number of vertex buffers present in the Mesh (highest stream in use + 1).</summary>
        public int vertexBufferCount
        {
            get { EnsureAlive(); return _layout.StreamCount; }
        }

        /// <summary>Get vertex buffer stream stride in bytes (0 if the stream is not present).</summary>
        public int GetVertexBufferStride(int stream)
        {
            EnsureAlive();
            return _layout.Stride(stream);
        }

        // ---- index buffer and sub-meshes ---------------------------------------------------------------------

        /// <summary>Sets the index buffer size and format (indices are kept when the format is unchanged).</summary>
        public void SetIndexBufferParams(int indexCount, IndexFormat format)
        {
            EnsureAlive();
            if (indexCount < 0) throw new ArgumentException("Mesh index count can't be negative (" + indexCount + ").");
            if (format != IndexFormat.UInt16 && format != IndexFormat.UInt32) throw new ArgumentException("Invalid index format (" + (int)format + ").");
            _indices.Resize(indexCount, format);
            _log.Record("SetIndexBufferParams", MeshUpdateFlags.Default, _bounds);
        }

        /// <summary>Sets the data of the index buffer of the Mesh; unless DontValidateIndices, an index at or past vertexCount throws.</summary>
        public void SetIndexBufferData<T>(T[] data, int dataStart, int meshBufferStart, int count, MeshUpdateFlags flags = MeshUpdateFlags.Default) where T : struct
        {
            EnsureAlive();
            if (data == null) throw new ArgumentNullException(nameof(data));
            if (!RawBytes.IsBlittable<T>())
                throw new ArgumentException("Array passed to SetIndexBufferData must be blittable.\n" + typeof(T) + " contains references.");
            if (dataStart < 0 || meshBufferStart < 0 || count < 0 || dataStart + count > data.Length)
                throw new ArgumentOutOfRangeException($"Bad start/count arguments (dataStart:{dataStart} meshBufferStart:{meshBufferStart} count:{count})");
            int indexSize = IndexBuffer.IndexSize(_indices.Format);
            long offset = (long)meshBufferStart * indexSize;
            var source = RawBytes.Of(data, dataStart, count);
            if (offset + source.Length > _indices.Bytes.Length)
                throw new ArgumentException($"SetIndexData() with out-of-bounds arguments; would need to copy {source.Length} bytes at offset {offset} into a {_indices.Bytes.Length} byte buffer");
            if ((flags & MeshUpdateFlags.DontValidateIndices) == 0)
            {
                for (int k = 0; k + indexSize <= source.Length; k += indexSize)
                {
                    long index = indexSize == 4 ? BinaryPrimitives.ReadUInt32LittleEndian(source.Slice(k)) : BinaryPrimitives.ReadUInt16LittleEndian(source.Slice(k));
                    if (index >= _vertexCount)
                        throw new ArgumentException($"Mesh.SetIndexBufferData: index {index} at position {meshBufferStart + k / indexSize} is out of bounds (vertexCount {_vertexCount}).");
                }
            }
            source.CopyTo(new Span<byte>(_indices.Bytes, (int)offset, source.Length));
            _log.Record("SetIndexBufferData", flags, _bounds);
        }

        /// <summary>
        /// Sets the information about a sub-mesh of the Mesh. Unless DontRecalculateBounds is passed, the descriptor's
        /// bounds, firstVertex and vertexCount are computed from the indices it covers (the Mesh's own bounds are not).
        /// </summary>
        public void SetSubMesh(int index, SubMeshDescriptor desc, MeshUpdateFlags flags = MeshUpdateFlags.Default)
        {
            EnsureAlive();
            if (index < 0 || index >= _subMeshes.Count) throw new IndexOutOfRangeException(SubMeshOutOfRange);
            if (desc.indexStart < 0 || desc.indexCount < 0 || (long)desc.indexStart + desc.indexCount > _indices.Count)
                throw new ArgumentException($"SubMesh index range (start {desc.indexStart}, count {desc.indexCount}) is out of bounds of the index buffer ({_indices.Count} indices).");
            _subMeshes[index] = (flags & MeshUpdateFlags.DontRecalculateBounds) == 0 ? WithComputedVertexRange(desc) : desc;
            _log.Record("SetSubMesh", flags, _bounds);
        }

        /// <summary>Get information about a sub-mesh of the Mesh.</summary>
        public SubMeshDescriptor GetSubMesh(int index)
        {
            EnsureAlive();
            if (index < 0 || index >= _subMeshes.Count) throw new IndexOutOfRangeException(SubMeshOutOfRange);
            return _subMeshes[index];
        }

        /// <summary>Gets the starting index location within the Mesh's index buffer, for the given sub-mesh.</summary>
        public uint GetIndexStart(int submesh)
        {
            EnsureAlive();
            if (submesh < 0 || submesh >= _subMeshes.Count) throw new IndexOutOfRangeException(SubMeshOutOfRange);
            return (uint)_subMeshes[submesh].indexStart;
        }

        /// <summary>Gets the index count of the given sub-mesh.</summary>
        public uint GetIndexCount(int submesh)
        {
            EnsureAlive();
            if (submesh < 0 || submesh >= _subMeshes.Count) throw new IndexOutOfRangeException(SubMeshOutOfRange);
            return (uint)_subMeshes[submesh].indexCount;
        }

        /// <summary>Gets the base vertex index of the given sub-mesh.</summary>
        public uint GetBaseVertex(int submesh)
        {
            EnsureAlive();
            if (submesh < 0 || submesh >= _subMeshes.Count) throw new IndexOutOfRangeException(SubMeshOutOfRange);
            return (uint)_subMeshes[submesh].baseVertex;
        }

        /// <summary>Fetches the triangle list for the specified sub-mesh on this object (logs an error and returns an empty array for a bad index).</summary>
        public int[] GetTriangles(int submesh) => GetTriangles(submesh, true);

        /// <summary>Fetches the triangle list for the specified sub-mesh on this object.</summary>
        public int[] GetTriangles(int submesh, bool applyBaseVertex)
        {
            EnsureAlive();
            if (!CheckSubMesh(submesh, "triangles")) return new int[0];
            return TrianglesOf(submesh, applyBaseVertex);
        }

        /// <summary>Fetches the index list for the specified sub-mesh (logs an error and returns an empty array for a bad index).</summary>
        public int[] GetIndices(int submesh) => GetIndices(submesh, true);

        /// <summary>Fetches the index list for the specified sub-mesh.</summary>
        public int[] GetIndices(int submesh, bool applyBaseVertex)
        {
            EnsureAlive();
            if (!CheckSubMesh(submesh, "indices")) return new int[0];
            var d = _subMeshes[submesh];
            var result = new int[d.indexCount];
            int add = applyBaseVertex ? d.baseVertex : 0;
            for (int i = 0; i < d.indexCount; i++) result[i] = _indices[d.indexStart + i] + add;
            return result;
        }

        // ---- stand-in internals -------------------------------------------------------------------------------

        /// <summary>Every recorded change (call, flags, whether renderers were notified), oldest first.</summary>
        internal MeshUpdateLog UpdateLog => _log;

        /// <summary>True after MarkDynamic.</summary>
        internal bool IsDynamic { get; private set; }

        /// <summary>True once the Mesh was destroyed and its buffers released.</summary>
        internal bool IsReleased { get; private set; }

        /// <summary>A copy of the raw bytes of vertex stream <paramref name="stream"/>.</summary>
        internal byte[] VertexStreamBytes(int stream) => (byte[])_streams[stream].Clone();

        /// <summary>Releases the buffers when the Mesh is destroyed.</summary>
        internal override void OnStandInDestroy()
        {
            IsReleased = true;
            for (int s = 0; s < _streams.Length; s++) _streams[s] = Array.Empty<byte>();
            _indices.Resize(0, _indices.Format);
            base.OnStandInDestroy();
        }

        bool CheckSubMesh(int submesh, string what)
        {
            if (submesh >= 0 && submesh < _subMeshes.Count) return true;
            Debug.LogError("Failed getting " + what + ". Submesh index is out of bounds.", this);
            return false;
        }

        int[] TrianglesOf(int submesh, bool applyBaseVertex)
        {
            var d = _subMeshes[submesh];
            if (d.topology == MeshTopology.Quads) throw StandInError.Unsupported("Mesh.GetTriangles of a Quads sub-mesh");
            if (d.topology != MeshTopology.Triangles) return new int[0];
            int count = d.indexCount - d.indexCount % 3;
            var result = new int[count];
            int add = applyBaseVertex ? d.baseVertex : 0;
            for (int i = 0; i < count; i++) result[i] = _indices[d.indexStart + i] + add;
            return result;
        }

        Vector3[] ReadChannel(VertexAttribute channel)
        {
            int a = _layout.IndexOf(channel);
            if (a < 0) return new Vector3[0];
            var attribute = _layout[a];
            var stream = _streams[attribute.stream];
            int stride = _layout.Stride(attribute.stream), offset = _layout.OffsetAt(a);
            var result = new Vector3[_vertexCount];
            for (int v = 0; v < _vertexCount; v++) result[v] = VertexDecoder.ReadVector3(stream, v * stride + offset, attribute);
            return result;
        }

        Vector3 PositionAt(int vertex, int attributeIndex)
        {
            var attribute = _layout[attributeIndex];
            return VertexDecoder.ReadVector3(_streams[attribute.stream], vertex * _layout.Stride(attribute.stream) + _layout.OffsetAt(attributeIndex), attribute);
        }

        Bounds VertexBounds(int first, int count)
        {
            int a = _layout.IndexOf(VertexAttribute.Position);
            if (a < 0 || count <= 0) return new Bounds();
            Vector3 min = PositionAt(first, a), max = min;
            for (int v = first + 1; v < first + count; v++)
            {
                var p = PositionAt(v, a);
                min = Vector3.Min(min, p);
                max = Vector3.Max(max, p);
            }
            var result = new Bounds();
            result.SetMinMax(min, max);
            return result;
        }

        /// <summary>The descriptor with firstVertex, vertexCount and bounds computed from the vertices its indices reference.</summary>
        SubMeshDescriptor WithComputedVertexRange(SubMeshDescriptor d)
        {
            int a = _layout.IndexOf(VertexAttribute.Position);
            int lo = int.MaxValue, hi = -1;
            Vector3 min = default, max = default;
            for (int i = 0; i < d.indexCount; i++)
            {
                int v = _indices[d.indexStart + i] + d.baseVertex;
                if (v < 0 || v >= _vertexCount) continue;
                bool first = hi < 0;
                if (v < lo) lo = v;
                if (v > hi) hi = v;
                if (a < 0) continue;
                var p = PositionAt(v, a);
                min = first ? p : Vector3.Min(min, p);
                max = first ? p : Vector3.Max(max, p);
            }
            if (hi < 0)
            {
                d.firstVertex = 0;
                d.vertexCount = 0;
                d.bounds = new Bounds();
                return d;
            }
            d.firstVertex = lo;
            d.vertexCount = hi - lo + 1;
            var b = new Bounds();
            b.SetMinMax(min, max);
            d.bounds = a < 0 ? new Bounds() : b;
            return d;
        }
    }
}
