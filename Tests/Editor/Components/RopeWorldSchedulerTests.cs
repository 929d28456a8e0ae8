using System;
using System.Collections.Generic;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools.Constraints;
using Is = UnityEngine.TestTools.Constraints.Is;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode, driving the shared multi-rope world's passes directly (RopeWorldScheduler.Step and Draw: what the
    /// first rope's FixedUpdate and the first renderer's LateUpdate run in Play; Play mode itself is in
    /// Tests/Runtime/RopeWorldPlayModeTests): ropes with renderers (one rotated and scaled) stepped and drawn by the world
    /// on two workers give the same bits, meshes included, as each rope simulated and rendered alone; a step and a draw
    /// of several ropes with meshes and a Rigidbody allocate 0 bytes on the main thread and on every worker; the world
    /// starts at the second rope and its threads stop when the last rope goes or at shutdown (Application.quitting, a
    /// domain reload); a rebuilt rope keeps its place; the worker count is checked and applies at the next pass.
    /// </summary>
    [TestFixture]
    public sealed class RopeWorldSchedulerTests
    {
        const float Dt = 1f / 90f, Alpha = 0.35f;
        UnityRopeScene _scene;
        int _workers;
        double _key;
        int _frame;

        [SetUp]
        public void SetUp()
        {
            _scene = new UnityRopeScene();
            _scene.Begin();
            _workers = ElasticRopeWorld.WorkerCount;
            ElasticRopeWorld.WorkerCount = 2;
        }

        [TearDown]
        public void TearDown()
        {
            RopeWorldScheduler.Shutdown();   // edit mode sends no OnDisable to the ropes
            _scene.End();
            ElasticRopeWorld.WorkerCount = _workers;
        }

        /// <summary>Rope <paramref name="index"/> of a varied scene with its renderer: pinned, loaded by a body, two-anchor, rotated and scaled.</summary>
        ElasticRope Rope(int index)
        {
            var top = new Vector3(2f * index, 5f, 0f);
            var anchor = _scene.Point("Anchor " + index, top);
            var go = _scene.Track(new GameObject("Rope " + index, typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer)));
            go.transform.position = top;
            var rope = go.GetComponent<ElasticRope>();
            rope.RestLength = 1f + 0.4f * index;
            rope.SegmentCount = 10 + 6 * index;
            rope.StartAttachment.Point = anchor;
            var renderer = go.GetComponent<RopeMeshRenderer>();
            renderer.RadialSegments = 6 + 2 * index;
            // ropes 1 and 3 without tangents: both vertex layouts in one world
            if (_lean && index % 2 == 1) renderer.Tangents = false;
            if (_viewDetail)
            {
                // seen from 3 … 9 m with a detail distance of 1 m: rope 0 all its sides at tolerance 3, the others
                // (4.4 D and farther) half their sides at about 1.3 … 2.2
                renderer.ViewPoint = _scene.Point("Viewer " + index, new Vector3(-3f, 5f, 0f));
                renderer.DetailDistance = 1f;
            }
            switch (index % 4)
            {
                case 1:
                    rope.EndAttachment.Body = _scene.Body("Load " + index, top + new Vector3(0.3f, -0.5f, 0f), 20f);
                    break;
                case 2:
                    rope.EndAttachment.Point = _scene.Point("Other end " + index, top + new Vector3(0.9f * rope.RestLength, 0f, 0.2f));
                    break;
                case 3:
                    go.transform.rotation = Quaternion.Euler(10f, 35f, -20f);
                    go.transform.localScale = new Vector3(1.5f, 1.5f, 1.5f);
                    break;
            }
            rope.Rebuild();
            return rope;
        }

        ElasticRope[] Ropes(int count)
        {
            var ropes = new ElasticRope[count];
            for (int i = 0; i < count; i++) ropes[i] = Rope(i);
            return ropes;
        }

        void WorldStep()
        {
            RopeWorldScheduler.Step(Dt, ++_key);
            Physics.Simulate(Dt);
        }

        void WorldDraw() => RopeWorldScheduler.Draw(Alpha, ++_frame);

        static void AddBits(List<int> bits, Vector3 v)
        {
            bits.Add(BitConverter.SingleToInt32Bits(v.x));
            bits.Add(BitConverter.SingleToInt32Bits(v.y));
            bits.Add(BitConverter.SingleToInt32Bits(v.z));
        }

        static List<int> Bits(ElasticRope rope)
        {
            var bits = new List<int>();
            for (int p = 0; p < rope.ParticleCount; p++) AddBits(bits, rope.GetParticlePosition(p));
            AddBits(bits, rope.EndForce);
            var mesh = rope.GetComponent<MeshFilter>().sharedMesh;
            foreach (var v in mesh.vertices) AddBits(bits, v);
            foreach (var n in mesh.normals) AddBits(bits, n);
            bits.Add((int)mesh.GetIndexCount(0));
            bits.Add((int)mesh.GetIndexCount(1));
            AddBits(bits, mesh.bounds.center);
            return bits;
        }

        /// <summary>Rope gives each renderer a view point 3 … 9 m away and a detail distance of 1 m.</summary>
        bool _viewDetail;

        /// <summary>Rope turns the tangents off on the odd ropes' renderers; SwitchTangents turns rope 2's off halfway.</summary>
        bool _lean;

        /// <summary>With <see cref="_lean"/>, at step 20 rope 2 (the <paramref name="first"/>-th index of <paramref name="ropes"/> on) stops writing tangents.</summary>
        void SwitchTangents(int step, ElasticRope[] ropes, int first = 0)
        {
            if (!_lean || step != 20) return;
            for (int k = 0; k < ropes.Length; k++)
                if (first + k == 2) ropes[k].GetComponent<RopeMeshRenderer>().Tangents = false;
        }

        [TestCase(false, false)]
        [TestCase(true, false)]
        [TestCase(false, true)]
        public void RopesSteppedAndDrawnByTheWorldGiveTheBitsOfEachRopeAlone(bool viewDetail, bool lean)
        {
            _viewDetail = viewDetail;
            _lean = lean;
            const int ropeCount = 4, steps = 40;
            var inWorld = new List<List<int>>();
            var ropes = Ropes(ropeCount);
            foreach (var rope in ropes) RopeWorldScheduler.Enroll(rope);
            Assert.That(ElasticRopeWorld.IsActive, Is.True);
            for (int s = 0; s < steps; s++)
            {
                SwitchTangents(s, ropes);
                WorldStep();
                WorldDraw();
            }
            foreach (var rope in ropes) inWorld.Add(Bits(rope));
            for (int i = 0; i < ropeCount; i++)
                Assert.That(ropes[i].GetComponent<MeshFilter>().sharedMesh.GetVertexBufferStride(0), Is.EqualTo(lean && (i % 2 == 1 || i == 2) ? 32 : 48),
                    "rope " + i + ": bytes per vertex");
            var drawn = new string[ropeCount];
            int fewerSides = 0;
            for (int i = 0; i < ropeCount; i++)
            {
                var renderer = ropes[i].GetComponent<RopeMeshRenderer>();
                drawn[i] = renderer.DrawnRadialSegments + " of " + renderer.RadialSegments + " sides at " + renderer.DrawnRingTolerance;
                if (renderer.DrawnRadialSegments < renderer.RadialSegments) fewerSides++;
                if (viewDetail) Assert.That(renderer.DrawnRingTolerance, Is.GreaterThan(1f), "rope " + i + " drew at its view distance's tolerance");
                else Assert.That(renderer.DrawnRingTolerance, Is.EqualTo(1f), "rope " + i);
            }
            TestContext.WriteLine("drawn in the world: " + string.Join("; ", drawn));
            Assert.That(fewerSides, viewDetail ? Is.EqualTo(3) : Is.EqualTo(0), "the ropes 4.4 m and farther draw half their sides");
            RopeWorldScheduler.Shutdown();
            _scene.End();
            _scene.Begin();

            for (int i = 0; i < ropeCount; i++)
            {
                var rope = Rope(i);
                var renderer = rope.GetComponent<RopeMeshRenderer>();
                for (int s = 0; s < steps; s++)
                {
                    SwitchTangents(s, new[] { rope }, i);
                    rope.Simulate(Dt);
                    Physics.Simulate(Dt);
                    renderer.Render(Alpha);
                }
                var alone = Bits(rope);
                Assert.That(alone.Count, Is.GreaterThan(3 * 3 * rope.ParticleCount), "positions and mesh vertices compared");
                int differing = 0;
                for (int b = 0; b < alone.Count; b++)
                    if (b >= inWorld[i].Count || alone[b] != inWorld[i][b]) differing++;
                Assert.That(inWorld[i].Count, Is.EqualTo(alone.Count), "rope " + i);
                Assert.That(differing, Is.EqualTo(0), "rope " + i + ": differing bits among positions, end force and mesh");
                _scene.End();
                _scene.Begin();
            }
        }

        [Test]
        public void AStepAndADrawOfSeveralRopesWithMeshesAllocateNothingOnAnyThread()
        {
            var ropes = Ropes(6);
            foreach (var rope in ropes) RopeWorldScheduler.Enroll(rope);
            var world = RopeWorldScheduler.World;
            var perWorker = new long[world.WorkerCount];
            var lastSeen = new long[world.WorkerCount];
            world.WorkerProbe = w =>
            {
                long now = GC.GetAllocatedBytesForCurrentThread();
                if (lastSeen[w] != 0) perWorker[w] += now - lastSeen[w];
                lastSeen[w] = now;
            };
            for (int i = 0; i < 120; i++)
            {
                WorldStep();
                WorldDraw();
            }
            Assert.That(() => { WorldStep(); WorldDraw(); }, Is.Not.AllocatingGCMemory());
            // the worker threads: the fewest bytes over several rounds (the runtime may allocate once while it
            // re-compiles a hot method; an allocation of the package lands in every round)
            long fewest = long.MaxValue;
            for (int round = 0; round < 6; round++)
            {
                Array.Clear(perWorker, 0, perWorker.Length);
                for (int i = 0; i < 20; i++)
                {
                    WorldStep();
                    WorldDraw();
                }
                long bytes = 0;
                foreach (long b in perWorker) bytes += b;
                fewest = Math.Min(fewest, bytes);
            }
            Assert.That(fewest, Is.EqualTo(0), "bytes on the world's threads over 20 steps and draws");
            Assert.That(ropes[5].GetComponent<MeshFilter>().sharedMesh.vertexCount, Is.GreaterThan(0), "the world drew the meshes");
        }

        [Test]
        public void TheWorldStartsAtTheSecondRopeAndItsThreadsStopWhenTheLastGoesOrAtShutdown()
        {
            var ropes = Ropes(3);
            RopeWorldScheduler.Enroll(ropes[0]);
            Assert.That(RopeWorldScheduler.World, Is.Null, "one rope steps inline: no world");
            Assert.That(ElasticRopeWorld.IsActive, Is.False);
            RopeWorldScheduler.Enroll(ropes[1]);
            var world = RopeWorldScheduler.World;
            Assert.That(world, Is.Not.Null);
            Assert.That(world.AnyWorkerAlive, Is.True, "two workers: one extra thread");
            Assert.That(world.IndexOf(ropes[1].Simulation), Is.EqualTo(1));
            Assert.That(ropes[1].IsSteppedInWorld, Is.True);

            RopeWorldScheduler.Withdraw(ropes[0]);
            Assert.That(ropes[1].WorldIndex, Is.EqualTo(0), "the ropes after it moved down");
            Assert.That(world.GetRope(0), Is.SameAs(ropes[1].Simulation));
            Assert.That(ElasticRopeWorld.IsActive, Is.False, "one left: it steps inline");
            Assert.That(world.IsDisposed, Is.False, "the threads wait for a second rope");
            RopeWorldScheduler.Withdraw(ropes[1]);
            Assert.That(RopeWorldScheduler.World, Is.Null);
            Assert.That(world.IsDisposed && !world.AnyWorkerAlive, Is.True, "the last rope stopped the threads");

            foreach (var rope in ropes) RopeWorldScheduler.Enroll(rope);
            world = RopeWorldScheduler.World;
            WorldStep();
            RopeWorldScheduler.Shutdown();   // what Application.quitting and a domain reload run
            Assert.That(world.IsDisposed && !world.AnyWorkerAlive, Is.True);
            Assert.That(ElasticRopeWorld.RopeCount, Is.EqualTo(0));
            Assert.That(ropes[2].WorldIndex, Is.EqualTo(-1));
        }

        [Test]
        public void ARopeRebuiltInAPassKeepsItsPlaceAndIsDrawnWithItsNewSegments()
        {
            var ropes = Ropes(3);
            foreach (var rope in ropes) RopeWorldScheduler.Enroll(rope);
            WorldStep();
            WorldDraw();
            var mesh = ropes[1].GetComponent<MeshFilter>().sharedMesh;
            int vertices = mesh.vertexCount;
            ropes[1].SegmentCount = 30;   // applies at the next step: rebuilt during the copy-in
            WorldStep();
            WorldDraw();
            Assert.That(ropes[1].ParticleCount, Is.EqualTo(31));
            Assert.That(ropes[1].WorldIndex, Is.EqualTo(1));
            Assert.That(RopeWorldScheduler.World.GetRope(1), Is.SameAs(ropes[1].Simulation));
            Assert.That(mesh.vertexCount, Is.GreaterThan(vertices), "the new rope's tube (" + vertices + " → " + mesh.vertexCount + " vertices)");
            Assert.That(ropes[1].GetParticlePosition(30).y, Is.LessThan(5f), "and it steps");
        }

        [Test]
        public void WorkerCountIsCheckedAndANewCountReplacesTheThreadsBeforeTheNextPass()
        {
            var none = Assert.Throws<ArgumentOutOfRangeException>(() => ElasticRopeWorld.WorkerCount = 0);
            Assert.That(none.ParamName, Is.EqualTo("WorkerCount"));
            Assert.Throws<ArgumentOutOfRangeException>(() => ElasticRopeWorld.WorkerCount = ElasticRopeWorld.MaxWorkerCount + 1);
            Assert.That(ElasticRopeWorld.WorkerCount, Is.EqualTo(2), "a refused value changes nothing");
            int byDefault = ElasticRopeWorld.DefaultWorkerCount;
            Assert.That(byDefault, Is.InRange(1, 8));
            Assert.That(byDefault, Is.EqualTo(Math.Max(1, Math.Min(8, SystemInfo.processorCount - 1))), "a core left for Unity's threads");

            var ropes = Ropes(2);
            foreach (var rope in ropes) RopeWorldScheduler.Enroll(rope);
            var two = RopeWorldScheduler.World;
            ElasticRopeWorld.WorkerCount = 3;
            Assert.That(RopeWorldScheduler.World, Is.SameAs(two), "not in the middle of anything");
            WorldStep();
            Assert.That(RopeWorldScheduler.World.WorkerCount, Is.EqualTo(3));
            Assert.That(two.IsDisposed && !two.AnyWorkerAlive, Is.True, "the old threads are joined");
            Assert.That(RopeWorldScheduler.World.IndexOf(ropes[1].Simulation), Is.EqualTo(1), "every rope moved over in order");
        }
    }
}
