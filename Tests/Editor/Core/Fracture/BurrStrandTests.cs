using System;
using HookeRope.Fracture;
using HookeRope.Geometry;
using HookeRope.Tests.Core.Geometry;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Fracture
{
    public sealed class BurrStrandTests
    {
        private const float R = 0.01f;

        private static TubeMeshUpdate BuildBroken(uint seed, int radial, out TubeVertex[] vertices, out int[] indices)
        {
            var settings = new TubeMeshSettings { RadialSegments = radial, RingsPerSegment = 2 };
            settings.Burr.Seed = seed;
            var builder = new TubeMeshBuilder(settings, 10);
            var broken = new bool[10];
            broken[6] = true;
            var shape = RopeShape.Straight(10, 0.1f, 1f, 0f, 0f, 1f);
            return TubeMeshTopologyTests.Build(builder, shape, R, broken, out vertices, out indices);
        }

        [Test]
        public void SameSeedGivesAnIdenticalBurr()
        {
            var a = BuildBroken(42u, 16, out var first, out var firstIndices);
            var b = BuildBroken(42u, 16, out var second, out var secondIndices);
            Assert.That(a.VertexCount, Is.EqualTo(b.VertexCount));
            for (int i = 0; i < a.VertexCount; i++)
            {
                Assert.That(second[i].PX, Is.EqualTo(first[i].PX));
                Assert.That(second[i].PY, Is.EqualTo(first[i].PY));
                Assert.That(second[i].PZ, Is.EqualTo(first[i].PZ));
                Assert.That(second[i].NX, Is.EqualTo(first[i].NX));
            }
            Assert.That(secondIndices, Is.EqualTo(firstIndices));
        }

        [Test]
        public void DifferentSeedsGiveDifferentBurrs()
        {
            var a = BuildBroken(1u, 16, out var first, out _);
            BuildBroken(2u, 16, out var second, out _);
            int strandStart = a.VertexCount - 2 * 16 * 9;
            int differing = 0;
            double largest = 0.0;
            for (int i = 0; i < a.VertexCount; i++)
            {
                double d = Math.Abs(second[i].PX - first[i].PX) + Math.Abs(second[i].PY - first[i].PY) + Math.Abs(second[i].PZ - first[i].PZ);
                if (d > 0.0) differing++;
                largest = Math.Max(largest, d);
            }
            Assert.That(differing, Is.GreaterThan(16)); // at least one tip per strand of one end
            Assert.That(largest, Is.GreaterThan(0.1 * R));
            Assert.That(strandStart, Is.GreaterThan(0));
        }

        [TestCase(8)]
        [TestCase(16)]
        [TestCase(32)]
        public void OneStrandPerRadialSegmentWithSeededLengthsPointingAwayFromTheRope(int radial)
        {
            var update = BuildBroken(7u, radial, out var vertices, out var indices);
            Assert.That(update.BurrIndexCount, Is.EqualTo(2 * radial * 9)); // two broken ends, three faces per strand
            var burr = new BurrSettings();
            // Broken segment 6 along +z: the lower piece ends at z = 0.6, the upper starts at z = 0.7.
            double shortest = double.MaxValue, longest = 0.0;
            for (int t = update.TubeIndexCount; t < update.IndexCount; t += 9)
            {
                TubeVertex b0 = vertices[indices[t]], b1 = vertices[indices[t + 1]], tip = vertices[indices[t + 2]];
                TubeVertex b2 = vertices[indices[t + 3 + 1]];
                bool lower = b0.PZ < 0.65f;
                double cz = (b0.PZ + b1.PZ + b2.PZ) / 3.0, cx = (b0.PX + b1.PX + b2.PX) / 3.0, cy = (b0.PY + b1.PY + b2.PY) / 3.0;
                double dz = tip.PZ - cz;
                double length = Math.Sqrt((tip.PX - cx) * (tip.PX - cx) + (tip.PY - cy) * (tip.PY - cy) + dz * dz);
                Assert.That(lower ? dz : -dz, Is.GreaterThan(0.0), "the strand leaves the broken end outward");
                // Base width: one radial segment of the end ring, 2 r sin(π/S): finer meshes give finer burrs.
                double width = Math.Sqrt((b1.PX - b0.PX) * (b1.PX - b0.PX) + (b1.PY - b0.PY) * (b1.PY - b0.PY) + (b1.PZ - b0.PZ) * (b1.PZ - b0.PZ));
                Assert.That(width, Is.EqualTo(2.0 * R * Math.Sin(Math.PI / radial)).Within(1e-6));
                shortest = Math.Min(shortest, length);
                longest = Math.Max(longest, length);
            }
            Assert.That(shortest, Is.GreaterThanOrEqualTo(0.35 * burr.Length * R - 1e-6));
            Assert.That(longest, Is.LessThanOrEqualTo(burr.Length * R + 1e-6));
            Assert.That(longest - shortest, Is.GreaterThan(0.2 * burr.Length * R)); // random lengths
            MeshChecks.Faces(vertices, indices, update.TubeIndexCount, update.BurrIndexCount, out double area, out _);
            Assert.That(area, Is.GreaterThan(1e-3 * R * R / radial));
        }

        [Test]
        public void BurrOffLeavesFlatClosedEndsAndNoStrandVertices()
        {
            var settings = new TubeMeshSettings { RadialSegments = 16, RingsPerSegment = 2 };
            settings.Burr.Enabled = false;
            var builder = new TubeMeshBuilder(settings, 10);
            var broken = new bool[10];
            broken[6] = true;
            var update = TubeMeshTopologyTests.Build(builder, RopeShape.Straight(10, 0.1f, 1f, 0f, 0f, 1f), R, broken, out var vertices, out var indices);
            Assert.That(update.BurrIndexCount, Is.EqualTo(0));
            Assert.That(update.VertexCount, Is.EqualTo((13 + 7) * 17 + 4 * 17));
            MeshChecks.Topology(vertices, update.VertexCount, indices, 0, update.IndexCount, out int v, out int e, out int f, out int bad, out _);
            Assert.That(bad, Is.EqualTo(0));
            Assert.That(v - e + f, Is.EqualTo(4));
        }

        [Test]
        public void StrandDrawIsAPureFunctionOfSeedEndAndIndex()
        {
            BurrStrand a = BurrStrand.Draw(9u, 13, 4, 0.6f);
            BurrStrand b = BurrStrand.Draw(9u, 13, 4, 0.6f);
            Assert.That(b.LengthFraction, Is.EqualTo(a.LengthFraction));
            Assert.That(b.Tilt, Is.EqualTo(a.Tilt));
            Assert.That(b.Twist, Is.EqualTo(a.Twist));
            double mean = 0.0;
            for (int i = 0; i < 4000; i++)
            {
                float u = SeededRandom.Unit(5u, i, 1);
                Assert.That(u, Is.InRange(0f, 0.99999994f));
                mean += u / 4000.0;
            }
            Assert.That(mean, Is.EqualTo(0.5).Within(0.02));
        }
    }
}
