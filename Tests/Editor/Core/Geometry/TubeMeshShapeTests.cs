using System;
using HookeRope.Geometry;
using HookeRope.Radius;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    public sealed class TubeMeshShapeTests
    {
        private const float R = 0.01f;

        [Test]
        public void StraightRopeNormalsPointOutwardAndCapsAlongTheAxis()
        {
            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = 16, RingsPerSegment = 4 }, 6);
            var shape = RopeShape.Straight(6, 0.1f, 1f, 1f, 2f, 3f);
            var update = TubeMeshTopologyTests.Build(builder, shape, R, new bool[6], out var vertices, out var indices);
            float ax = 1f / MathF.Sqrt(14f), ay = 2f * ax, az = 3f * ax;
            int capVertices = 17;
            for (int i = 0; i < update.VertexCount; i++)
            {
                TubeVertex v = vertices[i];
                float along = v.PX * ax + v.PY * ay + v.PZ * az;
                bool startCap = i < capVertices, endCap = i >= update.VertexCount - capVertices;
                if (startCap || endCap)
                {
                    float nDotAxis = v.NX * ax + v.NY * ay + v.NZ * az;
                    Assert.That(nDotAxis, Is.EqualTo(startCap ? -1f : 1f).Within(1e-5), "cap vertex " + i);
                    continue;
                }
                float rx = v.PX - along * ax, ry = v.PY - along * ay, rz = v.PZ - along * az;
                float distance = MathF.Sqrt(rx * rx + ry * ry + rz * rz);
                Assert.That(distance, Is.EqualTo(R).Within(1e-6));
                Assert.That((v.NX * rx + v.NY * ry + v.NZ * rz) / distance, Is.EqualTo(1f).Within(1e-5), "vertex " + i);
            }
            MeshChecks.Faces(vertices, indices, 0, update.IndexCount, out double area, out double alignment);
            Assert.That(alignment, Is.GreaterThan(0.95));
            Assert.That(MeshChecks.Volume(vertices, indices, 0, update.IndexCount), Is.GreaterThan(0.0));
        }

        [Test]
        public void CurvedRopeFacesAreWoundOutward()
        {
            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = 8, RingsPerSegment = 4 }, 30);
            var update = TubeMeshTopologyTests.Build(builder, RopeShape.Helix(30, 0.05f, 0.1f, 0.05f), R, new bool[30], out var vertices, out var indices);
            MeshChecks.Faces(vertices, indices, 0, update.IndexCount, out _, out double alignment);
            Assert.That(alignment, Is.GreaterThan(0.8));
            Assert.That(MeshChecks.Volume(vertices, indices, 0, update.IndexCount), Is.GreaterThan(0.0));
        }

        [TestCase(0.5, 1.0)]
        [TestCase(0.3, 1.24)]
        [TestCase(0.0, 1.6)]
        public void MeshVolumeAtOnePointSixStretchFollowsPoissonRatio(double nu, double expectedRatio)
        {
            const int n = 20;
            var settings = new RadiusSettings { NeckRadiusFraction = 0.8f, PoissonRatio = (float)nu, Necking = false, Fracture = false };
            var rest = RopeShape.Straight(n, 0.1f, 1f, 0.3f, -1f, 0.2f);
            var stretched = RopeShape.Straight(n, 0.1f, 1.6f, 0.3f, -1f, 0.2f);
            double restVolume = Volume(settings, rest);
            double stretchedVolume = Volume(settings, stretched);
            // Volume ratio of eq. 16: (r/R)²·λ = 1 + (1 − 2ν)(λ − 1).
            Assert.That(stretchedVolume / restVolume, Is.EqualTo(expectedRatio).Within(0.005 * expectedRatio));
            TestContext.WriteLine("nu = " + nu + ": volume ratio " + (stretchedVolume / restVolume).ToString("F6"));
        }

        private static double Volume(RadiusSettings settings, RopeShape shape)
        {
            var model = new RadiusModel(settings, R, shape.Rest);
            var lengths = new float[shape.Segments];
            for (int j = 0; j < shape.Segments; j++)
            {
                float dx = shape.X[j + 1] - shape.X[j], dy = shape.Y[j + 1] - shape.Y[j], dz = shape.Z[j + 1] - shape.Z[j];
                lengths[j] = MathF.Sqrt(dx * dx + dy * dy + dz * dz);
            }
            model.Update(lengths, ReadOnlySpan<bool>.Empty);
            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = 16 }, shape.Segments);
            var radii = new float[builder.Layout.RingCount];
            model.FillRingRadii(builder.Layout.RingSegments, builder.Layout.RingFractions, radii);
            var vertices = new TubeVertex[builder.GetVertexCount(ReadOnlySpan<bool>.Empty)];
            var indices = new int[builder.GetIndexCount(ReadOnlySpan<bool>.Empty)];
            var update = builder.BuildWithRingRadii(shape.X, shape.Y, shape.Z, shape.Rest, radii, ReadOnlySpan<bool>.Empty, vertices, indices);
            return MeshChecks.Volume(vertices, indices, 0, update.IndexCount);
        }

        private static RopeShape[] ExtremeShapes()
        {
            return new[]
            {
                RopeShape.Collapsed(12, 0.1f),
                RopeShape.PairsCoincident(12, 0.1f),
                RopeShape.Folded(12, 0.1f),
                RopeShape.Straight(12, 0.1f, 10f, 0f, 0f, 1f),
                RopeShape.UTurn(12, 0.1f, 0.5f * R),
                RopeShape.Straight(12, 0.1f, 0f, 1f, 0f, 0f),
            };
        }

        [Test]
        public void ExtremeShapesGiveNoNaNAndNoDegenerateTriangles()
        {
            double smallest = double.MaxValue;
            int[] radialCounts = { 3, 16, 64 };
            int[] ringCounts = { 1, 4 };
            foreach (RopeShape shape in ExtremeShapes())
            {
                foreach (int radial in radialCounts)
                {
                    foreach (int rings in ringCounts)
                    {
                        foreach (bool withBreak in new[] { false, true })
                        {
                            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = radial, RingsPerSegment = rings }, shape.Segments);
                            var broken = new bool[shape.Segments];
                            broken[5] = withBreak;
                            float radius = shape.X[12] - shape.X[0] > 5f ? R / MathF.Sqrt(10f) : R;
                            var update = TubeMeshTopologyTests.Build(builder, shape, radius, broken, out var vertices, out var indices);
                            Assert.That(MeshChecks.AllFiniteAndUnit(vertices, update.VertexCount), Is.True);
                            MeshChecks.Faces(vertices, indices, 0, update.IndexCount, out double area, out _);
                            smallest = Math.Min(smallest, area / (radius * radius));
                            for (int i = 0; i < update.VertexCount; i++)
                            {
                                Assert.That(vertices[i].PX, Is.InRange(update.BoundsMin.X, update.BoundsMax.X));
                                Assert.That(vertices[i].PY, Is.InRange(update.BoundsMin.Y, update.BoundsMax.Y));
                                Assert.That(vertices[i].PZ, Is.InRange(update.BoundsMin.Z, update.BoundsMax.Z));
                            }
                        }
                    }
                }
            }
            TestContext.WriteLine("smallest triangle area / r² = " + smallest.ToString("E3"));
            Assert.That(smallest, Is.GreaterThan(1e-6));
        }

        [Test]
        public void NonFiniteInputsNeverReachTheMesh()
        {
            var shape = RopeShape.Helix(12, 0.05f, 0.1f, 0.05f);
            shape.X[4] = float.NaN;
            shape.Y[7] = float.PositiveInfinity;
            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = 8 }, 12);
            var radii = new float[12];
            Array.Fill(radii, R);
            radii[2] = float.NaN;
            radii[9] = -1f;
            var broken = new bool[12];
            broken[10] = true;
            var vertices = new TubeVertex[builder.GetVertexCount(broken)];
            var indices = new int[builder.GetIndexCount(broken)];
            var update = builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, radii, broken, vertices, indices);
            Assert.That(MeshChecks.AllFiniteAndUnit(vertices, update.VertexCount), Is.True);
            Assert.That(float.IsFinite(update.BoundsMin.X) && float.IsFinite(update.BoundsMax.Y), Is.True);

            var model = new RadiusModel(new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, BreakStrain = 1000f }, R, shape.Rest);
            var lengths = new float[12];
            Array.Fill(lengths, 0.06f);
            lengths[3] = float.NaN;
            lengths[5] = float.PositiveInfinity;
            model.Update(lengths, ReadOnlySpan<bool>.Empty);
            for (int i = 0; i <= 12; i++) Assert.That(float.IsFinite(model.ParticleRadii[i]) && model.ParticleRadii[i] > 0f, Is.True, "particle " + i);
            Assert.That(model.SegmentRadii[3], Is.EqualTo(R)); // a non-finite length counts as unstretched
        }

        [Test]
        public void ParallelTransportDoesNotTwist()
        {
            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = 8, RingsPerSegment = 4 }, 30);
            var update = TubeMeshTopologyTests.Build(builder, RopeShape.UTurn(30, 0.05f, 0.1f), R, new bool[30], out var vertices, out _);
            // Vertex 0 of each ring points along that ring's normal; consecutive normals turn no more than the tangent does.
            int stride = 9;
            int rings = builder.Layout.RingCount;
            var centers = new double[rings, 3];
            for (int k = 0; k < rings; k++)
                for (int i = 0; i < 8; i++)
                {
                    TubeVertex v = vertices[stride + stride * k + i];
                    centers[k, 0] += v.PX / 8.0; centers[k, 1] += v.PY / 8.0; centers[k, 2] += v.PZ / 8.0;
                }
            double worstExcess = double.MinValue;
            for (int k = 2; k + 2 < rings; k++)
            {
                TubeVertex p = vertices[stride + stride * k], c = vertices[stride + stride * (k + 1)];
                double normalTurn = Math.Acos(Math.Min(1.0, p.NX * c.NX + p.NY * c.NY + p.NZ * c.NZ));
                double tangentTurn = Angle(centers, k - 1, k + 1, k, k + 2);
                worstExcess = Math.Max(worstExcess, normalTurn - tangentTurn);
            }
            TestContext.WriteLine("worst normal turn beyond tangent turn: " + worstExcess.ToString("E3") + " rad");
            Assert.That(worstExcess, Is.LessThanOrEqualTo(1e-3));
            // In-plane U-turn: the transported frame keeps the out-of-plane axis, so ring tangents (around) of vertex 0
            // stay ±z or the normal stays ±z all along: no flip between the first and last ring.
            TubeVertex first = vertices[stride * 1], last = vertices[stride * (rings)];
            Assert.That(Math.Abs(first.NZ), Is.EqualTo(Math.Abs(last.NZ)).Within(1e-3));
            Assert.That(first.NZ * last.NZ, Is.GreaterThanOrEqualTo(-1e-3));
        }

        private static double Angle(double[,] c, int a0, int a1, int b0, int b1)
        {
            double ax = c[a1, 0] - c[a0, 0], ay = c[a1, 1] - c[a0, 1], az = c[a1, 2] - c[a0, 2];
            double bx = c[b1, 0] - c[b0, 0], by = c[b1, 1] - c[b0, 1], bz = c[b1, 2] - c[b0, 2];
            double dot = (ax * bx + ay * by + az * bz) / Math.Sqrt((ax * ax + ay * ay + az * az) * (bx * bx + by * by + bz * bz));
            return Math.Acos(Math.Max(-1.0, Math.Min(1.0, dot)));
        }

        [Test]
        public void VFollowsRestArcLengthAndUGoesAround()
        {
            var settings = new TubeMeshSettings { RadialSegments = 8, RingsPerSegment = 2, VPerMetre = 4f };
            var builder = new TubeMeshBuilder(settings, 5);
            var slack = TubeMeshTopologyTests.Build(builder, RopeShape.Straight(5, 0.2f, 1f, 1f, 0f, 0f), R, new bool[5], out var restVertices, out _);
            TubeMeshTopologyTests.Build(builder, RopeShape.Straight(5, 0.2f, 3f, 1f, 0f, 0f), R, new bool[5], out var stretchedVertices, out _);
            int stride = 9, capVertices = 9;
            for (int k = 0; k < builder.Layout.RingCount; k++)
            {
                double restArc = 0.1 * k;
                for (int i = 0; i < stride; i++)
                {
                    TubeVertex a = restVertices[capVertices + k * stride + i];
                    Assert.That(a.V, Is.EqualTo(4.0 * restArc).Within(1e-5));
                    Assert.That(stretchedVertices[capVertices + k * stride + i].V, Is.EqualTo(a.V));
                    Assert.That(a.U, Is.EqualTo(i / 8.0).Within(1e-7));
                }
            }
            Assert.That(slack.BoundsMax.X, Is.EqualTo(1f).Within(1e-6));
        }

        [Test]
        public void NormalsTiltForAVaryingRadius()
        {
            // A cone: radius falls linearly from 20 mm to 10 mm over 1 m; slope dr/ds = −0.01.
            const int n = 10;
            var shape = RopeShape.Straight(n, 0.1f, 1f, 0f, 1f, 0f);
            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = 12, RingsPerSegment = 2 }, n);
            var radii = new float[builder.Layout.RingCount];
            for (int k = 0; k < radii.Length; k++) radii[k] = 0.02f - 0.01f * k / (radii.Length - 1);
            var vertices = new TubeVertex[builder.GetVertexCount(ReadOnlySpan<bool>.Empty)];
            var indices = new int[builder.GetIndexCount(ReadOnlySpan<bool>.Empty)];
            builder.BuildWithRingRadii(shape.X, shape.Y, shape.Z, shape.Rest, radii, ReadOnlySpan<bool>.Empty, vertices, indices);
            double expected = 0.01 / Math.Sqrt(1.0 + 0.01 * 0.01);
            for (int k = 0; k < radii.Length; k++)
                for (int i = 0; i < 13; i++)
                    Assert.That(vertices[13 + 13 * k + i].NY, Is.EqualTo(expected).Within(1e-5));
        }

        [Test]
        public void VerticesAndBoundsAreInTheFrameOfTheInputPositions()
        {
            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = 16 }, 8);
            var near = RopeShape.Straight(8, 0.125f, 1f, 1f, 0f, 0f);
            var far = RopeShape.Straight(8, 0.125f, 1f, 1f, 0f, 0f, 8192f, -4096f, 16384f);
            var a = TubeMeshTopologyTests.Build(builder, near, R, new bool[8], out var nearVertices, out _);
            var b = TubeMeshTopologyTests.Build(builder, far, R, new bool[8], out var farVertices, out _);
            Assert.That(nearVertices[0].PX, Is.EqualTo(0f));
            // Far out, a float holds 2^-9 m at 16384 m: the vertices are the near ones, shifted, to that precision.
            for (int i = 0; i < a.VertexCount; i++)
            {
                Assert.That(farVertices[i].PX, Is.EqualTo(nearVertices[i].PX + 8192f).Within(2e-3));
                Assert.That(farVertices[i].PY, Is.EqualTo(nearVertices[i].PY - 4096f).Within(2e-3));
                Assert.That(farVertices[i].PZ, Is.EqualTo(nearVertices[i].PZ + 16384f).Within(2e-3));
                Assert.That(farVertices[i].PX, Is.InRange(b.BoundsMin.X, b.BoundsMax.X));
                Assert.That(farVertices[i].PZ, Is.InRange(b.BoundsMin.Z, b.BoundsMax.Z));
            }
            Assert.That(a.BoundsMin.X, Is.EqualTo(b.BoundsMin.X - 8192f).Within(2e-3));
        }
    }
}
