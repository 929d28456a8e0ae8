using HookeRope.Editor;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode: moving and re-attaching a rope's ends in the editor. The Scene-view handles move each attached end
    /// through its Point, else its Body's Transform (a free end has none); a drag by d moves exactly that Transform
    /// by d and nothing else. "Attach Start/End to selection" sets Body and Point from Selection.activeTransform:
    /// a D-ring under a Rigidbody → Body = the body, Point = the D-ring; the body itself → Point empty; a plain
    /// Transform or one under a Rigidbody of the rope's own hierarchy → Point only. The buttons are disabled, with
    /// the reason, when nothing or the rope itself is selected.
    /// </summary>
    [TestFixture]
    public sealed class RopeEndEditingTests
    {
        static readonly Vector3 Drag = new Vector3(0.5f, -0.25f, 0.125f);
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); Selection.activeObject = null; }
        [TearDown] public void TearDown() { Selection.activeObject = null; _scene.End(); }

        Rigidbody Worker(out Transform dRing) => _scene.Rig(new Vector3(0f, 2f, 0f), 100f, new Vector3(0f, 0.4f, 0.1f), out dRing);

        static void AssertAt(Transform t, Vector3 expected) =>
            Assert.That((t.position - expected).magnitude, Is.LessThan(1e-6f), t.name + " at " + t.position + ", expected " + expected);

        // ---- Scene-view handles ----------------------------------------------------------------------------------

        [Test]
        public void EachAttachedEndHasAHandleOnItsPointElseItsBody()
        {
            var worker = Worker(out var dRing);
            var beam = _scene.Point("Beam", new Vector3(0f, 4f, 0f));
            var rope = _scene.Rope("Lanyard", beam.position);
            Assert.That(RopeEndHandles.HandleTransform(rope.StartAttachment), Is.Null, "a free end has no handle");
            rope.StartAttachment.Point = beam;
            rope.EndAttachment.Body = worker;
            Assert.That(RopeEndHandles.HandleTransform(rope.StartAttachment), Is.SameAs(beam));
            Assert.That(RopeEndHandles.HandleTransform(rope.EndAttachment), Is.SameAs(worker.transform), "no Point: the body's Transform");
            rope.EndAttachment.Point = dRing;
            Assert.That(RopeEndHandles.HandleTransform(rope.EndAttachment), Is.SameAs(dRing), "the Point on the body");
        }

        [Test]
        public void DraggingBothHandlesMovesBothEndsByTheDrag()
        {
            var worker = Worker(out var dRing);
            var beam = _scene.Point("Beam", new Vector3(0f, 4f, 0f));
            var rope = _scene.Rope("Lanyard", beam.position);
            rope.StartAttachment.Point = beam;
            rope.EndAttachment.Body = worker;
            rope.EndAttachment.Point = dRing;

            Assert.That(RopeEndHandles.Draw(rope, p => p + Drag), Is.EqualTo(2));
            AssertAt(beam, new Vector3(0f, 4f, 0f) + Drag);
            AssertAt(dRing, new Vector3(0f, 2.4f, 0.1f) + Drag);
            AssertAt(worker.transform, new Vector3(0f, 2f, 0f));
            Assert.That((rope.StartAttachment.WorldPosition(Vector3.zero) - (new Vector3(0f, 4f, 0f) + Drag)).magnitude, Is.LessThan(1e-6f));

            Assert.That(RopeEndHandles.Draw(rope, p => p), Is.EqualTo(0), "a handle that is not dragged moves nothing");
            AssertAt(beam, new Vector3(0f, 4f, 0f) + Drag);
        }

        [Test]
        public void ABodyEndWithoutPointMovesTheBodyAndAFreeEndHasNoHandle()
        {
            var worker = Worker(out _);
            var rope = _scene.Rope("Lanyard", new Vector3(0f, 4f, 0f));
            rope.EndAttachment.Body = worker;
            int handles = 0;
            Assert.That(RopeEndHandles.Draw(rope, p => { handles++; return p + Drag; }), Is.EqualTo(1));
            Assert.That(handles, Is.EqualTo(1), "one handle: the Start is free");
            AssertAt(worker.transform, new Vector3(0f, 2f, 0f) + Drag);
            Assert.That(RopeEndHandles.MoveEnd(rope.StartAttachment, Vector3.one, RopeEndHandles.MoveStartName), Is.False);
            AssertAt(rope.transform, new Vector3(0f, 4f, 0f));
        }

        // ---- Attach end to selection -----------------------------------------------------------------------------

        [Test]
        public void ADRingUnderARigidbodyBecomesATwoWayEndAtThatPoint()
        {
            var worker = Worker(out var dRing);
            var rope = _scene.Rope("Lanyard", new Vector3(0f, 4f, 0f));
            Selection.activeTransform = dRing;
            Assert.That(RopeAttachToSelection.Unavailable(new[] { rope }, Selection.activeTransform), Is.Null);

            RopeAttachToSelection.Attach(rope, rope.EndAttachment, Selection.activeTransform, RopeAttachToSelection.AttachEndName);
            Assert.That(rope.EndAttachment.Body, Is.SameAs(worker));
            Assert.That(rope.EndAttachment.Point, Is.SameAs(dRing));
            Assert.That(rope.EndAttachment.Kind, Is.EqualTo(RopeEndKind.Rigidbody));
            Assert.That(rope.StartAttachment.Kind, Is.EqualTo(RopeEndKind.Free), "the other end is untouched");

            Selection.activeTransform = worker.transform;
            RopeAttachToSelection.Attach(rope, rope.EndAttachment, Selection.activeTransform, RopeAttachToSelection.AttachEndName);
            Assert.That(rope.EndAttachment.Body, Is.SameAs(worker));
            Assert.That(rope.EndAttachment.Point, Is.Null, "the body itself: its position");
        }

        [Test]
        public void APlainTransformBecomesAFollowedEndAndClearsTheBody()
        {
            var worker = Worker(out _);
            var beam = _scene.Point("Beam", new Vector3(0f, 4f, 0f));
            var rope = _scene.Rope("Lanyard", beam.position);
            rope.StartAttachment.Body = worker;
            Selection.activeTransform = beam;

            RopeAttachToSelection.Attach(rope, rope.StartAttachment, Selection.activeTransform, RopeAttachToSelection.AttachStartName);
            Assert.That(rope.StartAttachment.Point, Is.SameAs(beam));
            Assert.That(rope.StartAttachment.Body, Is.Null);
            Assert.That(rope.StartAttachment.Kind, Is.EqualTo(RopeEndKind.Transform));
            Assert.That((rope.StartAttachment.WorldPosition(Vector3.zero) - new Vector3(0f, 4f, 0f)).magnitude, Is.LessThan(1e-6f));
        }

        [Test]
        public void ARigidbodyInTheRopesOwnHierarchyIsNotPulled()
        {
            var rope = _scene.Rope("Lanyard", new Vector3(0f, 4f, 0f));
            var clip = new GameObject("Clip");
            clip.transform.SetParent(rope.transform, false);
            clip.AddComponent<Rigidbody>();
            RopeAttachToSelection.Attach(rope, rope.StartAttachment, clip.transform, RopeAttachToSelection.AttachStartName);
            Assert.That(rope.StartAttachment.Body, Is.Null);
            Assert.That(rope.StartAttachment.Point, Is.SameAs(clip.transform));
        }

        [Test]
        public void TheButtonsAreDisabledWithAReasonWhenNothingOrTheRopeIsSelected()
        {
            var rope = _scene.Rope("Lanyard", Vector3.zero);
            var other = _scene.Rope("Other", Vector3.one);
            var ropes = new[] { rope, other };
            StringAssert.StartsWith("Nothing is selected", RopeAttachToSelection.Unavailable(ropes, Selection.activeTransform));
            Selection.activeTransform = other.transform;
            StringAssert.StartsWith("The rope itself is selected", RopeAttachToSelection.Unavailable(ropes, Selection.activeTransform));
            StringAssert.Contains("padlock", RopeAttachToSelection.Unavailable(ropes, Selection.activeTransform));
            Assert.That(RopeAttachToSelection.Unavailable(new[] { rope }, Selection.activeTransform), Is.Null, "another rope is a target like any object");
        }
    }
}
