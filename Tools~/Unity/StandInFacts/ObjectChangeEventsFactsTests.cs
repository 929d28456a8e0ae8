using System;
using System.Collections.Generic;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// The stand-in's ObjectChangeEvents behave as the Scripting Reference ("ObjectChangeEvents.changesPublished",
    /// "ObjectChangeKind") and UCR 2022.3 Editor/Mono/Undo/EditorObjectChangeEvents.cs describe (STAND-IN.md, "Object
    /// change events and editor load"): undoable creations and re-parentings are published once, batched, on the next
    /// editor update, in the order applied; InstanceIDToObject finds the objects; [InitializeOnLoad] static
    /// constructors have run once before the first test.
    /// </summary>
    [TestFixture]
    public sealed class ObjectChangeEventsFactsTests
    {
        const string PrefabPath = "Packages/com.hookerope.elastic-rope/Runtime/Prefabs/ElasticRope.prefab";
        readonly List<(ObjectChangeKind Kind, int Id, int Previous, int Next)> _published = new List<(ObjectChangeKind, int, int, int)>();
        int _batches;

        [SetUp]
        public void SetUp()
        {
            World.Reset();
            _published.Clear();
            _batches = 0;
            ObjectChangeEvents.changesPublished += Record;
        }

        [TearDown]
        public void TearDown()
        {
            ObjectChangeEvents.changesPublished -= Record;
            World.Reset();
        }

        void Record(ref ObjectChangeEventStream stream)
        {
            _batches++;
            for (int i = 0; i < stream.length; i++)
            {
                var kind = stream.GetEventType(i);
                if (kind == ObjectChangeKind.CreateGameObjectHierarchy)
                {
                    stream.GetCreateGameObjectHierarchyEvent(i, out var created);
                    _published.Add((kind, created.instanceId, 0, 0));
                }
                else if (kind == ObjectChangeKind.ChangeGameObjectParent)
                {
                    stream.GetChangeGameObjectParentEvent(i, out var parent);
                    _published.Add((kind, parent.instanceId, parent.previousParentInstanceId, parent.newParentInstanceId));
                }
            }
        }

        [Test]
        public void ARegisteredCreationIsPublishedOnceOnTheNextEditorUpdate()
        {
            var a = new GameObject("A");
            var b = new GameObject("B");
            Undo.RegisterCreatedObjectUndo(a, "Create A");
            Undo.RegisterCreatedObjectUndo(b, "Create B");
            Assert.That(_published.Count, Is.EqualTo(0), "not at once");

            PlayerLoop.RunFrames(1);
            Assert.That(_batches, Is.EqualTo(1), "one batch");
            Assert.That(_published.Count, Is.EqualTo(2));
            Assert.That(_published[0].Kind, Is.EqualTo(ObjectChangeKind.CreateGameObjectHierarchy));
            Assert.That(_published[0].Id, Is.EqualTo(a.GetInstanceID()), "in the order applied");
            Assert.That(_published[1].Id, Is.EqualTo(b.GetInstanceID()));
            Assert.That(EditorUtility.InstanceIDToObject(_published[1].Id), Is.SameAs(b));

            PlayerLoop.RunFrames(3);
            Assert.That(_batches, Is.EqualTo(1), "nothing new, nothing published");
        }

        [Test]
        public void InstantiatePrefabAloneAndPlainSetParentPublishNothing()
        {
            var prefab = AssetDatabase.LoadAssetAtPath<GameObject>(PrefabPath);
            var instance = (GameObject)PrefabUtility.InstantiatePrefab(prefab);
            var parent = new GameObject("Parent");
            instance.transform.SetParent(parent.transform, true);
            PlayerLoop.RunFrames(1);
            Assert.That(_batches, Is.EqualTo(0), "neither change is undoable");
        }

        [Test]
        public void SetTransformParentPublishesTheOldAndNewParentAndKeepsTheWorldPose()
        {
            var parent = new GameObject("Parent");
            parent.transform.position = new Vector3(1f, 2f, 3f);
            var child = new GameObject("Child");
            child.transform.position = new Vector3(0f, 5f, 0f);

            Undo.SetTransformParent(child.transform, parent.transform, "Parent");
            Undo.SetTransformParent(child.transform, parent.transform, "Same parent"); // no change, no event
            PlayerLoop.RunFrames(1);

            Assert.That(child.transform.parent, Is.SameAs(parent.transform));
            Assert.That((child.transform.position - new Vector3(0f, 5f, 0f)).magnitude, Is.LessThan(1e-5f));
            Assert.That(_published.Count, Is.EqualTo(1));
            Assert.That(_published[0].Kind, Is.EqualTo(ObjectChangeKind.ChangeGameObjectParent));
            Assert.That(_published[0].Id, Is.EqualTo(child.GetInstanceID()));
            Assert.That(_published[0].Previous, Is.EqualTo(0), "it was a root");
            Assert.That(_published[0].Next, Is.EqualTo(parent.GetInstanceID()));

            Undo.SetTransformParent(child.transform, null, false, "Unparent");
            PlayerLoop.RunFrames(1);
            Assert.That(_published.Count, Is.EqualTo(2));
            Assert.That(_published[1].Previous, Is.EqualTo(parent.GetInstanceID()));
            Assert.That(_published[1].Next, Is.EqualTo(0));
            Assert.That((child.transform.localPosition - new Vector3(-1f, 3f, -3f)).magnitude, Is.LessThan(1e-5f), "worldPositionStays false keeps the local position");
        }

        [Test]
        public void AGetterOfTheWrongKindThrowsAndADestroyedIdResolvesToNull()
        {
            var go = new GameObject("Gone");
            Undo.RegisterCreatedObjectUndo(go, "Create");
            ObjectChangeEventStream copy = default;
            int id = go.GetInstanceID();
            ObjectChangeEvents.ObjectChangeEventsHandler probe = (ref ObjectChangeEventStream stream) =>
            {
                var s = stream;
                Assert.Throws<InvalidOperationException>(() => s.GetChangeGameObjectParentEvent(0, out _));
                copy = stream;
            };
            ObjectChangeEvents.changesPublished += probe;
            try { PlayerLoop.RunFrames(1); }
            finally { ObjectChangeEvents.changesPublished -= probe; }
            Assert.That(copy.length, Is.EqualTo(1));
            Assert.That(copy.isCreated, Is.True);
            Assert.That(EditorUtility.InstanceIDToObject(id), Is.SameAs(go));
            UnityEngine.Object.DestroyImmediate(go);
            Assert.That(EditorUtility.InstanceIDToObject(id), Is.Null);
            copy.Dispose();
            Assert.That(copy.isCreated, Is.False);
            Assert.That(copy.length, Is.EqualTo(0));
        }

        [Test]
        public void InitializeOnLoadStaticConstructorsRanOnceBeforeTheFirstTest()
        {
            Assert.That(InitializeOnLoadProbe.RanDuring, Is.Not.EqualTo(TestContext.CurrentContext.Test.Name), "not first touched by this test");
            Assert.That(InitializeOnLoadProbe.Runs, Is.EqualTo(1));
            EditorLoad.Run();
            Assert.That(InitializeOnLoadProbe.Runs, Is.EqualTo(1));
        }
    }

    /// <summary>Counts its static constructor's runs (for the editor-load fact).</summary>
    [InitializeOnLoad]
    internal static class InitializeOnLoadProbe
    {
        internal static int Runs;

        /// <summary>The NUnit test (or suite) that was running when the static constructor ran.</summary>
        internal static string RanDuring;

        static InitializeOnLoadProbe()
        {
            Runs++;
            RanDuring = TestContext.CurrentContext.Test.Name;
        }
    }
}
