using System.Collections;
using HookeRope.Editor;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode: the editor hook (<see cref="RopeDropWiring"/>) wires a rope that lands on a harness rig, on the editor
    /// update after the undoable change, as Unity publishes ObjectChangeEvents. The package prefab dropped under a
    /// 100 kg worker with a "Harness D-Ring" child (InstantiatePrefab plus Undo.RegisterCreatedObjectUndo, what a drop
    /// into the Hierarchy records) ends up with End on the worker at the D-ring and Start on a root-level anchor the
    /// 2 m rest length above it, with one console line; a rope dragged under the rig (Undo.SetTransformParent) is
    /// wired the same way; a rope whose End.Body the user set is left exactly as it was, with no line.
    /// </summary>
    [TestFixture]
    public sealed class RopeDropWiringTests
    {
        const string PrefabPath = "Packages/com.hookerope.elastic-rope/Runtime/Prefabs/ElasticRope.prefab";
        const string LinePrefix = "HookeRope wired onto the rig: ";
        static readonly Vector3 DRingOffset = new Vector3(0f, 0.4f, 0.1f);
        UnityRopeScene _scene;
        int _wiringLines;
        string _lastLine;

        [SetUp]
        public void SetUp()
        {
            _scene = new UnityRopeScene();
            _scene.Begin();
            _wiringLines = 0;
            Application.logMessageReceived += CountWiringLines;
        }

        [TearDown]
        public void TearDown()
        {
            Application.logMessageReceived -= CountWiringLines;
            _scene.End();
        }

        void CountWiringLines(string message, string stackTrace, LogType type)
        {
            if (type == LogType.Log && message.StartsWith(LinePrefix, System.StringComparison.Ordinal))
            {
                _wiringLines++;
                _lastLine = message;
            }
        }

        ElasticRope DropPrefab(Transform parent)
        {
            var prefab = AssetDatabase.LoadAssetAtPath<GameObject>(PrefabPath);
            Assert.That(prefab, Is.Not.Null, PrefabPath);
            var instance = (GameObject)PrefabUtility.InstantiatePrefab(prefab, parent);
            _scene.Track(instance);
            Undo.RegisterCreatedObjectUndo(instance, "Drop Elastic Rope");
            return instance.GetComponent<ElasticRope>();
        }

        void AssertWiredOnto(ElasticRope rope, Rigidbody worker, Transform dRing)
        {
            Assert.That(rope.EndAttachment.Body, Is.SameAs(worker));
            Assert.That(rope.EndAttachment.Point, Is.SameAs(dRing));
            var anchor = rope.StartAttachment.Point;
            Assert.That(anchor, Is.Not.Null);
            _scene.Track(anchor.gameObject);
            Assert.That(rope.StartAttachment.Body, Is.Null);
            Assert.That(anchor.parent, Is.Null, "the anchor is a root-level object");
            Assert.That(anchor.name, Is.EqualTo(rope.name + " Anchor"));
            Assert.That(rope.RestLength, Is.EqualTo(2f));
            Assert.That((anchor.position - (dRing.position + new Vector3(0f, rope.RestLength, 0f))).magnitude, Is.LessThan(1e-5f),
                "the anchor is the rest length (2 m) above the D-ring");
        }

        [UnityTest]
        public IEnumerator PrefabDroppedOnAWorkerRigIsWiredOnTheNextEditorUpdate()
        {
            var worker = _scene.Rig(new Vector3(0f, 2f, 0f), 100f, DRingOffset, out var dRing);
            var rope = DropPrefab(worker.transform);
            Assert.That(rope.EndAttachment.Body, Is.Null, "published on the next editor update, not at once");

            yield return null;
            AssertWiredOnto(rope, worker, dRing);
            Assert.That(worker.mass, Is.EqualTo(100f));
            Assert.That(_wiringLines, Is.EqualTo(1));
            Assert.That(_lastLine, Is.EqualTo(LinePrefix + "Elastic Rope: End pulls Rigidbody 'Worker' at 'Harness D-Ring'; Start anchored at 'Elastic Rope Anchor' 2 m above it."),
                "the line names the anchor it created (described before wiring, not as an existing one)");

            yield return null; // the anchor's own creation event is published now: nothing more to wire
            Assert.That(_wiringLines, Is.EqualTo(1));
        }

        [UnityTest]
        public IEnumerator RopeDraggedUnderARigIsWired()
        {
            var worker = _scene.Rig(new Vector3(0f, 2f, 0f), 100f, DRingOffset, out var dRing);
            var rope = DropPrefab(null);
            yield return null;
            Assert.That(rope.EndAttachment.Body, Is.Null, "at the scene root there is no rig");
            Assert.That(_wiringLines, Is.EqualTo(0));

            Undo.SetTransformParent(rope.transform, worker.transform, "Drag Elastic Rope");
            yield return null;
            AssertWiredOnto(rope, worker, dRing);
            Assert.That(_wiringLines, Is.EqualTo(1));
        }

        [UnityTest]
        public IEnumerator RopeWithAnEndBodySetIsLeftAlone()
        {
            var worker = _scene.Rig(new Vector3(0f, 2f, 0f), 100f, DRingOffset, out _);
            var other = _scene.Body("Other", new Vector3(3f, 1f, 0f), 20f);
            var rope = DropPrefab(null);
            rope.EndAttachment.Body = other;
            var start = rope.StartAttachment.Point;
            Undo.SetTransformParent(rope.transform, worker.transform, "Drag Elastic Rope");
            yield return null;

            Assert.That(rope.EndAttachment.Body, Is.SameAs(other));
            Assert.That(rope.EndAttachment.Point, Is.Null);
            Assert.That(rope.StartAttachment.Point, Is.SameAs(start));
            Assert.That(rope.StartAttachment.Body, Is.Null);
            Assert.That(GameObject.Find(rope.name + " Anchor"), Is.Null, "no anchor created");
            Assert.That(_wiringLines, Is.EqualTo(0));
        }
    }
}
