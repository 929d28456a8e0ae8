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

        /// <summary>Builds a straight rope of rest radius R along +z broken at segment 6, with the radius-dependent fibre count.</summary>
        private static TubeMeshUpdate BuildFrayed(uint seed, int radial, out TubeVertex[] vertices, out int[] indices, out int fibres)
        {
            var settings = new TubeMeshSettings { RadialSegments = radial, RingsPerSegment = 2 };
            settings.Burr.Seed = seed;
            var builder = new TubeMeshBuilder(settings, new RingLayout(10, 2), R);
            fibres = builder.FibreCount;
            var broken = new bool[10];
            broken[6] = true;
            return TubeMeshTopologyTests.Build(builder, RopeShape.Straight(10, 0.1f, 1f, 0f, 0f, 1f), R, broken, out vertices, out indices);
        }

        [TestCase(0.01f, 8, 126)]
        [TestCase(0.006f, 8, 45)]
        [TestCase(0.003f, 16, 16)]
        [TestCase(0.003f, 8, 11)]
        [TestCase(0.1f, 8, 256)]
        [TestCase(0f, 12, 12)]
        public void FibreCountFollowsTheCrossSection(float restRadius, int radial, int expected)
        {
            // 40 fibres per cm² of π R², at least one per radial segment, at most 256.
            Assert.That(new BurrSettings().FibreCount(restRadius, radial), Is.EqualTo(expected));
        }

        [TestCase(8)]
        [TestCase(16)]
        [TestCase(32)]
        public void FibresCoverTheCutEndOnAndBothEndsShareTheLengthStatistics(int radial)
        {
            var update = BuildFrayed(7u, radial, out var vertices, out var indices, out int fibres);
            Assert.That(fibres, Is.EqualTo(126));
            Assert.That(update.BurrIndexCount, Is.EqualTo(2 * fibres * 9));
            var burr = new BurrSettings();
            // Broken segment 6 along +z: the lower piece ends at z = 0.6, the upper starts at z = 0.7.
            var lengths = new[] { new System.Collections.Generic.List<double>(), new System.Collections.Generic.List<double>() };
            double farthestBase = 0.0;
            for (int t = update.TubeIndexCount; t < update.IndexCount; t += 9)
            {
                TubeVertex b0 = vertices[indices[t]], b1 = vertices[indices[t + 1]], tip = vertices[indices[t + 2]], b2 = vertices[indices[t + 4]];
                bool lower = b0.PZ < 0.65f;
                double cx = (b0.PX + b1.PX + b2.PX) / 3.0, cy = (b0.PY + b1.PY + b2.PY) / 3.0, cz = (b0.PZ + b1.PZ + b2.PZ) / 3.0;
                double dz = tip.PZ - cz;
                Assert.That(lower ? dz : -dz, Is.GreaterThan(0.0), "the fibre leaves the broken end outward");
                farthestBase = Math.Max(farthestBase, Math.Sqrt(cx * cx + cy * cy));
                lengths[lower ? 0 : 1].Add(Math.Sqrt((tip.PX - cx) * (tip.PX - cx) + (tip.PY - cy) * (tip.PY - cy) + dz * dz) / (2.0 * R));
            }
            Assert.That(farthestBase, Is.LessThan(R), "fibre roots lie on the cut");
            double[] mean = new double[2], deviation = new double[2];
            for (int side = 0; side < 2; side++)
            {
                foreach (double l in lengths[side]) mean[side] += l / lengths[side].Count;
                foreach (double l in lengths[side]) deviation[side] += (l - mean[side]) * (l - mean[side]) / lengths[side].Count;
                deviation[side] = Math.Sqrt(deviation[side]);
            }
            double lowerCover = EndOnCoverage(vertices, indices, update, true), upperCover = EndOnCoverage(vertices, indices, update, false);
            TestContext.WriteLine(radial + " radial, " + fibres + " fibres: mean length " + mean[0] + " / " + mean[1] + " D, spread " + deviation[0] + " / " + deviation[1]
                + " D; end-on coverage " + lowerCover + " / " + upperCover);
            for (int side = 0; side < 2; side++)
            {
                Assert.That(mean[side], Is.EqualTo(burr.FibreLength).Within(0.03 * burr.FibreLength));
                Assert.That(deviation[side], Is.EqualTo(burr.FibreLengthSpread).Within(0.1 * burr.FibreLengthSpread));
            }
            Assert.That(Math.Abs(mean[0] - mean[1]), Is.LessThan(0.05 * mean[0]));
            Assert.That(Math.Abs(deviation[0] - deviation[1]), Is.LessThan(0.05 * deviation[0]));
            Assert.That(lowerCover, Is.GreaterThanOrEqualTo(0.8));
            Assert.That(upperCover, Is.GreaterThanOrEqualTo(0.8));
            MeshChecks.Faces(vertices, indices, update.TubeIndexCount, update.BurrIndexCount, out double area, out _);
            Assert.That(area, Is.GreaterThan(1e-4 * R * R));
        }

        /// <summary>Fraction of the cut's disc (radius R around the z axis) hidden by the fibres of one end seen along z.</summary>
        private static double EndOnCoverage(TubeVertex[] vertices, int[] indices, TubeMeshUpdate update, bool lower)
        {
            const int grid = 120;
            int inside = 0, covered = 0;
            for (int gy = 0; gy < grid; gy++)
            for (int gx = 0; gx < grid; gx++)
            {
                double px = R * (2.0 * (gx + 0.5) / grid - 1.0), py = R * (2.0 * (gy + 0.5) / grid - 1.0);
                if (px * px + py * py > R * R) continue;
                inside++;
                for (int t = update.TubeIndexCount; t < update.IndexCount; t += 3)
                {
                    TubeVertex a = vertices[indices[t]], b = vertices[indices[t + 1]], c = vertices[indices[t + 2]];
                    if ((a.PZ < 0.65f) != lower) continue;
                    if (InTriangle(px, py, a, b, c)) { covered++; break; }
                }
            }
            return (double)covered / inside;
        }

        private static bool InTriangle(double px, double py, TubeVertex a, TubeVertex b, TubeVertex c)
        {
            double d1 = (px - b.PX) * (a.PY - b.PY) - (a.PX - b.PX) * (py - b.PY);
            double d2 = (px - c.PX) * (b.PY - c.PY) - (b.PX - c.PX) * (py - c.PY);
            double d3 = (px - a.PX) * (c.PY - a.PY) - (c.PX - a.PX) * (py - a.PY);
            bool negative = d1 < 0 || d2 < 0 || d3 < 0, positive = d1 > 0 || d2 > 0 || d3 > 0;
            return !(negative && positive);
        }

        [Test]
        public void FibresSplayMoreAtTheRimAndTaperToATip()
        {
            var burr = new BurrSettings();
            double innerTilt = 0.0, outerTilt = 0.0;
            int inner = 0, outer = 0;
            for (int f = 0; f < 126; f++)
            {
                BurrStrand fibre = BurrStrand.Draw(burr, 3, f, 126);
                Assert.That(fibre.Tilt, Is.LessThanOrEqualTo(burr.Spread * fibre.Radial + 1e-6f));
                if (fibre.Radial < 0.5f) { innerTilt += fibre.Tilt; inner++; } else { outerTilt += fibre.Tilt; outer++; }
            }
            Assert.That(outerTilt / outer, Is.GreaterThan(2.0 * innerTilt / inner));
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
            var settings = new BurrSettings { Seed = 9u };
            BurrStrand a = BurrStrand.Draw(settings, 13, 4, 40);
            BurrStrand b = BurrStrand.Draw(settings, 13, 4, 40);
            Assert.That(b.Length, Is.EqualTo(a.Length));
            Assert.That(b.Radial, Is.EqualTo(a.Radial));
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
