using System;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// The stand-in's object model and player loop against Unity's documentation: "Order of execution for event
    /// functions" (Awake and OnEnable at instantiation, Start before the first update, FixedUpdate before Update
    /// before LateUpdate, OnDisable before OnDestroy), Object.Destroy ("actual object destruction is always delayed
    /// until after the current Update loop, but will always be done before rendering") against DestroyImmediate,
    /// the fake null of destroyed objects (UnityEngineObject.bindings.cs CompareBaseObjects), RequireComponent,
    /// DisallowMultipleComponent, and the fixed time step (as many fixed updates per frame as fixedDeltaTime fits).
    /// </summary>
    [TestFixture]
    public sealed class LifecycleFactsTests
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
        public void PlayModeOrderOfMessages()
        {
            World.IsPlaying = true;
            var go = new GameObject("A", typeof(LifecycleProbe));
            Assert.That(LifecycleProbe.Calls, Is.EqualTo(new[] { "A.Awake", "A.OnEnable" }), "Awake and OnEnable run inside AddComponent");
            PlayerLoop.RunFrames(1);
            Assert.That(LifecycleProbe.Calls, Is.EqualTo(new[] { "A.Awake", "A.OnEnable", "A.Start", "A.FixedUpdate@0.00", "A.Update", "A.LateUpdate" }));

            LifecycleProbe.Calls.Clear();
            go.SetActive(false);
            PlayerLoop.RunFrames(1);
            go.SetActive(true);
            Object.DestroyImmediate(go);
            Assert.That(LifecycleProbe.Calls, Is.EqualTo(new[] { "A.OnDisable", "A.OnEnable", "A.OnDisable", "A.OnDestroy" }));
        }

        [Test]
        public void DefaultExecutionOrderSortsScriptsBeforeCreationOrder()
        {
            // Manual "Script Execution Order": lower values run first; scripts without the attribute have 0.
            World.IsPlaying = true;
            var late = new GameObject("L", typeof(LateProbe));
            var plain = new GameObject("P", typeof(LifecycleProbe));
            var early = new GameObject("E", typeof(EarlyProbe));
            LifecycleProbe.Calls.Clear();
            PlayerLoop.RunFrames(1);
            Assert.That(LifecycleProbe.Calls, Is.EqualTo(new[]
            {
                "P.Start",
                "E.Early.FixedUpdate", "P.FixedUpdate@0.00", "L.Late.FixedUpdate",
                "E.Early.Update", "P.Update", "L.Late.Update",
                "P.LateUpdate",
            }));
            Assert.That(late && plain && early, Is.True);
        }

        [Test]
        public void DisabledScriptIsAwakenedButNotEnabled()
        {
            World.IsPlaying = true;
            var go = new GameObject("B");
            go.SetActive(false);
            var probe = go.AddComponent<LifecycleProbe>();
            Assert.That(LifecycleProbe.Calls, Is.Empty, "nothing runs on an inactive GameObject");
            probe.enabled = false;
            go.SetActive(true);
            Assert.That(LifecycleProbe.Calls, Is.EqualTo(new[] { "B.Awake" }));
            PlayerLoop.RunFrames(2);
            Assert.That(LifecycleProbe.Calls, Is.EqualTo(new[] { "B.Awake" }), "a disabled script gets no Start or updates");
        }

        [Test]
        public void EditModeRunsOnlyExecuteAlwaysScripts()
        {
            World.IsPlaying = false;
            var go = new GameObject("C", typeof(LifecycleProbe), typeof(EditModeProbe));
            PlayerLoop.RunFrames(3);
            Assert.That(LifecycleProbe.Calls, Is.Empty);
            var always = go.GetComponent<EditModeProbe>();
            Assert.That(always.Awakes, Is.EqualTo(1));
            Assert.That(always.Updates, Is.EqualTo(3));
        }

        [Test]
        public void DestroyWaitsForTheEndOfTheFrameButDestroyImmediateDoesNot()
        {
            World.IsPlaying = true;
            var deferred = new GameObject("Deferred", typeof(LifecycleProbe));
            var immediate = new GameObject("Immediate");
            var component = deferred.GetComponent<LifecycleProbe>();

            PlayerLoop.RunUntil(LoopPoint.AfterUpdate);
            Object.Destroy(deferred);
            Assert.That(deferred == null, Is.False, "still alive during the frame that destroyed it");
            PlayerLoop.FinishFrame();
            Assert.That(deferred == null, Is.True);
            Assert.That(component == null, Is.True, "its components go with it");
            Assert.That(LifecycleProbe.Calls, Does.Contain("Deferred.LateUpdate"), "LateUpdate of that frame still ran");
            Assert.That(LifecycleProbe.Calls[LifecycleProbe.Calls.Count - 1], Is.EqualTo("Deferred.OnDestroy"));

            Object.DestroyImmediate(immediate);
            Assert.That(immediate == null, Is.True);
        }

        [Test]
        public void DestroyedObjectsAreFakeNull()
        {
            var go = new GameObject("D");
            Object.DestroyImmediate(go);
            Assert.That(go == null, Is.True);
            Assert.That((bool)go, Is.False);
            Assert.That(go.Equals(null), Is.True);
            Assert.That(ReferenceEquals(go, null), Is.False, "the C# object itself is still there");
            Assert.Throws<MissingReferenceException>(() => { var _ = go.transform; });
        }

        [Test]
        public void DestroyInEditModeIsAnErrorAndDestroysNothing()
        {
            World.IsPlaying = false;
            var go = new GameObject("E");
            LogAssert.Expect(LogType.Error, "Destroy may not be called from edit mode! Use DestroyImmediate instead.\nDestroying an object in edit mode destroys it permanently.");
            Object.Destroy(go);
            PlayerLoop.RunFrames(1);
            Assert.That(go == null, Is.False);
        }

        [Test]
        public void RequireComponentAddsFirstAndDisallowMultipleRefuses()
        {
            var go = new GameObject("F", typeof(SingleProbe));
            var components = go.GetComponents<Component>();
            Assert.That(components.Length, Is.EqualTo(3));
            Assert.That(components[1], Is.InstanceOf<Rigidbody>(), "the required Rigidbody is added before the script");
            LogAssert.Expect(LogType.Error, "Can't add component 'SingleProbe' to F because such a component is already added to the game object!");
            Assert.That(go.AddComponent<SingleProbe>(), Is.Null);
        }

        [TestCase(1f / 90f, 90, 50)]
        [TestCase(0.05f, 10, 23)]
        [TestCase(1f, 3, 34)]
        public void FixedStepsFollowTheFrameClock(float frameInterval, int frames, int expectedFixedSteps)
        {
            // First frame at t = 0 runs the step at 0; each later frame adds min(interval, maximumDeltaTime = 1/3 s);
            // the steps run are those starting at k·fixedDeltaTime <= t: floor(t / 0.02) + 1.
            World.IsPlaying = true;
            PlayerLoop.FrameInterval = frameInterval;
            new GameObject("G", typeof(LifecycleProbe));
            PlayerLoop.RunFrames(frames);
            int steps = LifecycleProbe.Calls.FindAll(c => c.StartsWith("G.FixedUpdate", StringComparison.Ordinal)).Count;
            Assert.That(steps, Is.EqualTo(expectedFixedSteps));
            float elapsed = (frames - 1) * Math.Min(frameInterval, Time.maximumDeltaTime);
            Assert.That(Time.time, Is.EqualTo(elapsed).Within(1e-4f));
            Assert.That(Time.fixedTime, Is.LessThanOrEqualTo(Time.time + 1e-5f));
            Assert.That(Time.time - Time.fixedTime, Is.LessThan(Time.fixedDeltaTime), "render time is inside the last fixed step");
        }
    }
}
