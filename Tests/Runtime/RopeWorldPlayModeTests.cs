using System;
using System.Collections;
using System.Collections.Generic;
using System.Threading;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;
using Object = UnityEngine.Object;

namespace HookeRope.Tests
{
    /// <summary>
    /// Play mode (in Unity and headless through the Unity stand-in's player loop): ropes enabled together are stepped by
    /// the shared multi-rope world (<see cref="ElasticRopeWorld"/>, issue 18 item 4) on two workers, and each gives the
    /// same bits as the same rope stepped alone (inline, as before the world): particle positions, the forces on its
    /// ends, its Rigidbody, its peak tension and its break event, which is raised once, on the main thread. A
    /// Rigidbody worker on a lanyard in the world is arrested exactly as alone. Ropes disabled, destroyed or created
    /// mid-play leave, join and step once per physics step, and the world's threads stop when the last rope goes.
    /// </summary>
    public sealed class RopeWorldPlayModeTests
    {
        const int Steps = 60;
        readonly List<GameObject> _objects = new List<GameObject>();
        int _workers;

        [SetUp] public void SetUp() => _workers = ElasticRopeWorld.WorkerCount;

        [TearDown]
        public void TearDown()
        {
            DestroyAll();
            ElasticRopeWorld.WorkerCount = _workers;
        }

        // ---- scenes ---------------------------------------------------------------------------------------------
        enum EndKind { Free, Pinned, Body }

        /// <summary>One rope of the test scene: hung from an anchor at x = 3·index (m, apart so nothing meets).</summary>
        sealed class Spec
        {
            public float RestLength = 2f, Mass, BreakStrain;
            public int Segments = 24;
            public EndKind End;
            public bool GaussSeidel;
        }

        static readonly Spec[] s_Scene =
        {
            new Spec { RestLength = 1.5f, Segments = 16, End = EndKind.Free },
            new Spec { RestLength = 2f, Segments = 24, End = EndKind.Body, Mass = 80f },          // falls 1 m, then the rope arrests it
            new Spec { RestLength = 3f, Segments = 30, End = EndKind.Pinned, GaussSeidel = true },  // sags between two anchors
            new Spec { RestLength = 1f, Segments = 10, End = EndKind.Body, Mass = 500f, BreakStrain = 0.05f }, // breaks
            new Spec { RestLength = 2.5f, Segments = 20, End = EndKind.Body, Mass = 5f },
        };

        /// <summary>What a rope did, as raw bits, plus its break events (thread ids kept apart).</summary>
        sealed class Record
        {
            public readonly List<int> Bits = new List<int>();
            public int Steps, Breaks, BreakThread = -1;
            public float BreakTension;
            public Vector3 BreakPosition;
        }

        GameObject Track(GameObject go)
        {
            _objects.Add(go);
            return go;
        }

        /// <summary>Builds the scene's rope <paramref name="index"/>; its events count steps and breaks into <paramref name="record"/>.</summary>
        ElasticRope Build(int index, Record record)
        {
            var spec = s_Scene[index];
            var top = new Vector3(3f * index, 10f, 0f);
            var anchor = Track(new GameObject("Anchor " + index)).transform;
            anchor.position = top;
            // rope 0 is drawn too: by the world's draw pass while it is in the world
            var go = Track(index == 0 ? new GameObject("Rope 0", typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer))
                : new GameObject("Rope " + index));
            go.transform.position = top;
            var rope = index == 0 ? go.GetComponent<ElasticRope>() : go.AddComponent<ElasticRope>();
            rope.RestLength = spec.RestLength;
            rope.SegmentCount = spec.Segments;
            if (spec.GaussSeidel) rope.Solver = HookeRope.Solver.ConstraintSolverKind.GaussSeidel;
            rope.Fracture = spec.BreakStrain > 0f;
            if (spec.BreakStrain > 0f) rope.BreakStrain = spec.BreakStrain;
            rope.StartAttachment.Point = anchor;
            if (spec.End == EndKind.Pinned)
            {
                var other = Track(new GameObject("Other end " + index)).transform;
                other.position = top + new Vector3(0.8f * spec.RestLength, -0.2f, 0.3f);
                rope.EndAttachment.Point = other;
            }
            else if (spec.End == EndKind.Body)
            {
                var load = Track(new GameObject("Load " + index));
                load.transform.position = top + new Vector3(0.01f, 1f - spec.RestLength, 0f);
                var body = load.AddComponent<Rigidbody>();
                body.mass = spec.Mass;
                rope.EndAttachment.Body = body;
            }
            rope.Rebuild();
            rope.OnStepped.AddListener((start, end) => record.Steps++);
            rope.OnBreak.AddListener((position, tension) =>
            {
                record.Breaks++;
                record.BreakThread = Thread.CurrentThread.ManagedThreadId;
                record.BreakPosition = position;
                record.BreakTension = tension;
            });
            return rope;
        }

        static void Capture(ElasticRope rope, Record record)
        {
            for (int p = 0; p < rope.ParticleCount; p++) AddBits(record.Bits, rope.GetParticlePosition(p));
            AddBits(record.Bits, rope.StartForce);
            AddBits(record.Bits, rope.EndForce);
            record.Bits.Add(BitConverter.SingleToInt32Bits(rope.PeakTension));
            var body = rope.EndAttachment.Body;
            if (body != null)
            {
                AddBits(record.Bits, body.position);
                AddBits(record.Bits, body.velocity);
            }
        }

        static void AddBits(List<int> bits, Vector3 v)
        {
            bits.Add(BitConverter.SingleToInt32Bits(v.x));
            bits.Add(BitConverter.SingleToInt32Bits(v.y));
            bits.Add(BitConverter.SingleToInt32Bits(v.z));
        }

        static int Mismatches(List<int> a, List<int> b)
        {
            if (a.Count != b.Count) return int.MaxValue;
            int n = 0;
            for (int i = 0; i < a.Count; i++)
                if (a[i] != b[i]) n++;
            return n;
        }

        void DestroyAll()
        {
            foreach (var go in _objects)
                if (go != null) Object.Destroy(go);
            _objects.Clear();
        }

        /// <summary>Two frames: objects destroyed earlier (Destroy acts at the end of a frame) are gone.</summary>
        static IEnumerator Settle()
        {
            yield return null;
            yield return null;
        }

        static IEnumerator FixedSteps(int count)
        {
            for (int i = 0; i < count; i++) yield return new WaitForFixedUpdate();
        }

        // ---- tests ----------------------------------------------------------------------------------------------
        [UnityTest]
        public IEnumerator RopesInTheWorldGiveTheBitsOfEachRopeAloneAndBreakOnTheMainThread()
        {
            yield return Settle();
            Assert.That(ElasticRopeWorld.RopeCount, Is.EqualTo(0), "no rope left over from an earlier test");
            ElasticRopeWorld.WorkerCount = 2;
            int mainThread = Thread.CurrentThread.ManagedThreadId;

            var together = new Record[s_Scene.Length];
            var ropes = new ElasticRope[s_Scene.Length];
            for (int i = 0; i < s_Scene.Length; i++) ropes[i] = Build(i, together[i] = new Record());
            Assert.That(ElasticRopeWorld.RopeCount, Is.EqualTo(s_Scene.Length));
            Assert.That(ElasticRopeWorld.IsActive, Is.True);
            Assert.That(RopeWorldScheduler.World.WorkerCount, Is.EqualTo(2));
            yield return FixedSteps(Steps);
            for (int i = 0; i < ropes.Length; i++)
            {
                Assert.That(ropes[i].IsSteppedInWorld, Is.True, "rope " + i);
                Capture(ropes[i], together[i]);
            }
            yield return null;
            var drawn = ropes[0].GetComponent<RopeMeshRenderer>();
            Assert.That(drawn.DrawnFrame, Is.GreaterThanOrEqualTo(Time.frameCount - 1), "drawn by the world's pass in the last LateUpdate");
            Assert.That(drawn.Mesh.vertexCount, Is.GreaterThan(ropes[0].ParticleCount), "a tube around the rope");
            var world = RopeWorldScheduler.World;
            DestroyAll();
            yield return Settle();
            Assert.That(ElasticRopeWorld.RopeCount, Is.EqualTo(0));
            Assert.That(RopeWorldScheduler.World, Is.Null, "the last rope took the world with it");
            Assert.That(world.IsDisposed && !world.AnyWorkerAlive, Is.True, "its threads are joined");

            for (int i = 0; i < s_Scene.Length; i++)
            {
                var alone = new Record();
                var rope = Build(i, alone);
                Assert.That(rope.IsSteppedInWorld, Is.False);
                yield return FixedSteps(Steps);
                Capture(rope, alone);
                DestroyAll();
                yield return Settle();

                Assert.That(together[i].Steps, Is.EqualTo(Steps), "rope " + i + " stepped once per physics step in the world");
                Assert.That(alone.Steps, Is.EqualTo(Steps), "and alone");
                Assert.That(Mismatches(together[i].Bits, alone.Bits), Is.EqualTo(0), "rope " + i + ": positions, end forces, peak tension, body");
                Assert.That(together[i].Breaks, Is.EqualTo(alone.Breaks), "rope " + i + " breaks");
                if (alone.Breaks == 0) continue;
                Assert.That(together[i].BreakTension, Is.EqualTo(alone.BreakTension), "rope " + i + " break tension (N)");
                Assert.That(together[i].BreakPosition, Is.EqualTo(alone.BreakPosition), "rope " + i + " break position (m)");
                Assert.That(together[i].BreakThread, Is.EqualTo(mainThread), "OnBreak is raised on the main thread");
            }
            Assert.That(together[3].Breaks, Is.EqualTo(1), "the 500 kg load breaks its 5 % rope once");
            TestContext.WriteLine("rope 3 broke at " + together[3].BreakPosition + " with " + together[3].BreakTension + " N");
        }

        [UnityTest]
        public IEnumerator AWorkerOnALanyardInTheWorldIsArrestedAsAlone()
        {
            // WorkerFallArrestTests' scene: 100 kg falls 4 m on the default 2 m lanyard, undamped, at Unity's 50 Hz step
            yield return Settle();
            ElasticRopeWorld.WorkerCount = 2;
            const float G = 9.81f, Mass = 100f, FreeFall = 4f;
            float worldPeak = 0f, worldLowest = 0f;
            for (int run = 0; run < 2; run++)
            {
                var anchor = Track(new GameObject("Anchor")).transform;
                anchor.position = new Vector3(0f, 20f, 0f);
                var go = Track(new GameObject("Lanyard"));
                go.transform.position = anchor.position;
                var rope = go.AddComponent<ElasticRope>();
                var rig = Track(new GameObject("Worker"));
                rig.transform.position = new Vector3(0.01f, 20f + FreeFall - rope.RestLength, 0f);
                var worker = rig.AddComponent<Rigidbody>();
                worker.mass = Mass;
                rope.Damping = 0f;
                rope.StartAttachment.Point = anchor;
                rope.EndAttachment.Body = worker;
                rope.Rebuild();
                // run 0: two more ropes hang beside it, so the lanyard steps in the world
                if (run == 0)
                    for (int i = 1; i <= 2; i++) Build(i, new Record());
                Assert.That(rope.IsSteppedInWorld, Is.EqualTo(run == 0));

                float lowest = float.PositiveInfinity;
                for (int s = 0; s < 300; s++)
                {
                    yield return new WaitForFixedUpdate();
                    lowest = Math.Min(lowest, worker.position.y);
                }
                float weight = Mass * G, k = rope.AxialStiffness / rope.RestLength;
                float expected = weight + (float)Math.Sqrt(weight * weight + 2f * weight * k * FreeFall);
                TestContext.WriteLine((run == 0 ? "in the world" : "alone") + ": peak " + rope.PeakArrestForce + " N (energy balance " + expected + " N), lowest " + lowest + " m");
                Assert.That(rope.PeakArrestForce, Is.EqualTo(expected).Within(2).Percent);
                Assert.That(lowest, Is.EqualTo(20f - rope.RestLength - expected / k).Within(0.02f * expected / k + 0.02f));
                if (run == 0)
                {
                    worldPeak = rope.PeakArrestForce;
                    worldLowest = lowest;
                }
                else
                {
                    Assert.That(rope.PeakArrestForce, Is.EqualTo(worldPeak), "the same peak, to the bit (N)");
                    Assert.That(lowest, Is.EqualTo(worldLowest), "the same lowest point, to the bit (m)");
                }
                DestroyAll();
                yield return Settle();
            }
        }

        [UnityTest]
        public IEnumerator RopesDisabledDestroyedOrCreatedMidPlayLeaveAndJoinTheWorld()
        {
            yield return Settle();
            ElasticRopeWorld.WorkerCount = 2;
            var records = new Record[3];
            var ropes = new ElasticRope[3];
            for (int i = 0; i < 3; i++) ropes[i] = Build(i, records[i] = new Record());
            yield return FixedSteps(10);

            // disabled between steps: B leaves (and does not move), A and C go on in the world
            ropes[1].enabled = false;
            Assert.That(ElasticRopeWorld.RopeCount, Is.EqualTo(2));
            Vector3 frozen = ropes[1].GetParticlePosition(ropes[1].ParticleCount - 1);
            yield return FixedSteps(10);
            Assert.That(ropes[1].GetParticlePosition(ropes[1].ParticleCount - 1), Is.EqualTo(frozen), "a disabled rope is not stepped");
            Assert.That(ropes[0].IsSteppedInWorld && ropes[2].IsSteppedInWorld, Is.True);

            // destroyed: A is left alone and steps inline; B re-enabled joins it in the world again
            Object.Destroy(ropes[2].gameObject);
            yield return Settle();
            Assert.That(ElasticRopeWorld.RopeCount, Is.EqualTo(1));
            Assert.That(ropes[0].IsSteppedInWorld, Is.False, "one rope steps inline");
            int stepsAlone = records[0].Steps;
            yield return FixedSteps(5);
            Assert.That(records[0].Steps - stepsAlone, Is.EqualTo(5));
            ropes[1].enabled = true;
            Assert.That(ropes[0].IsSteppedInWorld && ropes[1].IsSteppedInWorld, Is.True);

            // during a pass: A's stepped event (copy-out, main thread) disables B and creates D. B was stepped in that
            // pass but gets no copy-out; D joins after the pass and steps once in every later physics step.
            var late = new Record();
            ElasticRope created = null;
            bool acted = false;
            ropes[0].OnStepped.AddListener((start, end) =>
            {
                if (acted) return;
                acted = true;
                ropes[1].enabled = false;
                created = Build(4, late);
            });
            int bSteps = records[1].Steps;
            yield return new WaitForFixedUpdate();
            Assert.That(acted, Is.True);
            Assert.That(records[1].Steps, Is.EqualTo(bSteps), "B's copy-out was left out");
            Assert.That(ElasticRopeWorld.RopeCount, Is.EqualTo(2), "A and D");
            Assert.That(late.Steps, Is.EqualTo(0), "D joined after the pass");
            yield return FixedSteps(7);
            Assert.That(late.Steps, Is.EqualTo(7), "D stepped once per physics step");
            Assert.That(created.IsSteppedInWorld, Is.True);

            // the last rope going stops the world's threads
            var world = RopeWorldScheduler.World;
            Assert.That(world.AnyWorkerAlive, Is.True);
            ropes[0].enabled = false;
            created.enabled = false;
            Assert.That(ElasticRopeWorld.RopeCount, Is.EqualTo(0));
            Assert.That(RopeWorldScheduler.World, Is.Null);
            Assert.That(world.IsDisposed && !world.AnyWorkerAlive, Is.True, "threads joined when the last rope was disabled");
        }
    }
}
