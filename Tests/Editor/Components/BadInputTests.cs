using System.Collections.Generic;
using System.Reflection;
using System.Text.RegularExpressions;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.TestTools;
using UnityEngine.TestTools.Constraints;
using Is = UnityEngine.TestTools.Constraints.Is;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): bad input from the scene and the inspector
    /// (Documentation~/index.md, "Bad input"). Each case logs one warning naming the object and the field, the rope
    /// keeps simulating from its last valid state, and neither the particles nor the mesh ever hold a non-finite value.
    /// </summary>
    [TestFixture]
    public sealed class BadInputTests
    {
        const float Dt = 0.02f, G = 9.81f;

        UnityRopeScene _scene;
        readonly List<string> _warnings = new List<string>();

        [SetUp]
        public void SetUp()
        {
            _scene = new UnityRopeScene();
            _scene.Begin();
            _warnings.Clear();
            Application.logMessageReceived += Collect;
        }

        [TearDown]
        public void TearDown()
        {
            Application.logMessageReceived -= Collect;
            _scene.End();
        }

        void Collect(string condition, string stackTrace, LogType type)
        {
            if (type == LogType.Warning) _warnings.Add(condition);
        }

        int WarningsContaining(string text)
        {
            int count = 0;
            foreach (var warning in _warnings)
                if (warning.Contains(text)) count++;
            return count;
        }

        /// <summary>A 2 m, 12-segment rope whose start follows <paramref name="anchor"/> at (0, 5, 0), with the mesh renderer.</summary>
        ElasticRope RopeFrom(Transform anchor)
        {
            var go = _scene.Track(new GameObject("Rope", typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer)));
            go.transform.position = anchor.position;
            var rope = go.GetComponent<ElasticRope>();
            rope.SegmentCount = 12;
            rope.StartAttachment.Point = anchor;
            return rope;
        }

        static void AssertFinite(ElasticRope rope)
        {
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                var p = rope.GetParticlePosition(i);
                Assert.That(float.IsFinite(p.x) && float.IsFinite(p.y) && float.IsFinite(p.z), Is.True, "particle " + i + " = " + p);
            }
        }

        static void AssertMeshFinite(Mesh mesh)
        {
            var vertices = MeshInUse.Vertices(mesh);
            Assert.That(vertices.Length, Is.GreaterThan(0));
            for (int v = 0; v < vertices.Length; v++)
                Assert.That(float.IsFinite(vertices[v].x) && float.IsFinite(vertices[v].y) && float.IsFinite(vertices[v].z), Is.True, "vertex " + v);
            var size = mesh.bounds.size;
            Assert.That(float.IsFinite(size.x) && float.IsFinite(size.y) && float.IsFinite(size.z), Is.True, "bounds");
        }

        /// <summary>The rope's renderer draws a mesh now, and every vertex and the bounds are finite.</summary>
        static void AssertDrawsFiniteMesh(ElasticRope rope)
        {
            var renderer = rope.GetComponent<RopeMeshRenderer>();
            Assert.That(renderer.Render(1f), Is.True);
            AssertMeshFinite(renderer.Mesh);
        }

        static Vector3 CentreOfMass(ElasticRope rope, out Vector3 velocity)
        {
            var core = rope.Simulation.Rope;
            Vector3 sum = Vector3.zero, momentum = Vector3.zero;
            float mass = 0f;
            for (int i = 0; i < core.ParticleCount; i++)
            {
                float m = core.GetParticleMass(i);
                sum += m * rope.GetParticlePosition(i);
                var v = core.GetVelocity(i);
                momentum += m * new Vector3(v.X, v.Y, v.Z);
                mass += m;
            }
            velocity = momentum / mass;
            return sum / mass;
        }

        [Test]
        public void DestroyedStartPointFreesTheEndAndTheRopeFallsAtG()
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 5f, 0f));
            var rope = RopeFrom(anchor);
            rope.Rebuild();
            UnityRopeScene.Run(rope, 50, Dt);
            Object.DestroyImmediate(anchor.gameObject);
            var com0 = CentreOfMass(rope, out var v0);

            const int steps = 25;
            for (int i = 0; i < steps; i++) rope.Simulate(Dt);

            // the free rope's centre of mass follows gravity alone: Δy = v0·t − g·t²/2 (semi-implicit Euler over the substeps adds < 1 %)
            float t = steps * Dt;
            var com = CentreOfMass(rope, out _);
            float expected = v0.y * t - 0.5f * G * t * t;
            TestContext.WriteLine($"destroyed anchor: centre of mass moved {com.y - com0.y:G5} m in {t} s, v0·t − g·t²/2 = {expected:G5} m");
            Assert.That(com.y - com0.y, Is.EqualTo(expected).Within(0.01f * System.Math.Abs(expected)));
            Assert.That(rope.Simulation.Rope.IsPinBroken(0), Is.True, "the start pin is released in place");
            Assert.That(WarningsContaining("ElasticRope 'Rope': Start.Point ('Anchor') was destroyed"), Is.EqualTo(1));
            AssertFinite(rope);

            // a later rebuild (new segment count) compares against the destroyed object and builds a free rope
            rope.SegmentCount = 16;
            rope.Simulate(Dt);
            Assert.That(rope.ParticleCount, Is.EqualTo(17));
            Assert.That(rope.Simulation.Rope.PinCount, Is.EqualTo(0));
            Assert.That(WarningsContaining("was destroyed"), Is.EqualTo(1), "one warning per cause");
            AssertDrawsFiniteMesh(rope);
        }

        [Test]
        public void DestroyedEndBodyTakesItsMassOutOfTheRope()
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 5f, 0f));
            var worker = _scene.Body("Worker", new Vector3(0f, 3f, 0f), 80f);
            var rope = RopeFrom(anchor);
            rope.EndAttachment.Body = worker;
            rope.Rebuild();
            var core = rope.Simulation.Rope;
            int last = rope.ParticleCount - 1;
            float share = core.GetParticleMass(last) - 80f;
            UnityRopeScene.Run(rope, 50, Dt);

            Object.DestroyImmediate(worker.gameObject);
            UnityRopeScene.Run(rope, 25, Dt);

            TestContext.WriteLine($"destroyed body: end particle {core.GetParticleMass(last):G4} kg (rope share {share:G4} kg), arrest force {rope.ArrestForce:G4} N");
            Assert.That(rope.Simulation.Rope, Is.SameAs(core), "handled in place, no rebuild");
            Assert.That(core.IsLoadReleased(0), Is.True);
            Assert.That(core.GetParticleMass(last), Is.EqualTo(share).Within(1e-4f), "only the rope's own share is left (kg)");
            Assert.That(share, Is.GreaterThan(0f).And.LessThan(0.1f));
            Assert.That(WarningsContaining("End.Body ('Worker') was destroyed"), Is.EqualTo(1));
            Assert.That(rope.ArrestForce, Is.LessThan(5f), "no worker left to arrest (N)");
            AssertFinite(rope);
        }

        [Test]
        public void NonFinitePoseKeepsTheLastPoseAndWarnsOncePerOccurrence()
        {
            var rig = _scene.Point("Rig", new Vector3(0f, 5f, 0f));
            var hand = _scene.Point("Hand", new Vector3(0f, 5f, 0f));
            hand.parent = rig;
            var rope = RopeFrom(hand);
            rope.Rebuild();
            UnityRopeScene.Run(rope, 10, Dt);

            // a huge rig scale carries a finite local offset to an infinite world position (Transform setters refuse NaN)
            rig.localScale = new Vector3(1e30f, 1e30f, 1e30f);
            hand.localPosition = new Vector3(1e10f, 0f, 0f);
            Assert.That(float.IsFinite(hand.position.x), Is.False, "hand x = " + hand.position.x);
            UnityRopeScene.Run(rope, 20, Dt);
            Assert.That(WarningsContaining("ElasticRope 'Rope': Start.Point ('Hand') is at a non-finite position"), Is.EqualTo(1));
            Assert.That((rope.GetParticlePosition(0) - new Vector3(0f, 5f, 0f)).magnitude, Is.LessThan(1e-5f), "the end keeps its last pose (m)");
            AssertFinite(rope);
            AssertDrawsFiniteMesh(rope);
            Assert.That(() => { rope.Simulate(Dt); }, Is.Not.AllocatingGCMemory(), "a cause already reported costs nothing");

            // the cause clears, then comes back: a second warning
            hand.localPosition = Vector3.zero;
            rope.Simulate(Dt);
            Assert.That(() => { rope.Simulate(Dt); }, Is.Not.AllocatingGCMemory(), "valid input costs nothing");
            hand.localPosition = new Vector3(1e10f, 0f, 0f);
            rope.Simulate(Dt);
            Assert.That(WarningsContaining("is at a non-finite position"), Is.EqualTo(2));
        }

        [TestCase(1e-7f, TestName = "BodyMassAtUnitysLimitsKeepsTheRopeFinite(1e-7 kg)")]
        [TestCase(1e9f, TestName = "BodyMassAtUnitysLimitsKeepsTheRopeFinite(1e9 kg)")]
        public void BodyMassAtUnitysLimitsKeepsTheRopeFinite(float mass)
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 5f, 0f));
            var body = _scene.Body("Load", new Vector3(0f, 3f, 0f), mass);
            var rope = RopeFrom(anchor);
            rope.EndAttachment.Body = body;
            rope.Rebuild();
            UnityRopeScene.Run(rope, 100, Dt);

            AssertFinite(rope);
            var p = body.position;
            Assert.That(float.IsFinite(p.x) && float.IsFinite(p.y) && float.IsFinite(p.z), Is.True, "body position " + p);
            AssertDrawsFiniteMesh(rope);
            TestContext.WriteLine($"body of {mass:G3} kg after 2 s: y = {p.y:G6} m, top tension {rope.TopTension:G4} N");
            if (mass < 1f)
                Assert.That(p.y, Is.EqualTo(3f).Within(0.02f), "a near-massless body hangs at the rope's rest length (m)");
            else
            {
                // 1e9 kg: no rope holds it; it snaps the rope at its break strain and falls at g (g·t²/2 = 19.6 m in 2 s)
                Assert.That(rope.IsBroken, Is.True);
                Assert.That(3f - p.y, Is.EqualTo(0.5f * G * 4f).Within(0.5f));
            }
        }

        [TestCase(float.PositiveInfinity)]
        [TestCase(float.NaN)]
        public void NonFiniteMassIsRefusedByUnityAndTheRopeKeepsTheBodysMass(float mass)
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 5f, 0f));
            var body = _scene.Body("Worker", new Vector3(0f, 3f, 0f), 80f);
            LogAssert.Expect(LogType.Error, new Regex(@"^rigidbody\.mass assign attempt for 'Worker' is not valid"));
            body.mass = mass;
            var rope = RopeFrom(anchor);
            rope.EndAttachment.Body = body;
            rope.Rebuild();
            var core = rope.Simulation.Rope;
            Assert.That(core.LoadCount, Is.EqualTo(1));
            Assert.That(core.GetParticleMass(rope.ParticleCount - 1), Is.GreaterThan(80f).And.LessThan(80.1f));
            UnityRopeScene.Run(rope, 50, Dt);
            AssertFinite(rope);
        }

        [Test]
        public void ZeroScaleKeepsTheLastMeshAndWarnsOnce()
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 5f, 0f));
            var rope = RopeFrom(anchor);
            rope.Rebuild();
            var renderer = rope.GetComponent<RopeMeshRenderer>();
            UnityRopeScene.Run(rope, 10, Dt);
            Assert.That(renderer.Render(1f), Is.True);
            var before = renderer.Mesh.vertices;

            rope.transform.localScale = Vector3.zero;
            UnityRopeScene.Run(rope, 10, Dt);
            Assert.That(renderer.Render(1f), Is.False);
            Assert.That(renderer.Render(1f), Is.False);
            Assert.That(WarningsContaining("RopeMeshRenderer 'Rope': Transform scale (0, 0, 0)"), Is.EqualTo(1));
            var kept = renderer.Mesh.vertices;
            Assert.That(kept.Length, Is.EqualTo(before.Length));
            for (int v = 0; v < kept.Length; v++) Assert.That(kept[v], Is.EqualTo(before[v]), "vertex " + v);
            AssertFinite(rope);

            rope.transform.localScale = Vector3.one;
            Assert.That(renderer.Render(1f), Is.True);
            AssertMeshFinite(renderer.Mesh);
        }

        [Test]
        public void PointUnderAZeroScaledParentIsAValidPoseAtTheParent()
        {
            var rig = _scene.Point("Rig", new Vector3(0f, 5f, 0f));
            var hand = _scene.Point("Hand", new Vector3(0.5f, 5f, 0f));
            hand.parent = rig;
            var rope = RopeFrom(hand);
            rope.Rebuild();
            rig.localScale = Vector3.zero;
            UnityRopeScene.Run(rope, 10, Dt);
            Assert.That((rope.GetParticlePosition(0) - new Vector3(0f, 5f, 0f)).magnitude, Is.LessThan(1e-5f), "the hand collapses onto the rig (m)");
            Assert.That(_warnings.Count, Is.EqualTo(0));
            AssertFinite(rope);
        }

        [Test]
        public void BothEndsOnTheSamePointHangAsALoop()
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 5f, 0f));
            var rope = RopeFrom(anchor);
            rope.EndAttachment.Point = anchor;
            rope.Rebuild();
            UnityRopeScene.Run(rope, 150, Dt);

            AssertFinite(rope);
            float lowest = float.PositiveInfinity;
            for (int i = 0; i < rope.ParticleCount; i++) lowest = System.Math.Min(lowest, rope.GetParticlePosition(i).y);
            TestContext.WriteLine($"both ends at one point: fold {5f - lowest:G4} m below it");
            // two 1 m halves hanging from one point: the fold is about 1 m below it
            Assert.That(5f - lowest, Is.EqualTo(1f).Within(0.1f));
            AssertDrawsFiniteMesh(rope);
        }

        [Test]
        public void InspectorValuesAboveTheTableAreClampedWithAMessageAndTheRopeKeepsRunning()
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 5f, 0f));
            var rope = RopeFrom(anchor);
            rope.Rebuild();
            UnityRopeScene.Run(rope, 5, Dt);

            var so = new SerializedObject(rope);
            so.FindProperty("m_RestLength").floatValue = 20000f;
            so.ApplyModifiedProperties();
            Assert.That(rope.RestLength, Is.EqualTo(RopeParameters.RestLength.Max));
            Assert.That(WarningsContaining("ElasticRope 'Rope': Rest length = 20000 m is outside [0.01, 10000] m; clamped to 10000 m."), Is.EqualTo(1));

            // from code the setter refuses the value and the rope keeps the clamped one
            Assert.That(() => rope.RestLength = 1e5f, Throws.TypeOf<System.ArgumentOutOfRangeException>().With.Message.Contains("RestLength"));
            Assert.That(rope.RestLength, Is.EqualTo(10000f));
            rope.RestLength = 2f;
            UnityRopeScene.Run(rope, 5, Dt);
            AssertFinite(rope);
        }

        [Test]
        public void ASceneSavedWithTooManySegmentsIsClampedAtTheBuild()
        {
            // a value out of range stored in a scene reaches a player, where OnValidate never runs
            var anchor = _scene.Point("Anchor", new Vector3(0f, 5f, 0f));
            var rope = RopeFrom(anchor);
            typeof(ElasticRope).GetField("m_SegmentCount", BindingFlags.Instance | BindingFlags.NonPublic).SetValue(rope, 20000);
            rope.Rebuild();
            Assert.That(rope.ParticleCount, Is.EqualTo(RopeParameters.SegmentCount.Max + 1));
            Assert.That(WarningsContaining("ElasticRope 'Rope': Segment count = 20000 is outside [1, 10000]; clamped to 10000."), Is.EqualTo(1));
            rope.Simulate(Dt);
            TestContext.WriteLine("10 000 segments: one 0.02 s step took " + rope.StepMilliseconds + " ms");
            AssertFinite(rope);
        }
    }
}
