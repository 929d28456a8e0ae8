using NUnit.Framework;
using UnityEngine;
using HookeRope.Editor;

namespace HookeRope.Tests.Components
{
    /// <summary>Edit mode (in Unity and headless on the Unity stand-in): GameObject &gt; 3D Object &gt; Elastic Rope builds a rope between two child anchors whose default length sags.</summary>
    [TestFixture]
    public sealed class ElasticRopeMenuTests
    {
        GameObject _created;

        [TearDown]
        public void TearDown()
        {
            if (_created != null) Object.DestroyImmediate(_created);
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
        }
    }
}
