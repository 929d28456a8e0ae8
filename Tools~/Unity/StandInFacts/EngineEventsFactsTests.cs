using System;
using System.Collections.Generic;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// The members the shared multi-rope world uses (issue 18 item 4) against Unity's documentation:
    /// Time.fixedTimeAsDouble ("the double precision time the latest FixedUpdate has started"), Application.quitting
    /// ("invoked when exiting Play mode"; the stand-in raises it before the scene is destroyed), AssemblyReloadEvents
    /// .beforeAssemblyReload (every subscriber, in order) and SystemInfo.processorCount (the logical processors).
    /// </summary>
    [TestFixture]
    public sealed class EngineEventsFactsTests
    {
        bool _wasPlaying;

        [SetUp]
        public void SetUp()
        {
            _wasPlaying = World.IsPlaying;
            World.Reset();
            LifecycleProbe.Calls.Clear();
        }

        [TearDown]
        public void TearDown()
        {
            World.Reset();
            World.IsPlaying = _wasPlaying;
        }

        [Test]
        public void FixedTimeAsDoubleIsTheFixedTimeInDoublePrecision()
        {
            World.IsPlaying = true;
            Time.fixedDeltaTime = 0.02f;
            PlayerLoop.RunSeconds(1f);
            // frames at 1/90 s: the last frame starts at 90/90 s, so fixed steps ran at 0, 0.02, …, 1.0 s
            Assert.That(Time.fixedTimeAsDouble, Is.EqualTo(50 * (double)0.02f).Within(1e-9));
            Assert.That((float)Time.fixedTimeAsDouble, Is.EqualTo(Time.fixedTime));
        }

        [Test]
        public void ExitingPlayModeRaisesQuittingThenDestroysTheScene()
        {
            World.IsPlaying = true;
            new GameObject("Q", typeof(LifecycleProbe));
            PlayerLoop.RunFrames(1);
            var seen = new List<string>();
            Action quitting = () => seen.Add("quitting (Play " + Application.isPlaying + ", " + World.ObjectCount + " object)");
            Application.quitting += quitting;
            try
            {
                LifecycleProbe.Calls.Clear();
                World.ExitPlayMode();
            }
            finally
            {
                Application.quitting -= quitting;
            }
            Assert.That(seen, Is.EqualTo(new[] { "quitting (Play True, 1 object)" }));
            Assert.That(LifecycleProbe.Calls, Is.EqualTo(new[] { "Q.OnDisable", "Q.OnDestroy" }), "then the scene goes");
            Assert.That(Application.isPlaying, Is.False);
            Assert.Throws<InvalidOperationException>(World.ExitPlayMode, "only from Play mode");
        }

        [Test]
        public void BeforeAssemblyReloadCallsEverySubscriberInOrder()
        {
            var seen = new List<string>();
            AssemblyReloadEvents.AssemblyReloadCallback first = () => seen.Add("first");
            AssemblyReloadEvents.AssemblyReloadCallback failing = () => throw new InvalidOperationException("subscriber failed");
            AssemblyReloadEvents.AssemblyReloadCallback last = () => seen.Add("last");
            AssemblyReloadEvents.beforeAssemblyReload += first;
            AssemblyReloadEvents.beforeAssemblyReload += failing;
            AssemblyReloadEvents.beforeAssemblyReload += last;
            try
            {
                LogAssert.Expect(LogType.Exception, "InvalidOperationException: subscriber failed");
                AssemblyReloadEvents.InvokeBeforeAssemblyReload();
            }
            finally
            {
                AssemblyReloadEvents.beforeAssemblyReload -= first;
                AssemblyReloadEvents.beforeAssemblyReload -= failing;
                AssemblyReloadEvents.beforeAssemblyReload -= last;
            }
            Assert.That(seen, Is.EqualTo(new[] { "first", "last" }), "a failing subscriber is logged and the next one runs");
        }

        [Test]
        public void ProcessorCountIsTheLogicalProcessorCount()
        {
            Assert.That(SystemInfo.processorCount, Is.EqualTo(Environment.ProcessorCount));
            Assert.That(SystemInfo.processorCount, Is.GreaterThanOrEqualTo(1));
        }
    }
}
