using System;
using System.Collections.Generic;
using HookeRope.Geometry;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// <see cref="TubeMeshSettings.RingTolerance"/> (issue 18): the adaptive rings' tolerance times the setting. The drawn
    /// surface stays within the polygon's own depth plus the scaled tolerance of the smooth tube, measured both ways; the
    /// ring count of a bent segment falls as 1/sqrt(scale) (rounded up, at least one); the goal lanyard draws fewer
    /// vertices; a new value on a running simulation takes effect without a new builder or any allocation.
    /// </summary>
    public sealed class RingToleranceTests
    {
        private const float R = 0.01f;

        private static IEnumerable<TestCaseData> Cases()
        {
            foreach (int radial in new[] { 8, 16 })
                foreach (float scale in new[] { 2f, 4f })
                    foreach (string shape in new[] { "lanyard", "helix", "u-turn", "wave" })
                        yield return new TestCaseData(shape, radial, scale);
        }

        [TestCaseSource(nameof(Cases))]
        public void ALooserToleranceDrawsFewerRingsWithinItsBound(string name, int radial, float scale)
        {
            RopeShape shape = AdaptiveRingsTests.Shape(name);
            int n = shape.Segments;
            // without the ring budget, so the counts are the placement's own (AdaptiveRingsTests for the budget)
            var exact = TubeMeshBuilder.Adaptive(new TubeMeshSettings { RadialSegments = radial }, n, R, null, AdaptiveRings.MaxRingsPerSegment);
            var loose = TubeMeshBuilder.Adaptive(new TubeMeshSettings { RadialSegments = radial, RingTolerance = scale }, n, R, null, AdaptiveRings.MaxRingsPerSegment);
            AdaptiveRingsTests.BuildAdaptive(exact, shape, R, new bool[n], out _, out _);
            AdaptiveRingsTests.BuildAdaptive(loose, shape, R, new bool[n], out var vertices, out _);
            Assert.That(loose.ToleranceFraction, Is.EqualTo(RingNeed.Tolerance(radial) * scale), "the tolerance is the polygon's depth times the setting");
            double polygon = R * (1.0 - Math.Cos(Math.PI / radial));
            double bound = polygon + loose.ToleranceFraction * R;
            double deviation = TubeDeviation.Largest(shape, R, loose.Layout, radial, vertices, out _, out _);
            int before = exact.Layout.RingCount, after = loose.Layout.RingCount;
            TestContext.WriteLine($"{name}, {radial} sides, tolerance ×{scale}: {before} → {after} rings ({n} segments), " +
                                  $"deviation {deviation / R:F4} R, bound {bound / R:F4} R");
            Assert.That(deviation, Is.LessThanOrEqualTo(bound * 1.0001 + 1e-7), "within the scaled bound");
            // each segment's count is max(1, ⌈need/sqrt(scale)⌉) with need ≤ its count at scale 1
            Assert.That(after, Is.LessThanOrEqualTo(before / Math.Sqrt(scale) + n + 1));
            Assert.That(after, Is.GreaterThanOrEqualTo(n + 1), "at least one ring per segment");
            if (before > 2 * (n + 1)) Assert.That(after, Is.LessThan(before), "a bent rope draws fewer rings");
            else Assert.That(after, Is.LessThanOrEqualTo(before));
        }

        [Test]
        public void TheGoalLanyardDrawsFewerVerticesAndANewValueAllocatesNothing()
        {
            // the goal scene's lanyard (defaults, 16 sides) in the bench's window, at tolerance 1 and 2
            var settings = new RopeSettings { SegmentCount = 64 };
            var exact = GoalLanyard.Pinned(settings, 0f, 1.8f);
            var loose = GoalLanyard.Pinned(new RopeSettings { SegmentCount = 64 }, 0f, 1.8f);
            exact.MeshSettings.RadialSegments = 16;
            loose.MeshSettings.RadialSegments = 16;
            loose.MeshSettings.RingTolerance = 2f;
            int exactMost = 0, looseMost = 0;
            for (int frame = 1; frame <= 74; frame++)
            {
                exact.Step(1f / 90f);
                loose.Step(1f / 90f);
                if (frame <= 44) continue;
                exactMost = Math.Max(exactMost, Fill(exact));
                looseMost = Math.Max(looseMost, Fill(loose));
            }
            TestContext.WriteLine($"goal lanyard, frames 45-74: most vertices {exactMost} at tolerance 1, {looseMost} at 2");
            Assert.That(looseMost, Is.LessThan(exactMost));
            // read at every build: the same builder and buffers (made for the ring budget's cap) take a new value each frame
            var builder = exact.Mesh.Builder;
            var vertices = new TubeVertex[exact.GetVertexCapacity()];
            var indices = new int[exact.GetIndexCapacity()];
            float[] scales = { 4f, 1f, 2f, 4f };
            int calls = 0, fewest = int.MaxValue;
            long bytes = SteadyStateAllocation.Bytes(() =>
            {
                exact.MeshSettings.RingTolerance = scales[calls++ % scales.Length];
                exact.Step(1f / 90f);
                fewest = Math.Min(fewest, exact.FillMesh(vertices, indices).VertexCount);
            }, 40);
            TestContext.WriteLine($"tolerance changed every frame for 360 frames: {bytes} B allocated, fewest vertices {fewest}");
            Assert.That(bytes, Is.EqualTo(0), "a new tolerance each frame allocates nothing");
            Assert.That(exact.Mesh.Builder, Is.SameAs(builder), "no new builder");
            Assert.That(exact.GetVertexCapacity(), Is.EqualTo(vertices.Length), "the buffers keep their capacity");
            // held at 4, the budget gives the rings back after its calm spell
            exact.MeshSettings.RingTolerance = 4f;
            int held = int.MaxValue;
            for (int i = 0; i < 120; i++)
            {
                exact.Step(1f / 90f);
                held = exact.FillMesh(vertices, indices).VertexCount;
            }
            TestContext.WriteLine($"held at 4 for 120 more frames: {held} vertices");
            Assert.That(held, Is.LessThan(exactMost));
            Assert.That(() => exact.MeshSettings.RingTolerance = 0.5f, Throws.TypeOf<ArgumentOutOfRangeException>()
                .With.Message.Contain("RingTolerance").And.Message.Contain("[1, 16]"));
            Assert.That(() => exact.MeshSettings.RingTolerance = float.NaN, Throws.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(exact.MeshSettings.RingTolerance, Is.EqualTo(4f), "a rejected value leaves the setting");
        }

        private static int Fill(RopeSimulation simulation)
        {
            var update = simulation.FillMesh(new TubeVertex[simulation.GetVertexCapacity()], new int[simulation.GetIndexCapacity()]);
            return update.VertexCount;
        }
    }
}
