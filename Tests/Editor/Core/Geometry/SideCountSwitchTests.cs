using System;
using System.Runtime.InteropServices;
using HookeRope.Geometry;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// A rope's mesh switched between two side counts (as <see cref="ViewDetail.RadialSegments"/> switches a far rope):
    /// the other count's builder is kept, so switching back allocates nothing, and a builder taken up again writes every
    /// vertex and index, even where the rope did not move since it last drew (its caches would say "unchanged" while the
    /// buffers hold the other count's mesh).
    /// </summary>
    public sealed class SideCountSwitchTests
    {
        private static RopeSimulation Lanyard()
        {
            var simulation = GoalLanyard.Pinned(new RopeSettings { SegmentCount = 64 }, 0f, 1.8f);
            simulation.MeshSettings.RadialSegments = 16;
            for (int frame = 0; frame < 60; frame++) simulation.Step(1f / 90f);
            return simulation;
        }

        [Test]
        public void ABuilderTakenUpAgainRewritesTheBuffersOfTheOtherSideCount()
        {
            var simulation = Lanyard();
            var vertices = new TubeVertex[Math.Max(simulation.GetVertexCapacity(), 4 * 64 * 17)];
            var indices = new int[Math.Max(simulation.GetIndexCapacity(), 4 * 64 * 16 * 6)];
            // the rope does not move between the fills: only the side count changes
            var first = simulation.FillMesh(vertices, indices);
            var sixteen = simulation.Mesh.Builder;
            var expectedVertices = vertices.AsSpan(0, first.VertexCount).ToArray();
            var expectedIndices = indices.AsSpan(0, first.IndexCount).ToArray();

            simulation.MeshSettings.RadialSegments = 8;
            var eight = simulation.FillMesh(vertices, indices);
            var eightBuilder = simulation.Mesh.Builder;
            Assert.That(eightBuilder, Is.Not.SameAs(sixteen));
            Assert.That(eight.VertexCount, Is.LessThan(first.VertexCount));
            Assert.That(eight.TopologyChanged, Is.True);

            simulation.MeshSettings.RadialSegments = 16;
            int topology = simulation.MeshTopologyVersion;
            var again = simulation.FillMesh(vertices, indices);
            Assert.That(simulation.Mesh.Builder, Is.SameAs(sixteen), "the 16-sided builder again, not a new one");
            Assert.That(again.TopologyChanged, Is.True, "the caller re-uploads the indices");
            Assert.That(again.VertexCount, Is.EqualTo(first.VertexCount));
            Assert.That(again.IndexCount, Is.EqualTo(first.IndexCount));
            bool sameVertices = MemoryMarshal.AsBytes(vertices.AsSpan(0, first.VertexCount)).SequenceEqual(MemoryMarshal.AsBytes(expectedVertices.AsSpan()));
            bool sameIndices = indices.AsSpan(0, first.IndexCount).SequenceEqual(expectedIndices);
            Assert.That(sameVertices && sameIndices, Is.True, "the same mesh as before the switch, bit for bit: every vertex and index written again");

            simulation.MeshSettings.RadialSegments = 8;
            simulation.FillMesh(vertices, indices);
            Assert.That(simulation.Mesh.Builder, Is.SameAs(eightBuilder), "and the 8-sided one");
        }

        [Test]
        public void ABuilderTakenUpAgainOnASwingingRopePlansItsRingsFromTheRopeAsItIsNow()
        {
            // 16 sides for 30 frames of the swing, 8 for the next 60, then 16 again: the 16-sided builder's budget must
            // start from the rope's present need (primed like a new builder), not from where it left off 60 frames ago
            var simulation = Lanyard();
            var vertices = new TubeVertex[Math.Max(simulation.GetVertexCapacity(), 4 * 64 * 17)];
            var indices = new int[Math.Max(simulation.GetIndexCapacity(), 4 * 64 * 16 * 6)];
            for (int frame = 0; frame < 90; frame++)
            {
                simulation.MeshSettings.RadialSegments = frame < 30 ? 16 : 8;
                simulation.Step(1f / 90f);
                simulation.FillMesh(vertices, indices);
            }
            var rope = simulation.Rope;
            var fresh = TubeMeshBuilder.Adaptive(new TubeMeshSettings { RadialSegments = 16 }, rope.SegmentCount, simulation.RestRadius, null);
            fresh.PrimeRings(rope.PositionX, rope.PositionY, rope.PositionZ, rope.BrokenSegments, false, simulation.RestRadius);
            fresh.PlanRings(rope.PositionX, rope.PositionY, rope.PositionZ, rope.BrokenSegments, false, simulation.RestRadius, vertices.Length, indices.Length);
            simulation.MeshSettings.RadialSegments = 16;
            var update = simulation.FillMesh(vertices, indices);
            TestContext.WriteLine($"back to 16 sides after 60 frames at 8: {simulation.Mesh.Builder.Layout.RingCount} rings, a new builder {fresh.Layout.RingCount}");
            Assert.That(simulation.Mesh.Builder.Layout.RingCount, Is.EqualTo(fresh.Layout.RingCount), "the rings a new builder would draw now");
            Assert.That(update.VertexCount, Is.EqualTo(fresh.GetVertexCount(rope.BrokenSegments)));
        }

        [Test]
        public void SwitchingBackAndForthAllocatesNothing()
        {
            var simulation = Lanyard();
            var vertices = new TubeVertex[simulation.GetVertexCapacity()];
            var indices = new int[simulation.GetIndexCapacity()];
            simulation.FillMesh(vertices, indices);
            simulation.MeshSettings.RadialSegments = 8;
            simulation.FillMesh(vertices, indices);
            int frame = 0, fewest = int.MaxValue, most = 0;
            long bytes = SteadyStateAllocation.Bytes(() =>
            {
                // 16 and 8 sides, switching every fifth frame, the rope swinging
                simulation.MeshSettings.RadialSegments = (frame++ / 5) % 2 == 0 ? 16 : 8;
                simulation.Step(1f / 90f);
                int count = simulation.FillMesh(vertices, indices).VertexCount;
                fewest = Math.Min(fewest, count);
                most = Math.Max(most, count);
            }, 40);
            TestContext.WriteLine($"switching every fifth frame: {bytes} B, {fewest} … {most} vertices");
            Assert.That(bytes, Is.EqualTo(0));
            Assert.That(fewest, Is.LessThan(most));
        }
    }
}
