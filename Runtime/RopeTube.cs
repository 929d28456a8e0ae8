using System;
using HookeRope.Fracture;
using HookeRope.Geometry;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// Owns a core <see cref="TubeMeshBuilder"/> (on the ring layout of the rope's <see cref="RopeSimulation"/>,
    /// refined around the neck) and the caller-owned vertex and index buffers of one rope mesh, and feeds the builder
    /// with the rope's interpolated positions in the renderer's local space (the facade's own mesh fill uses the
    /// latest physics positions in world space, so the renderer builds its own). Buffers grow only
    /// when the topology grows (a new segment count or a break); otherwise an update allocates nothing.
    /// </summary>
    internal sealed class RopeTube
    {
        readonly TubeMeshSettings _settings = new TubeMeshSettings();
        TubeMeshBuilder _builder;
        RingLayout _layout;
        TubeVertex[] _vertices = Array.Empty<TubeVertex>();
        int[] _indices = Array.Empty<int>();
        float[] _x = Array.Empty<float>(), _y = Array.Empty<float>(), _z = Array.Empty<float>();
        float[] _ringRadii = Array.Empty<float>();
        bool[] _broken = Array.Empty<bool>();

        /// <summary>Tube for <paramref name="radialSegments"/> vertices around (3 … 64).</summary>
        public RopeTube(int radialSegments)
        {
            _settings.RadialSegments = radialSegments;
        }

        /// <summary>Vertices around the tube.</summary>
        public int RadialSegments => _settings.RadialSegments;

        /// <summary>Vertices written by the last update.</summary>
        public int VertexCount { get; private set; }

        /// <summary>Indices written by the last update: the tube and caps first, then the burr strands.</summary>
        public int IndexCount { get; private set; }

        /// <summary>Indices of the tube and caps, [0, TubeIndexCount): submesh 0.</summary>
        public int TubeIndexCount { get; private set; }

        /// <summary>Vertex buffer (local space of the renderer, m).</summary>
        public TubeVertex[] Vertices => _vertices;

        /// <summary>Index buffer (triangles).</summary>
        public int[] Indices => _indices;

        /// <summary>Local-space bounds of the last update (m).</summary>
        public Bounds Bounds { get; private set; }

        /// <summary>
        /// Rebuilds the tube from <paramref name="world"/> (x, y, z triples, m) of <paramref name="particles"/>
        /// particles, expressed in <paramref name="frame"/>'s local space. Returns true when the vertex layout or the
        /// index buffer changed and must be uploaded again.
        /// </summary>
        public bool Update(ElasticRope rope, float[] world, int particles, Transform frame)
        {
            var core = rope.Simulation.Rope;
            int segments = particles - 1;
            bool resized = false;
            // The facade's ring layout: uniform, or refined around the neck zone in Zone neck mode.
            var ringLayout = rope.Simulation.RingLayout;
            if (_builder == null || !ReferenceEquals(_layout, ringLayout) || _builder.SegmentCount != segments)
            {
                _layout = ringLayout;
                _builder = new TubeMeshBuilder(_settings, ringLayout);
                _x = new float[particles];
                _y = new float[particles];
                _z = new float[particles];
                _broken = new bool[segments];
                _ringRadii = new float[_builder.Layout.RingCount];
                resized = true;
            }

            for (int i = 0, j = 0; i < particles; i++, j += 3)
            {
                var local = frame.InverseTransformPoint(new Vector3(world[j], world[j + 1], world[j + 2]));
                _x[i] = local.x;
                _y[i] = local.y;
                _z[i] = local.z;
            }
            for (int s = 0; s < segments; s++) _broken[s] = rope.IsSegmentBroken(s);

            var layout = _builder.Layout;
            rope.FillRingRadii(layout.RingSegments, layout.RingFractions, _ringRadii);
            var scale = frame.lossyScale;
            float inverseScale = scale.x != 0f ? 1f / Math.Abs(scale.x) : 1f;
            if (inverseScale != 1f)
                for (int k = 0; k < _ringRadii.Length; k++) _ringRadii[k] *= inverseScale;

            int vertexCount = _builder.GetVertexCount(_broken);
            int indexCount = _builder.GetIndexCount(_broken);
            if (_vertices.Length < vertexCount) { _vertices = new TubeVertex[vertexCount]; resized = true; }
            if (_indices.Length < indexCount) { _indices = new int[indexCount]; resized = true; }

            var update = _builder.BuildWithRingRadii(_x, _y, _z, core.RestLengths, _ringRadii, _broken, _vertices, _indices);

            // The builder writes positions relative to its origin (the first particle); move them back to local space.
            float ox = update.Origin.X, oy = update.Origin.Y, oz = update.Origin.Z;
            if (ox != 0f || oy != 0f || oz != 0f)
            {
                for (int v = 0; v < update.VertexCount; v++)
                {
                    _vertices[v].PX += ox;
                    _vertices[v].PY += oy;
                    _vertices[v].PZ += oz;
                }
            }
            var min = new Vector3(update.BoundsMin.X + ox, update.BoundsMin.Y + oy, update.BoundsMin.Z + oz);
            var max = new Vector3(update.BoundsMax.X + ox, update.BoundsMax.Y + oy, update.BoundsMax.Z + oz);
            Bounds = new Bounds((min + max) * 0.5f, max - min);

            // A new index array always comes with resized = true, so the uploaded indices are the current ones otherwise.
            bool changed = resized || update.TopologyChanged || VertexCount != update.VertexCount || IndexCount != update.IndexCount;
            VertexCount = update.VertexCount;
            IndexCount = update.IndexCount;
            TubeIndexCount = update.TubeIndexCount;
            return changed;
        }

        /// <summary>The package's burr texture (256 × 64 RGBA32, 16 strands, polyamide beige), from the core generator.</summary>
        public static Texture2D CreateBurrTexture()
        {
            const int width = 256, height = 64;
            var pixels = new byte[BurrTextureGenerator.ByteCount(width, height)];
            BurrTextureGenerator.Generate(width, height, 16, 1u, 214, 200, 160, pixels);
            var texture = new Texture2D(width, height, TextureFormat.RGBA32, mipChain: false)
            {
                name = "Elastic Rope Burr (generated)",
                hideFlags = HideFlags.DontSave,
                wrapMode = TextureWrapMode.Repeat,
                filterMode = FilterMode.Bilinear,
            };
            texture.SetPixelData(pixels, 0);
            texture.Apply(updateMipmaps: false, makeNoLongerReadable: true);
            return texture;
        }
    }
}
