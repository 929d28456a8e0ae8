using System;
using System.Collections.Generic;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Solver;
using HookeRope.World;
using NUnit.Framework;

namespace HookeRope.Tests.Core.World
{
    /// <summary>The many-ropes world: same bits for any worker count, no allocation per pass, failures on the caller, clean shutdown.</summary>
    public sealed class RopeWorldTests
    {
        private const float Frame = 1f / 90f;

        /// <summary>A varied scene: segment counts 8 … 52, both solvers, pinned ends, loads, a sphere under some ropes, a radius model on some.</summary>
        private static List<RopeSimulation> Scene(int ropeCount)
        {
            var list = new List<RopeSimulation>();
            for (int r = 0; r < ropeCount; r++)
            {
                int segments = 8 + (r * 11) % 45;
                var settings = new RopeSettings
                {
                    RestLength = 1.5f + 0.1f * r,
                    SegmentCount = segments,
                    Solver = r % 3 == 1 ? ConstraintSolverKind.GaussSeidel : ConstraintSolverKind.ExactChain,
                };
                var start = new Float3(r * 0.7f, 3f, 0f);
                var end = new Float3(r * 0.7f + 1.2f, 2.5f, 0.3f);
                var sim = new RopeSimulation(settings, start, end, r % 2 == 0 ? new HookeRope.Radius.RadiusSettings() : null);
                sim.Rope.AddPin(0, start);
                if (r % 4 == 0) sim.Rope.AddPin(segments, end);
                else sim.Rope.AddLoad(segments, 0.5f + r);
                if (r % 5 == 2) sim.Rope.AddCollider(ColliderShape.Sphere(new Float3(r * 0.7f + 0.6f, 2.4f, 0.1f), 0.3f));
                list.Add(sim);
            }
            return list;
        }

        /// <summary>Positions and mesh vertices of a scene as raw bits after <paramref name="frames"/> passes on <paramref name="workers"/> workers.</summary>
        private static List<int> RunBits(int workers, int ropeCount, int frames)
        {
            var scene = Scene(ropeCount);
            var bits = new List<int>();
            using (var world = new RopeWorld(workers))
            {
                foreach (var sim in scene) world.EnableMesh(world.Add(sim));
                for (int f = 0; f < frames; f++) world.StepAndFillMeshes(Frame);
                for (int i = 0; i < world.Count; i++)
                {
                    Rope rope = world.GetRope(i).Rope;
                    for (int p = 0; p < rope.ParticleCount; p++)
                    {
                        bits.Add(BitConverter.SingleToInt32Bits(rope.PositionX[p]));
                        bits.Add(BitConverter.SingleToInt32Bits(rope.PositionY[p]));
                        bits.Add(BitConverter.SingleToInt32Bits(rope.PositionZ[p]));
                    }
                    bits.Add(BitConverter.SingleToInt32Bits(world.GetLastReport(i).Residual));
                    RopeMeshSlot slot = world.GetMeshSlot(i);
                    for (int v = 0; v < slot.Update.VertexCount; v++)
                    {
                        TubeVertex vertex = slot.Vertices[v];
                        bits.Add(BitConverter.SingleToInt32Bits(vertex.PX));
                        bits.Add(BitConverter.SingleToInt32Bits(vertex.PY));
                        bits.Add(BitConverter.SingleToInt32Bits(vertex.NZ));
                    }
                }
            }
            return bits;
        }

        private static int Mismatches(List<int> a, List<int> b)
        {
            if (a.Count != b.Count) return int.MaxValue;
            int n = 0;
            for (int i = 0; i < a.Count; i++)
                if (a[i] != b[i]) n++;
            return n;
        }

        [TestCase(2)]
        [TestCase(3)]
        public void ResultsAreTheSameBitsForOneAndSeveralWorkers(int workers)
        {
            var one = RunBits(1, 13, 45);
            var several = RunBits(workers, 13, 45);
            Assert.That(one.Count, Is.GreaterThan(13 * 9 * 3), "positions, residuals and mesh vertices compared");
            Assert.That(Mismatches(one, several), Is.EqualTo(0));
        }

        [Test]
        public void WorldStepIsTheSameBitsAsSteppingEachRopeAlone()
        {
            var alone = Scene(7);
            var inWorld = Scene(7);
            using (var world = new RopeWorld(2))
            {
                foreach (var sim in inWorld) world.Add(sim);
                for (int f = 0; f < 30; f++)
                {
                    world.Step(Frame);
                    foreach (var sim in alone) sim.Step(Frame);
                }
            }
            int differing = 0;
            double sag = 0;
            for (int r = 0; r < alone.Count; r++)
            {
                Rope a = alone[r].Rope, b = inWorld[r].Rope;
                for (int p = 0; p < a.ParticleCount; p++)
                {
                    if (BitConverter.SingleToInt32Bits(a.PositionY[p]) != BitConverter.SingleToInt32Bits(b.PositionY[p])) differing++;
                    sag = Math.Max(sag, -b.PositionY[p]);
                }
            }
            Assert.That(differing, Is.EqualTo(0));
            Assert.That(sag, Is.GreaterThan(0.05), "the ropes did move (metres below their start)");
        }

        [TestCase(1)]
        [TestCase(2)]
        public void APassAllocatesNothingOnAnyThread(int workers)
        {
            var scene = Scene(20);
            using (var world = new RopeWorld(workers))
            {
                foreach (var sim in scene) world.EnableMesh(world.Add(sim));
                var perWorker = new long[workers];
                var lastSeen = new long[workers];
                world.WorkerProbe = w =>
                {
                    long now = GC.GetAllocatedBytesForCurrentThread();
                    if (lastSeen[w] != 0) perWorker[w] += now - lastSeen[w];
                    lastSeen[w] = now;
                };
                for (int i = 0; i < 60; i++) world.StepAndFillMeshes(Frame);
                // The fewest bytes over up to 20 rounds, stopping at the first clean one (as SteadyStateAllocation): the
                // runtime may allocate a few bytes on some thread while it re-compiles a hot method (tiered JIT, on-stack
                // replacement), which on a loaded machine can land in several rounds in a row (24–48 B seen with the load
                // average above 30); an allocation of the world or the ropes lands in every round.
                long fewestCaller = long.MaxValue, fewestWorkers = long.MaxValue;
                for (int round = 0; round < 20 && (fewestCaller > 0 || fewestWorkers > 0); round++)
                {
                    Array.Clear(perWorker, 0, workers);
                    fewestCaller = Math.Min(fewestCaller, MeasureCaller(world, 50));
                    long workerBytes = 0;
                    foreach (long b in perWorker) workerBytes += b;
                    fewestWorkers = Math.Min(fewestWorkers, workerBytes);
                }
                Assert.That(fewestCaller, Is.EqualTo(0), "bytes on the calling thread (worker 0) over 50 passes");
                Assert.That(fewestWorkers, Is.EqualTo(0), "bytes on all worker threads over 50 passes (the probe allocates nothing)");
            }
        }

        private static long MeasureCaller(RopeWorld world, int passes)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < passes; i++) world.StepAndFillMeshes(Frame);
            return GC.GetAllocatedBytesForCurrentThread() - before;
        }

        [TestCase(1)]
        [TestCase(2)]
        public void AFailingRopeIsReportedOnTheCallerAndTheOthersStillStep(int workers)
        {
            var scene = Scene(6);
            using (var world = new RopeWorld(workers))
            {
                foreach (var sim in scene) world.Add(sim);
                // rope 4 draws through caller positions too short for it: its mesh fill throws on a worker
                world.EnableMesh(4).UseCallerPositions(new float[1], new float[1], new float[1], 1f);
                float before = scene[5].Rope.PositionY[5];
                var error = Assert.Throws<InvalidOperationException>(() => world.StepAndFillMeshes(Frame));
                Assert.That(error.Message, Does.StartWith("Rope 4 of the world failed"));
                Assert.That(error.InnerException, Is.InstanceOf<ArgumentException>());
                Assert.That(scene[5].Rope.PositionY[5], Is.LessThan(before), "rope 5 (after the failing one) still stepped: it fell (m)");
                Assert.That(world.GetLastReport(0).Residual, Is.LessThan(1e-3f), "rope 0 still stepped");
                Assert.That(world.LastPassFailed(4), Is.True, "the failing rope is flagged");
                Assert.That(world.LastPassFailed(3) || world.LastPassFailed(5), Is.False, "its neighbours are not");

                world.DisableMesh(4);
                world.StepAndFillMeshes(Frame);
                Assert.That(world.LastPassFailed(4), Is.False, "the flag is per pass");
                Assert.That(world.Count, Is.EqualTo(6), "the world is still usable after the failure");
            }
        }

        [Test]
        public void ACallerFrameOnTheSlotKeepsTheWorldDrawnTubeOutOfTheCollider()
        {
            // the wrapped rope of MeshFrameTests (0.1 m sphere at (0, 1, 0), R = 1 cm), drawn by the world through
            // renderer-local positions with their frame: no drawn vertex sinks more than 2 % of R into the sphere, while
            // the simulation's own frameless fill of the same positions sinks more than 10 % of R
            RopeSimulation sim = HookeRope.Tests.Core.Geometry.MeshFrameTests.WrappedRope();
            var frame = new MeshFrame(new Float3(0.4f, 0.3f, -0.2f), Quat.FromAxisAngle(new Float3(1f, 2f, -1f), 0.87f), 1.7f);
            Rope rope = sim.Rope;
            int n = rope.ParticleCount;
            float[] x = new float[n], y = new float[n], z = new float[n];
            for (int i = 0; i < n; i++)
            {
                Float3 local = frame.Rotation.Conjugate.Rotate(rope.Origin + new Float3(rope.PositionX[i], rope.PositionY[i], rope.PositionZ[i]) - frame.Origin) * (1f / frame.Scale);
                x[i] = local.X; y[i] = local.Y; z[i] = local.Z;
            }
            var frameless = new TubeVertex[sim.GetVertexCount()];
            int framelessCount = sim.FillMesh(x, y, z, frameless, new int[sim.GetIndexCount()], 1f / frame.Scale).VertexCount;
            const float radius = 0.01f, sphere = 0.1f;
            var centre = new Float3(0f, 1f, 0f);
            float Deepest(TubeVertex[] vertices, int count)
            {
                float deepest = float.PositiveInfinity;
                for (int v = 0; v < count; v++)
                {
                    Float3 world = frame.Origin + frame.Rotation.Rotate(new Float3(vertices[v].PX, vertices[v].PY, vertices[v].PZ) * frame.Scale);
                    deepest = Math.Min(deepest, (world - centre).Length - sphere);
                }
                return deepest;
            }

            using (var world = new RopeWorld(1))
            {
                world.Add(sim);
                var slot = world.EnableMesh(0);
                slot.UseCallerPositions(x, y, z, 1f / frame.Scale, frame);
                world.FillMeshes();
                float framed = Deepest(slot.Vertices, slot.Update.VertexCount);
                TestContext.WriteLine("deepest drawn vertex: framed " + framed / radius + " R, frameless " + Deepest(frameless, framelessCount) / radius + " R");
                Assert.That(framed, Is.GreaterThan(-0.02f * radius));
                Assert.That(Deepest(frameless, framelessCount), Is.LessThan(-0.1f * radius));

                slot.UseCallerPositions(x, y, z, 1f / frame.Scale);
                world.FillMeshes();
                Assert.That(Deepest(slot.Vertices, slot.Update.VertexCount), Is.LessThan(-0.1f * radius), "the frameless overload clears the frame");
            }
        }

        [TestCase(1)]
        [TestCase(2)]
        [TestCase(4)]
        public void DisposeJoinsTheWorkersAndLaterPassesThrow(int workers)
        {
            var world = new RopeWorld(workers);
            foreach (var sim in Scene(3)) world.Add(sim);
            world.Step(Frame);
            Assert.That(world.AnyWorkerAlive, Is.EqualTo(workers > 1));
            world.Dispose();
            world.Dispose();
            Assert.That(world.AnyWorkerAlive, Is.False);
            Assert.That(world.IsDisposed, Is.True);
            Assert.Throws<ObjectDisposedException>(() => world.Step(Frame));
        }

        [Test]
        public void AddRemoveKeepOrderAndRejectDuplicates()
        {
            var scene = Scene(4);
            using (var world = new RopeWorld(2))
            {
                foreach (var sim in scene) world.Add(sim);
                Assert.Throws<ArgumentException>(() => world.Add(scene[2]));
                Assert.That(world.Remove(scene[1]), Is.True);
                Assert.That(world.Remove(scene[1]), Is.False);
                Assert.That(world.Count, Is.EqualTo(3));
                Assert.That(world.GetRope(1), Is.SameAs(scene[2]));
                Assert.That(world.IndexOf(scene[3]), Is.EqualTo(2));
                Assert.Throws<ArgumentOutOfRangeException>(() => world.Step(0f));
                Assert.Throws<ArgumentOutOfRangeException>(() => world.GetRope(3));
                Assert.Throws<ArgumentOutOfRangeException>(() => new RopeWorld(0));
            }
        }

        [Test]
        public void ReplaceKeepsThePlaceAndTheSlotAndRejectsARopeAlreadyInTheWorld()
        {
            var scene = Scene(3);
            var rebuilt = Scene(4)[3];
            using (var world = new RopeWorld(2))
            {
                foreach (var sim in scene) world.Add(sim);
                RopeMeshSlot slot = world.EnableMesh(1);
                world.StepAndFillMeshes(Frame);
                Assert.That(world.GetLastStepMilliseconds(1), Is.GreaterThan(0.0), "the step of rope 1 was timed (ms)");
                Assert.That(world.GetLastFillMilliseconds(1), Is.GreaterThan(0.0), "and its mesh fill (ms)");
                Assert.That(world.GetLastFillMilliseconds(0), Is.EqualTo(0.0), "rope 0 has no mesh: no fill time");

                world.Replace(1, rebuilt);
                Assert.That(world.GetRope(1), Is.SameAs(rebuilt));
                Assert.That(world.GetMeshSlot(1), Is.SameAs(slot), "the host's slot stays with the place");
                Assert.That(world.GetLastReport(1).Substeps, Is.EqualTo(0), "the new rope has not stepped here yet");
                Assert.That(world.GetLastStepMilliseconds(1), Is.EqualTo(0.0));
                Assert.That(world.GetLastFillMilliseconds(1), Is.EqualTo(0.0));
                world.Replace(1, rebuilt);
                Assert.Throws<ArgumentException>(() => world.Replace(0, rebuilt), "a rope can be in one world once");
                Assert.Throws<ArgumentNullException>(() => world.Replace(0, null));
                Assert.Throws<ArgumentOutOfRangeException>(() => world.Replace(3, Scene(1)[0]));

                world.StepAndFillMeshes(Frame);
                Assert.That(world.GetLastReport(1).Substeps, Is.EqualTo(rebuilt.Rope.Settings.Substeps), "the replacing rope steps in its place");
                Assert.That(slot.Update.VertexCount, Is.EqualTo(rebuilt.GetVertexCount()), "and its mesh fills the kept slot");
            }
        }

        [Test]
        public void ADisabledSlotKeepsItsLastFill()
        {
            var scene = Scene(2);
            using (var world = new RopeWorld(2))
            {
                foreach (var sim in scene) world.Add(sim);
                RopeMeshSlot kept = world.EnableMesh(0), filled = world.EnableMesh(1);
                world.StepAndFillMeshes(Frame);
                int middle = kept.Update.VertexCount / 2;
                TubeVertex before = kept.Vertices[middle];
                kept.Enabled = false;
                for (int f = 0; f < 5; f++) world.StepAndFillMeshes(Frame);
                Assert.That(kept.FillCount, Is.EqualTo(1), "no fill while disabled");
                Assert.That(kept.Vertices[middle].PY, Is.EqualTo(before.PY), "the last fill stays (m)");
                Assert.That(filled.FillCount, Is.EqualTo(6));
                kept.Enabled = true;
                world.FillMeshes();
                Assert.That(kept.FillCount, Is.EqualTo(2));
                Assert.That(kept.Vertices[middle].PY, Is.LessThan(before.PY), "filled again from the rope that kept sagging (m)");
            }
        }

        [Test]
        public void EmptyWorldPassesDoNothing()
        {
            using (var world = new RopeWorld(2))
            {
                world.StepAndFillMeshes(Frame);
                world.FillMeshes();
                Assert.That(world.Count, Is.EqualTo(0));
            }
        }

        [Test]
        public void PartitionSplitsContiguousChunksThatShrinkToSingleRopes()
        {
            var bounds = new int[101];
            var costs = new double[100];
            for (int i = 0; i < costs.Length; i++) costs[i] = 1.0;
            int chunks = WorkPartition.Split(costs, 100, 2, bounds);
            Assert.That(bounds[0], Is.EqualTo(0));
            Assert.That(bounds[chunks], Is.EqualTo(100), "every rope in one chunk");
            double left = 100.0;
            for (int k = 0; k < chunks; k++)
            {
                int size = bounds[k + 1] - bounds[k];
                Assert.That(size, Is.GreaterThanOrEqualTo(1), "no empty chunk");
                // about 1/(4 W) = 1/8 of the cost left, rounded to whole ropes (at least one)
                Assert.That(size, Is.LessThanOrEqualTo(Math.Max(1.0, left / 8.0 + 0.5)), "chunk " + k + " of " + chunks);
                left -= size;
            }
            Assert.That(bounds[1], Is.EqualTo(12).Or.EqualTo(13), "the first chunk: 1/8 of 100 equal ropes");
            Assert.That(bounds[chunks] - bounds[chunks - 1], Is.EqualTo(1), "the last chunk is one rope");
            Assert.That(chunks, Is.LessThan(40), "few claims per pass");

            int heavy = WorkPartition.Split(new double[] { 60, 1, 1, 1, 1 }, 5, 2, bounds);
            Assert.That(bounds[1], Is.EqualTo(1), "a rope heavier than the target is a chunk of its own");
            Assert.That(bounds[heavy], Is.EqualTo(5));

            Assert.That(WorkPartition.Split(costs, 0, 2, bounds), Is.EqualTo(1), "no rope: one empty chunk");
            Assert.That(bounds[0] == 0 && bounds[1] == 0, Is.True);
        }

        [Test]
        public void APassOnTwoWorkersReportsItsChunksAndTheWorkersTime()
        {
            var scene = Scene(12);
            using (var world = new RopeWorld(2))
            {
                foreach (var sim in scene) world.EnableMesh(world.Add(sim));
                for (int i = 0; i < 5; i++) world.StepAndFillMeshes(Frame);
                Assert.That(world.LastChunkCount, Is.InRange(2, 12), "guided chunks of 12 ropes");
                double pass = world.LastPassMilliseconds;
                Assert.That(pass, Is.GreaterThan(0.0));
                for (int w = 0; w < 2; w++)
                {
                    Assert.That(world.LastIdleMilliseconds(w), Is.InRange(0.0, pass), "worker " + w + " idle within the pass");
                    Assert.That(world.LastWakeMilliseconds(w), Is.InRange(0.0, pass), "worker " + w + " began within the pass");
                }
            }
        }
    }
}
