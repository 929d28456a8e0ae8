using System;
using NUnit.Framework;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// The stand-in's ObjectFactory.PlaceGameObject, Scene view, prefab stage and Undo groups behave as UCR 2022.3's
    /// GOCreationCommands.Place, SceneView, PrefabStage/MainStage.PlaceGameObjectInStage and Undo describe (STAND-IN.md,
    /// "Menu placement, prefab stage and Undo").
    /// </summary>
    [TestFixture]
    public sealed class PlacementFactsTests
    {
        const string PrefabPath = "Packages/com.hookerope.elastic-rope/Runtime/Prefabs/ElasticRope.prefab";

        [SetUp] public void SetUp() => World.Reset();
        [TearDown] public void TearDown() => World.Reset();

        [Test]
        public void ASceneViewIsOpenWithTheDefaultPivotAfterAReset()
        {
            SceneView.lastActiveSceneView.pivot = new Vector3(1f, 2f, 3f);
            World.Reset();
            Assert.That(SceneView.lastActiveSceneView, Is.Not.Null);
            Assert.That(SceneView.lastActiveSceneView.pivot, Is.EqualTo(Vector3.zero));
        }

        [Test]
        public void PlaceWithoutParentMovesToThePivotAndSelects()
        {
            SceneView.lastActiveSceneView.pivot = new Vector3(2f, -1f, 7f);
            var go = new GameObject("Probe");
            ObjectFactory.PlaceGameObject(go);
            Assert.That(go.transform.position, Is.EqualTo(new Vector3(2f, -1f, 7f)));
            Assert.That(Selection.activeGameObject, Is.SameAs(go));
        }

        [Test]
        public void PlaceWithParentResetsTheLocalPoseAndTakesOnlyTheObjectsLayer()
        {
            var parent = new GameObject("Parent") { layer = 4 };
            parent.transform.position = new Vector3(5f, 0f, 0f);
            var go = new GameObject("Probe");
            var child = new GameObject("Child");
            child.transform.SetParent(go.transform, false);
            go.transform.position = new Vector3(9f, 9f, 9f);
            go.transform.localScale = new Vector3(2f, 2f, 2f);
            ObjectFactory.PlaceGameObject(go, parent);
            Assert.That(go.transform.parent, Is.SameAs(parent.transform));
            Assert.That(go.transform.localPosition, Is.EqualTo(Vector3.zero));
            Assert.That(go.transform.localScale, Is.EqualTo(Vector3.one));
            Assert.That(go.layer, Is.EqualTo(4));
            Assert.That(child.layer, Is.EqualTo(0), "GOCreationCommands.SetGameObjectParent sets the object's layer only");
        }

        [Test]
        public void NamesBecomeUniqueAmongSiblingsOnly()
        {
            var parent = new GameObject("Parent");
            new GameObject("Probe");
            var a = new GameObject("Probe");
            ObjectFactory.PlaceGameObject(a);
            Assert.That(a.name, Is.EqualTo("Probe (1)"));
            var b = new GameObject("Probe");
            ObjectFactory.PlaceGameObject(b, parent);
            Assert.That(b.name, Is.EqualTo("Probe"), "no sibling of that name under Parent");
        }

        [Test]
        public void PrefabStageOpensClosesAndTakesPlacedObjects()
        {
            var stage = PrefabStageUtility.OpenPrefab(PrefabPath);
            var root = stage.prefabContentsRoot;
            Assert.That(stage.assetPath, Is.EqualTo(PrefabPath));
            Assert.That(root.GetComponent<HookeRope.ElasticRope>(), Is.Not.Null);
            SceneView.lastActiveSceneView.pivot = new Vector3(0f, 3f, 0f);
            var go = new GameObject("Placed");
            ObjectFactory.PlaceGameObject(go);
            Assert.That(go.transform.parent, Is.SameAs(root.transform));
            Assert.That(go.transform.position, Is.EqualTo(new Vector3(0f, 3f, 0f)));

            var second = PrefabStageUtility.OpenPrefab(PrefabPath);
            Assert.That(root == null, Is.True, "opening another prefab closes the first stage");
            StageUtility.GoToMainStage();
            Assert.That(PrefabStageUtility.GetCurrentPrefabStage(), Is.Null);
            Assert.Throws<InvalidOperationException>(() => _ = second.prefabContentsRoot);
        }

        [Test]
        public void MainStageRefusesAChild()
        {
            var parent = new GameObject("Parent");
            var child = new GameObject("Child");
            child.transform.SetParent(parent.transform, false);
            Assert.Throws<ArgumentException>(() => StageUtility.PlaceGameObjectInCurrentStage(child));
        }

        [Test]
        public void PerformUndoRevertsTheLatestGroupOfCreatedObjects()
        {
            var first = new GameObject("First");
            Undo.RegisterCreatedObjectUndo(first, "Create First");
            Undo.IncrementCurrentGroup();
            int group = Undo.GetCurrentGroup();
            var second = new GameObject("Second");
            Undo.RegisterCreatedObjectUndo(second, "Create Second");
            Undo.PerformUndo();
            Assert.That(second == null, Is.True);
            Assert.That(first == null, Is.False, "an earlier group stays");
            Assert.That(Undo.GetCurrentGroup(), Is.EqualTo(group));
            Undo.PerformUndo();
            Assert.That(first == null, Is.True);

            Undo.IncrementCurrentGroup();
            var third = new GameObject("Third");
            Undo.RecordObject(third, "Edit");
            Assert.Throws<NotSupportedException>(Undo.PerformUndo);
            Object.DestroyImmediate(third);
        }
    }
}
