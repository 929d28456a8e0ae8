using System;
using System.Runtime.InteropServices;
using HookeRope.Geometry;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    public sealed class TubeMeshTopologyTests
    {
        private const float R = 0.01f;

        internal static TubeMeshUpdate Build(TubeMeshBuilder builder, RopeShape shape, float radius, bool[] broken, out TubeVertex[] vertices, out int[] indices)
        {
            vertices = new TubeVertex[builder.GetVertexCount(broken)];
            indices = new int[builder.GetIndexCount(broken)];
            var radii = new float[shape.Segments];
            Array.Fill(radii, radius);
            return builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, radii, broken, vertices, indices);
        }

        [Test]
        public void VertexIsTwelvePackedFloatsInUnityStreamOrder()
        {
            Assert.That(Marshal.SizeOf<TubeVertex>(), Is.EqualTo(48));
            Assert.That(TubeVertex.SizeInBytes, Is.EqualTo(48));
            string[] order = { "PX", "PY", "PZ", "NX", "NY", "NZ", "TX", "TY", "TZ", "TW", "U", "V" };
            for (int i = 0; i < order.Length; i++)
                Assert.That((int)Marshal.OffsetOf<TubeVertex>(order[i]), Is.EqualTo(4 * i), order[i]);
        }

        [TestCase(3, 1)]
        [TestCase(8, 4)]
        [TestCase(16, 4)]
        [TestCase(32, 2)]
        [TestCase(64, 1)]
        public void IntactMeshIsWatertightWithEulerCharacteristicTwo(int radial, int rings)
        {
            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = radial, RingsPerSegment = rings }, 24);
            var update = Build(builder, RopeShape.Helix(24, 0.05f, 0.1f, 0.08f), R, new bool[24], out var vertices, out var indices);
            MeshChecks.Topology(vertices, update.VertexCount, indices, 0, update.IndexCount, out int v, out int e, out int f, out int badEdges, out int badDirections);
            Assert.That(badEdges, Is.EqualTo(0), "edges not shared by exactly two triangles");
            Assert.That(badDirections, Is.EqualTo(0), "inconsistent winding");
            Assert.That(v - e + f, Is.EqualTo(2));
            Assert.That(update.BurrIndexCount, Is.EqualTo(0));
            int ringCount = 24 * rings + 1;
            Assert.That(update.VertexCount, Is.EqualTo(ringCount * (radial + 1) + 2 * (radial + 1)));
            Assert.That(update.IndexCount, Is.EqualTo((ringCount - 1) * radial * 6 + 2 * radial * 3));
        }

        [Test]
        public void BrokenRopeIsTwoClosedPiecesAndCountsMatchTheQueries()
        {
            var settings = new TubeMeshSettings { RadialSegments = 12, RingsPerSegment = 3 };
            var builder = new TubeMeshBuilder(settings, 10);
            var broken = new bool[10];
            broken[4] = true;
            var update = Build(builder, RopeShape.Straight(10, 0.1f, 1f, 0f, -1f, 0f), R, broken, out var vertices, out var indices);
            Assert.That(update.VertexCount, Is.EqualTo(builder.GetVertexCount(broken)));
            Assert.That(update.IndexCount, Is.EqualTo(builder.GetIndexCount(broken)));
            Assert.That(update.BurrIndexCount, Is.EqualTo(2 * 12 * 9));
            MeshChecks.Topology(vertices, update.VertexCount, indices, 0, update.TubeIndexCount, out int v, out int e, out int f, out int badEdges, out int badDirections);
            Assert.That(badEdges, Is.EqualTo(0));
            Assert.That(badDirections, Is.EqualTo(0));
            Assert.That(v - e + f, Is.EqualTo(4)); // two spheres
            // Rings of the broken segment are gone: (4·3 + 1) + (5·3 + 1) rings.
            Assert.That(update.VertexCount, Is.EqualTo((13 + 16) * 13 + 4 * 13 + 2 * 12 * 9));
        }

        [Test]
        public void IndicesAreRewrittenOnlyWhenTheTopologyChanges()
        {
            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = 16 }, 8);
            var shape = RopeShape.Straight(8, 0.1f, 1.2f, 1f, 0f, 0f);
            var broken = new bool[8];
            var radii = new float[8];
            Array.Fill(radii, R);
            var vertices = new TubeVertex[builder.GetVertexCount(broken)];
            var indices = new int[builder.GetIndexCount(broken)];
            Assert.That(builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, radii, broken, vertices, indices).TopologyChanged, Is.True);
            indices[0] = -7; // a second build must not touch the index buffer
            Assert.That(builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, radii, broken, vertices, indices).TopologyChanged, Is.False);
            Assert.That(indices[0], Is.EqualTo(-7));
            var other = new int[indices.Length];
            Assert.That(builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, radii, broken, vertices, other).TopologyChanged, Is.True);
            broken[2] = true;
            vertices = new TubeVertex[builder.GetVertexCount(broken)];
            other = new int[builder.GetIndexCount(broken)];
            Assert.That(builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, radii, broken, vertices, other).TopologyChanged, Is.True);
            Assert.That(builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, radii, broken, vertices, other).TopologyChanged, Is.False);
        }

        [Test]
        public void MeshUpdateAllocatesNothing()
        {
            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = 16 }, 50);
            var shape = RopeShape.Helix(50, 0.05f, 0.2f, 0.1f);
            var broken = new bool[50];
            broken[20] = true;
            var radii = new float[50];
            Array.Fill(radii, R);
            var vertices = new TubeVertex[builder.GetVertexCount(broken)];
            var indices = new int[builder.GetIndexCount(broken)];
            int frame = 0;
            long bytes = SteadyStateAllocation.Bytes(() =>
            {
                shape.X[3] = 0.1f + 1e-4f * (frame++ % 100);
                builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, radii, broken, vertices, indices);
            }, 50);
            Assert.That(bytes, Is.EqualTo(0));
        }

        [Test]
        public void BadInputThrowsNamingTheParameterAndRange()
        {
            var settings = new TubeMeshSettings { RadialSegments = 16 };
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.RadialSegments = 2).Message, Does.Contain("RadialSegments").And.Contain("[3, 64]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.RadialSegments = 65).ParamName, Is.EqualTo("RadialSegments"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.RingsPerSegment = 0).Message, Does.Contain("[1, 64]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.VPerMetre = float.NaN).ParamName, Is.EqualTo("VPerMetre"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.Burr.FibreLength = 0f).Message, Does.Contain("FibreLength").And.Contain("(0, 5]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.Burr.FibreLength = 5.5f).ParamName, Is.EqualTo("FibreLength"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.Burr.FibreLengthSpread = -0.1f).Message, Does.Contain("FibreLengthSpread").And.Contain("[0, 2]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.Burr.FibreDensity = 0.5f).Message, Does.Contain("FibreDensity").And.Contain("[1, 400]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.Burr.FibreDensity = float.NaN).ParamName, Is.EqualTo("FibreDensity"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => settings.Burr.Spread = float.PositiveInfinity).ParamName, Is.EqualTo("Spread"));

            var builder = new TubeMeshBuilder(settings, 4);
            var shape = RopeShape.Straight(4, 0.1f, 1f, 1f, 0f, 0f);
            var radii = new float[4];
            var small = new TubeVertex[3];
            var indices = new int[10000];
            var e = Assert.Throws<ArgumentException>(() => builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, radii, ReadOnlySpan<bool>.Empty, small, indices));
            Assert.That(e.ParamName, Is.EqualTo("vertices"));
            e = Assert.Throws<ArgumentException>(() => builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, new float[3], ReadOnlySpan<bool>.Empty, new TubeVertex[1000], indices));
            Assert.That(e.ParamName, Is.EqualTo("segmentRadii"));
        }
    }
}
