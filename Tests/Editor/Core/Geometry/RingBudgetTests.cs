using System;
using System.Collections.Generic;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;
using HookeRope.World;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// Issue 18, "0 bytes per update": the adaptive rings' ring budget. A piece never holds more than its cap
    /// (<see cref="AdaptiveRings.MaxMeanRingsPerSegment"/> rings per segment plus a neck's stations), the mesh buffers
    /// are made once for that cap, and a swinging scene that keeps hitting it allocates nothing per pass while its mesh
    /// stays valid; where the cap is not hit the mesh is the same bits as without it.
    /// </summary>
    public sealed class RingBudgetTests
    {
        private const float Frame = 1f / 90f;

        /// <summary>
        /// The swinging scene: three thin 2 m cords pinned at both ends 1.8 m apart and dropped from straight, 16 sides:
        /// 64 segments of 1 mm radius, swinging freely (it hits the budget in bursts while it swings through the bottom),
        /// 32 segments of 0.5 mm and 8 segments of 1 mm radius with their first pin shaken up and down by 10 cm at 1 Hz
        /// (their coarse segments keep wanting more than the budget holds). Thin ropes want the most rings (the tolerance
        /// is a fraction of the radius) without folding tighter than their radius, so their meshes stay valid tubes.
        /// </summary>
        private sealed class SwingingScene
        {
            public readonly List<RopeSimulation> Ropes = new List<RopeSimulation>();
            private readonly List<int> shakenPins = new List<int>();
            private int frame;

            public SwingingScene()
            {
                Add(64, 0.001f, false);
                Add(32, 0.0005f, true);
                Add(8, 0.001f, true);
            }

            private void Add(int segments, float radius, bool shaken)
            {
                float x = 3f * Ropes.Count;
                var start = new Float3(x, 3f, 0f);
                var end = new Float3(x + 1.8f, 3f, 0f);
                var sim = new RopeSimulation(new RopeSettings { RestLength = 2f, SegmentCount = segments, Radius = radius },
                    start, end, null, new TubeMeshSettings { RadialSegments = 16 });
                int pin = sim.Rope.AddPin(0, start);
                sim.Rope.AddPin(segments, end);
                shakenPins.Add(shaken ? pin : -1);
                Ropes.Add(sim);
            }

            /// <summary>Moves the shaken pins to where they are at the next frame (allocation-free).</summary>
            public void Shake()
            {
                float t = frame++ * Frame;
                for (int r = 0; r < Ropes.Count; r++)
                    if (shakenPins[r] >= 0)
                        Ropes[r].Rope.SetPinTarget(shakenPins[r], new Float3(3f * r, 3f + 0.1f * MathF.Sin(2f * MathF.PI * t), 0f));
            }

            /// <summary>Ropes whose last fill wanted more rings than the budget holds.</summary>
            public int Hits()
            {
                int hits = 0;
                foreach (var sim in Ropes) if (sim.Mesh.Builder.BudgetHit) hits++;
                return hits;
            }
        }

        [TestCase(1)]
        [TestCase(2)]
        public void ASwingingSceneHitsTheBudgetAndItsPassesAllocateNothing(int workers)
        {
            var scene = new SwingingScene();
            using (var world = new RopeWorld(workers))
            {
                foreach (var sim in scene.Ropes) world.EnableMesh(world.Add(sim));
                var perWorker = new long[workers];
                var lastSeen = new long[workers];
                world.WorkerProbe = w =>
                {
                    long now = GC.GetAllocatedBytesForCurrentThread();
                    if (lastSeen[w] != 0) perWorker[w] += now - lastSeen[w];
                    lastSeen[w] = now;
                };
                scene.Shake();
                world.StepAndFillMeshes(Frame);
                var buffers = new TubeVertex[scene.Ropes.Count][];
                var lastCount = new int[scene.Ropes.Count];
                for (int r = 0; r < buffers.Length; r++)
                {
                    buffers[r] = world.GetMeshSlot(r).Vertices;
                    lastCount[r] = world.GetMeshSlot(r).Update.VertexCount;
                }
                int hits = 0, budgetChanges = 0;
                for (int i = 1; i < 60; i++)
                {
                    scene.Shake();
                    world.StepAndFillMeshes(Frame);
                    budgetChanges += CountChanges(world, lastCount);
                }
                long fewestCaller = long.MaxValue, fewestWorkers = long.MaxValue;
                for (int round = 0; round < 6; round++)
                {
                    Array.Clear(perWorker, 0, workers);
                    long caller = 0;
                    for (int pass = 0; pass < 50; pass++)
                    {
                        long before = GC.GetAllocatedBytesForCurrentThread();
                        scene.Shake();
                        world.StepAndFillMeshes(Frame);
                        caller += GC.GetAllocatedBytesForCurrentThread() - before;
                        hits += scene.Hits();
                        budgetChanges += CountChanges(world, lastCount);
                    }
                    long workerBytes = 0;
                    foreach (long b in perWorker) workerBytes += b;
                    fewestCaller = Math.Min(fewestCaller, caller);
                    fewestWorkers = Math.Min(fewestWorkers, workerBytes);
                }
                TestContext.WriteLine($"{workers} worker(s): {hits} rope-passes over the budget in 300 passes, {budgetChanges} budget changes since the first fill; " +
                                      $"fewest bytes per 50 passes: caller {fewestCaller}, workers {fewestWorkers}");
                Assert.That(hits, Is.GreaterThan(100), "rope-passes whose rings wanted more than the budget (of 900)");
                Assert.That(budgetChanges, Is.GreaterThanOrEqualTo(3), "the budgets step within the buffers (vertex counts that changed)");
                Assert.That(fewestCaller, Is.EqualTo(0), "bytes on the calling thread over 50 passes");
                Assert.That(fewestWorkers, Is.EqualTo(0), "bytes on all worker threads over 50 passes");
                for (int r = 0; r < buffers.Length; r++)
                    Assert.That(world.GetMeshSlot(r).Vertices, Is.SameAs(buffers[r]), "rope " + r + "'s slot kept the buffers it made at its first fill");

                // the mesh stays a valid tube while the rings are redistributed within the budget
                for (int pass = 0; pass < 90; pass++)
                {
                    scene.Shake();
                    world.StepAndFillMeshes(Frame);
                    if (pass % 15 != 0) continue;
                    for (int r = 0; r < scene.Ropes.Count; r++)
                        AssertValidTube(world.GetMeshSlot(r), scene.Ropes[r], "rope " + r + ", pass " + pass);
                }
            }
        }

        /// <summary>Ropes whose slot's vertex count changed since <paramref name="lastCount"/> (updated).</summary>
        private static int CountChanges(RopeWorld world, int[] lastCount)
        {
            int changes = 0;
            for (int r = 0; r < lastCount.Length; r++)
            {
                int count = world.GetMeshSlot(r).Update.VertexCount;
                if (count != lastCount[r]) changes++;
                lastCount[r] = count;
            }
            return changes;
        }

        /// <summary>Watertight (caps on), consistently wound, no zero-area or inverted triangle, finite unit normals, within the capacity.</summary>
        private static void AssertValidTube(RopeMeshSlot slot, RopeSimulation sim, string where)
        {
            TubeMeshUpdate u = slot.Update;
            Assert.That(u.VertexCount, Is.LessThanOrEqualTo(sim.GetVertexCapacity()), where);
            Assert.That(sim.Mesh.Layout.RingCount, Is.LessThanOrEqualTo(sim.Mesh.Builder.MostRings), where + ": rings within the budget");
            Assert.That(MeshChecks.AllFiniteAndUnit(slot.Vertices, u.VertexCount), Is.True, where);
            MeshChecks.Topology(slot.Vertices, u.VertexCount, slot.Indices, 0, u.TubeIndexCount, out _, out _, out _, out int badEdges, out int badDirections);
            Assert.That(badEdges, Is.EqualTo(0), where + ": edges not shared by two triangles");
            Assert.That(badDirections, Is.EqualTo(0), where + ": inconsistent winding");
            MeshChecks.Faces(slot.Vertices, slot.Indices, 0, u.TubeIndexCount, out double smallestArea, out double worstAlignment);
            float r = sim.RestRadius;
            Assert.That(smallestArea, Is.GreaterThan(1e-6 * r * r), where + ": degenerate triangle (m²)");
            Assert.That(worstAlignment, Is.GreaterThan(0.0), where + ": inverted triangle (face normal against its vertex normals)");
        }

        /// <summary>A capped (the package's) and an uncapped builder fed the same positions and radii.</summary>
        private sealed class CappedAndUncapped
        {
            private readonly TubeMeshBuilder capped, uncapped;
            private readonly TubeVertex[] cappedVertices, uncappedVertices;
            private readonly int[] cappedIndices, uncappedIndices;
            private readonly float[] radii;
            private readonly float radius;

            public CappedAndUncapped(int segments, float radius)
            {
                var settings = new TubeMeshSettings { RadialSegments = 16 };
                capped = TubeMeshBuilder.Adaptive(settings, segments, radius, null);
                uncapped = TubeMeshBuilder.Adaptive(settings, segments, radius, null, AdaptiveRings.MaxRingsPerSegment);
                cappedVertices = new TubeVertex[capped.GetVertexCapacity(ReadOnlySpan<bool>.Empty)];
                cappedIndices = new int[capped.GetIndexCapacity(ReadOnlySpan<bool>.Empty)];
                uncappedVertices = new TubeVertex[uncapped.GetVertexCapacity(ReadOnlySpan<bool>.Empty)];
                uncappedIndices = new int[uncapped.GetIndexCapacity(ReadOnlySpan<bool>.Empty)];
                radii = new float[uncapped.MostRings];
                Array.Fill(radii, radius);
                this.radius = radius;
            }

            public bool BudgetHit { get; private set; }

            /// <summary>Fills both from the rope's positions; returns the number of differing vertex and index words.</summary>
            public int Differences(Rope rope, bool first)
            {
                var broken = ReadOnlySpan<bool>.Empty;
                if (first)
                {
                    capped.PrimeRings(rope.PositionX, rope.PositionY, rope.PositionZ, broken, false, radius);
                    uncapped.PrimeRings(rope.PositionX, rope.PositionY, rope.PositionZ, broken, false, radius);
                }
                capped.PlanRings(rope.PositionX, rope.PositionY, rope.PositionZ, broken, false, radius, cappedVertices.Length, cappedIndices.Length);
                uncapped.PlanRings(rope.PositionX, rope.PositionY, rope.PositionZ, broken, false, radius, uncappedVertices.Length, uncappedIndices.Length);
                BudgetHit |= capped.BudgetHit;
                TubeMeshUpdate a = capped.BuildWithRingRadii(rope.PositionX, rope.PositionY, rope.PositionZ, rope.RestLengths,
                    radii.AsSpan(0, capped.Layout.RingCount), broken, cappedVertices, cappedIndices);
                TubeMeshUpdate b = uncapped.BuildWithRingRadii(rope.PositionX, rope.PositionY, rope.PositionZ, rope.RestLengths,
                    radii.AsSpan(0, uncapped.Layout.RingCount), broken, uncappedVertices, uncappedIndices);
                if (a.VertexCount != b.VertexCount || a.IndexCount != b.IndexCount) return int.MaxValue;
                int differing = 0;
                for (int v = 0; v < a.VertexCount; v++)
                {
                    TubeVertex p = cappedVertices[v], q = uncappedVertices[v];
                    if (Bits(p.PX) != Bits(q.PX) || Bits(p.PY) != Bits(q.PY) || Bits(p.PZ) != Bits(q.PZ) || Bits(p.NX) != Bits(q.NX)
                        || Bits(p.NY) != Bits(q.NY) || Bits(p.NZ) != Bits(q.NZ) || Bits(p.V) != Bits(q.V)) differing++;
                }
                for (int k = 0; k < a.IndexCount; k++)
                    if (cappedIndices[k] != uncappedIndices[k]) differing++;
                return differing;
            }

            private static int Bits(float f) => BitConverter.SingleToInt32Bits(f);
        }

        private static IEnumerable<TestCaseData> CalmRopes()
        {
            yield return new TestCaseData("taut", 2.02f);
            yield return new TestCaseData("gently curved", 1.8f);
        }

        [TestCaseSource(nameof(CalmRopes))]
        public void ACalmRopeDrawsTheSameBitsAsWithoutTheBudget(string name, float span)
        {
            // a 2 m, 64-segment, 1 cm rope pinned at both ends span metres apart (2.02 m: taut; 1.8 m: the goal lanyard's sag),
            // released from straight: it settles over 2 s; every frame's mesh is compared with the placement without a budget
            var settings = new RopeSettings { RestLength = 2f, SegmentCount = 64, Radius = 0.01f };
            var start = new Float3(0f, 2f, 0f);
            var end = new Float3(span, 2f, 0f);
            var sim = new RopeSimulation(settings, start, end);
            sim.Rope.AddPin(0, start);
            sim.Rope.AddPin(64, end);
            var pair = new CappedAndUncapped(64, settings.Radius);
            int differing = 0;
            for (int frame = 0; frame < 180; frame++)
            {
                sim.Step(Frame);
                differing += pair.Differences(sim.Rope, frame == 0);
            }
            Assert.That(pair.BudgetHit, Is.False, name + ": the budget holds what the rope needs");
            Assert.That(differing, Is.EqualTo(0), name + ": vertex and index words that differ from the mesh without a budget over 180 frames");
        }

        [Test]
        public void AShakenRopeOverTheBudgetDiffersFromTheMeshWithoutIt()
        {
            // the control of the calm-rope test: the comparison does see the budget where it bites
            var scene = new SwingingScene();
            RopeSimulation shaken = scene.Ropes[1];
            var pair = new CappedAndUncapped(32, shaken.RestRadius);
            int framesDiffering = 0;
            for (int frame = 0; frame < 240; frame++)
            {
                scene.Shake();
                shaken.Step(Frame);
                if (pair.Differences(shaken.Rope, frame == 0) != 0) framesDiffering++;
            }
            Assert.That(pair.BudgetHit, Is.True);
            Assert.That(framesDiffering, Is.GreaterThan(0));
        }

        [Test]
        public void ThePieceCapHoldsATightBendAndTheRingsAreRedistributedWithinIt()
        {
            // an 8-segment U-turn of 5 cm bend radius, 1 mm rope, 16 sides: without a budget it asks for more than 8 rings per segment
            RopeShape bend = RopeShape.UTurn(8, 0.05f, 0.05f);
            var settings = new TubeMeshSettings { RadialSegments = 16 };
            var capped = TubeMeshBuilder.Adaptive(settings, 8, 0.001f, null);
            var uncapped = TubeMeshBuilder.Adaptive(settings, 8, 0.001f, null, AdaptiveRings.MaxRingsPerSegment);
            var broken = ReadOnlySpan<bool>.Empty;
            capped.PrimeRings(bend.X, bend.Y, bend.Z, broken, false, 0.001f);
            uncapped.PrimeRings(bend.X, bend.Y, bend.Z, broken, false, 0.001f);
            Assert.That(uncapped.Layout.RingCount, Is.GreaterThan(8 * AdaptiveRings.MaxMeanRingsPerSegment + 1), "the bend wants more than the cap");
            Assert.That(capped.BudgetHit, Is.True);
            Assert.That(capped.Layout.RingCount, Is.EqualTo(8 * AdaptiveRings.MaxMeanRingsPerSegment + 1), "the budget stays at the cap: 8 × 8 + 1 rings");
            for (int j = 0; j < 8; j++)
                Assert.That(capped.Layout.RingsIn(j), Is.InRange(1, AdaptiveRings.MaxRingsPerSegment), "segment " + j);
            // more where it bends more: the ends of the U (straight) keep fewer rings than its apex
            Assert.That(capped.Layout.RingsIn(4), Is.GreaterThanOrEqualTo(capped.Layout.RingsIn(0)));

            var vertices = new TubeVertex[capped.GetVertexCapacity(broken)];
            var indices = new int[capped.GetIndexCapacity(broken)];
            Assert.That(vertices.Length, Is.EqualTo((8 * 8 + 1) * 17 + 2 * 17), "capacity: the cap's rings of 17 vertices and two caps");
            var radii = new float[capped.MostRings];
            Array.Fill(radii, 0.001f);
            for (int build = 0; build < 3; build++)
            {
                capped.PlanRings(bend.X, bend.Y, bend.Z, broken, false, 0.001f, vertices.Length, indices.Length);
                var update = capped.BuildWithRingRadii(bend.X, bend.Y, bend.Z, bend.Rest, radii.AsSpan(0, capped.Layout.RingCount), broken, vertices, indices);
                Assert.That(update.VertexCount, Is.EqualTo(vertices.Length), "at the cap the mesh fills the capacity");
                MeshChecks.Topology(vertices, update.VertexCount, indices, 0, update.TubeIndexCount, out _, out _, out _, out int badEdges, out int badDirections);
                Assert.That(badEdges + badDirections, Is.EqualTo(0), "watertight and consistently wound");
            }
        }

        [Test]
        public void TheCapacityIsTheCapForEverySegmentAndNeckStations()
        {
            // 64 segments × 16 sides: 64 × 8 + 1 = 513 rings of 17 vertices + 2 caps = 8 755 vertices, 512 × 16 × 6 + 2 × 16 × 3 = 49 248 indices
            var builder = TubeMeshBuilder.Adaptive(new TubeMeshSettings { RadialSegments = 16 }, 64, 0.01f, null);
            Assert.That(AdaptiveRings.MaxMeanRingsPerSegment, Is.EqualTo(8));
            Assert.That(builder.MostRings, Is.EqualTo(513));
            Assert.That(builder.GetVertexCapacity(ReadOnlySpan<bool>.Empty), Is.EqualTo(8755));
            Assert.That(builder.GetIndexCapacity(ReadOnlySpan<bool>.Empty), Is.EqualTo(49248));

            // a Zone neck's stations come on top of the cap, in the segments that hold them
            var rest = new float[64];
            Array.Fill(rest, 2f / 64f);
            RingLayout stations = RingLayout.Adapted(rest, 1, 1f, 0.1f, 0.01f, 16);
            int extra = 0;
            for (int j = 0; j < 64; j++) if (stations.RingsIn(j) > 1) extra += stations.RingsIn(j);
            Assert.That(extra, Is.GreaterThan(0));
            var necked = new AdaptiveRings(64, 16, stations);
            Assert.That(necked.MostRings, Is.EqualTo(64 * 8 + extra + 1));
            Assert.That(necked.CapOfPiece(0, 64) + 1, Is.EqualTo(necked.MostRings));

            // a broken rope's pieces share the same rings: their caps add up to the whole rope's
            Assert.That(necked.CapOfPiece(0, 20) + necked.CapOfPiece(20, 64), Is.EqualTo(necked.CapOfPiece(0, 64)));
        }

        [Test]
        public void AMeanCapOutsideItsRangeIsRejected()
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new AdaptiveRings(8, 16, null, 0));
            Assert.That(e.ParamName, Is.EqualTo("meanRingsPerSegment"));
            e = Assert.Throws<ArgumentOutOfRangeException>(() => new AdaptiveRings(8, 16, null, AdaptiveRings.MaxRingsPerSegment + 1));
            Assert.That(e.ParamName, Is.EqualTo("meanRingsPerSegment"));
        }
    }
}
