using NUnit.Framework;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using HookeRope.Editor;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): GameObject &gt; 3D Object &gt; Elastic Rope builds a rope
    /// between two child anchors whose default length sags, and places it as Unity's own 3D objects
    /// (ObjectFactory.PlaceGameObject): at the Scene view's pivot, under the open prefab stage's root, or as the child
    /// of the right-clicked object; the creation is one Undo step.
    /// </summary>
    [TestFixture]
    public sealed class ElasticRopeMenuTests
    {
        const string PrefabPath = "Packages/com.hookerope.elastic-rope/Runtime/Prefabs/ElasticRope.prefab";
        static readonly Vector3 Pivot = new Vector3(3.25f, 1.5f, -2f);

        GameObject _created, _context;
        Vector3 _savedPivot;
        bool _openedStage;

        [SetUp]
        public void SetUp()
        {
            if (SceneView.lastActiveSceneView != null) _savedPivot = SceneView.lastActiveSceneView.pivot;
        }

        [TearDown]
        public void TearDown()
        {
            if (_created != null) Object.DestroyImmediate(_created);
            if (_context != null) Object.DestroyImmediate(_context);
            if (_openedStage) StageUtility.GoToMainStage();
            if (SceneView.lastActiveSceneView != null) SceneView.lastActiveSceneView.pivot = _savedPivot;
        }

        static SceneView RequireSceneView()
        {
            var view = SceneView.lastActiveSceneView;
            Assume.That(view, Is.Not.Null, "needs an open Scene view (the Editor's default layout; none in batch mode)");
            return view;
        }

        [Test]
        public void CreatesRopeBetweenTwoChildAnchors()
        {
            var rope = ElasticRopeMenu.Create(null);
            _created = rope.gameObject;
            Assert.That(rope.GetComponent<RopeMeshRenderer>(), Is.Not.Null);
            Assert.That(rope.StartAttachment.Kind, Is.EqualTo(RopeEndKind.Transform));
            Assert.That(rope.EndAttachment.Kind, Is.EqualTo(RopeEndKind.Transform));
            Assert.That(rope.StartAttachment.Point.parent, Is.SameAs(rope.transform));
            Assert.That(rope.EndAttachment.Point.parent, Is.SameAs(rope.transform));
            float span = (rope.EndAttachment.Point.position - rope.StartAttachment.Point.position).magnitude;
            Assert.That(span, Is.EqualTo(1.6f).Within(1e-5f));
            Assert.That(span, Is.LessThan(rope.RestLength), "the rope is longer than the span, so it sags");
            Assert.That(Selection.activeGameObject, Is.SameAs(_created));
        }

        [Test]
        public void LandsAtTheSceneViewPivot()
        {
            RequireSceneView().pivot = Pivot;
            var rope = ElasticRopeMenu.Create(null);
            _created = rope.gameObject;
            Assert.That(rope.transform.parent, Is.Null);
            Assert.That((rope.transform.position - Pivot).magnitude, Is.LessThan(1e-5f));
            Vector3 midpoint = 0.5f * (rope.StartAttachment.Point.position + rope.EndAttachment.Point.position);
            Assert.That((midpoint - Pivot).magnitude, Is.LessThan(1e-5f), "the anchors move with the rope");
        }

        [Test]
        public void InsideAnOpenPrefabStageItIsParentedUnderThePrefabRoot()
        {
            RequireSceneView().pivot = Pivot;
            var stage = PrefabStageUtility.OpenPrefab(PrefabPath);
            _openedStage = true;
            Assert.That(PrefabStageUtility.GetCurrentPrefabStage(), Is.SameAs(stage));
            var root = stage.prefabContentsRoot.transform;
            int children = root.childCount;

            var rope = ElasticRopeMenu.Create(null);
            _created = rope.gameObject;
            Assert.That(rope.transform.parent, Is.SameAs(root));
            Assert.That(root.childCount, Is.EqualTo(children + 1));
            Assert.That((rope.transform.position - Pivot).magnitude, Is.LessThan(1e-4f), "placed at the pivot, then parented keeping its world pose");
        }

        [Test]
        public void WithAContextObjectItBecomesItsChildAtItsOrigin()
        {
            _context = new GameObject("Harness");
            _context.transform.position = new Vector3(-1f, 4f, 2f);
            _context.layer = 5;
            var rope = ElasticRopeMenu.Create(_context);
            _created = rope.gameObject;
            Assert.That(rope.transform.parent, Is.SameAs(_context.transform));
            Assert.That(rope.transform.localPosition, Is.EqualTo(Vector3.zero));
            Assert.That((rope.transform.position - _context.transform.position).magnitude, Is.LessThan(1e-6f));
            Assert.That(rope.gameObject.layer, Is.EqualTo(5), "takes the parent's layer");
        }

        [Test]
        public void CreationIsOneUndoStep()
        {
            Undo.IncrementCurrentGroup();
            var rope = ElasticRopeMenu.Create(null);
            var start = rope.StartAttachment.Point.gameObject;
            Assert.That(rope == null, Is.False);
            Undo.PerformUndo();
            Assert.That(rope == null, Is.True, "Undo removes the rope");
            Assert.That(start == null, Is.True, "and its anchors");
        }

        [Test]
        public void SecondRopeGetsAUniqueName()
        {
            var first = ElasticRopeMenu.Create(null);
            _created = first.gameObject;
            var second = ElasticRopeMenu.Create(null);
            try
            {
                Assert.That(first.name, Is.EqualTo("Elastic Rope"));
                Assert.That(second.name, Is.EqualTo("Elastic Rope (1)"));
            }
            finally
            {
                Object.DestroyImmediate(second.gameObject);
            }
        }
    }
}
