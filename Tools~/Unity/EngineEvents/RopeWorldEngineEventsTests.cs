using System;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;

namespace HookeRope.StandIn.EngineEvents
{
    /// <summary>
    /// The shared multi-rope world against the engine's events, which only the stand-in can raise from a test (Unity
    /// raises them when Play mode ends or the scripts reload): with two ropes enabled in Play on two workers, the
    /// world's threads are stopped by Application.quitting (raised when the Editor leaves Play mode, before the scene is
    /// destroyed) and by AssemblyReloadEvents.beforeAssemblyReload (the package editor's [InitializeOnLoad] hook), while
    /// the ropes are still enabled.
    /// </summary>
    [TestFixture]
    public sealed class RopeWorldEngineEventsTests
    {
        bool _wasPlaying;
        int _workers;

        [SetUp]
        public void SetUp()
        {
            _wasPlaying = World.IsPlaying;
            _workers = ElasticRopeWorld.WorkerCount;
            World.Reset();
            World.IsPlaying = true;
            ElasticRopeWorld.WorkerCount = 2;
        }

        [TearDown]
        public void TearDown()
        {
            if (World.IsPlaying) World.Reset();
            RopeWorldScheduler.Shutdown();
            World.Reset();
            World.IsPlaying = _wasPlaying;
            ElasticRopeWorld.WorkerCount = _workers;
        }

        /// <summary>Two hanging ropes enabled in Play, stepped for a few frames by the world.</summary>
        static ElasticRope[] TwoRopesInTheWorld()
        {
            var ropes = new ElasticRope[2];
            for (int i = 0; i < 2; i++)
            {
                var go = new GameObject("Rope " + i, typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer));
                go.transform.position = new Vector3(2f * i, 5f, 0f);
                ropes[i] = go.GetComponent<ElasticRope>();
            }
            PlayerLoop.RunFrames(5);
            Assert.That(ropes[0].IsSteppedInWorld && ropes[1].IsSteppedInWorld, Is.True);
            Assert.That(RopeWorldScheduler.World.AnyWorkerAlive, Is.True);
            return ropes;
        }

        [Test]
        public void LeavingPlayModeStopsTheWorldThreadsAtApplicationQuitting()
        {
            var ropes = TwoRopesInTheWorld();
            var world = RopeWorldScheduler.World;
            string seen = null;
            // subscribed after the world's own handler, so it sees what that handler left
            Action probe = () => seen = "world disposed " + world.IsDisposed + ", threads alive " + world.AnyWorkerAlive +
                                        ", ropes enrolled " + ElasticRopeWorld.RopeCount + ", rope enabled " + ropes[0].isActiveAndEnabled;
            Application.quitting += probe;
            try
            {
                World.ExitPlayMode();
            }
            finally
            {
                Application.quitting -= probe;
            }
            Assert.That(seen, Is.EqualTo("world disposed True, threads alive False, ropes enrolled 0, rope enabled True"));
            Assert.That(RopeWorldScheduler.World, Is.Null);
        }

        [Test]
        public void AScriptReloadStopsTheWorldThreadsFirst()
        {
            var ropes = TwoRopesInTheWorld();
            var world = RopeWorldScheduler.World;
            AssemblyReloadEvents.InvokeBeforeAssemblyReload();
            Assert.That(world.IsDisposed && !world.AnyWorkerAlive, Is.True, "the editor hook stopped the threads");
            Assert.That(ElasticRopeWorld.RopeCount, Is.EqualTo(0));
            Assert.That(ropes[0].isActiveAndEnabled && !ropes[0].IsSteppedInWorld, Is.True, "the ropes are still there, stepping alone");
        }
    }
}
