using System.Collections;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.Tests
{
    /// <summary>
    /// Play mode (in Unity and headless through the Unity stand-in's player loop): the package prefab's objects (a rope
    /// whose Start points at its own "Anchor" child, End empty) appear under a 100 kg worker Rigidbody with a
    /// "Harness D-Ring" child, as a prefab dropped onto the rig does. Awake wires it without a field touched: End pulls
    /// the worker at the D-ring, Start hangs from a root-level anchor the rest length above it, one console line says so,
    /// and the falling worker is arrested (the lanyard pulls, the worker stays within the stretched lanyard's reach).
    /// With a beam 1.5 m above the D-ring, the anchor is snapped to the beam's underside instead.
    /// </summary>
    public sealed class RopeDropOnRigTests
    {
        GameObject _worker, _anchor, _beam;

        [TearDown]
        public void TearDown()
        {
            if (_worker != null) Object.Destroy(_worker);
            if (_anchor != null) Object.Destroy(_anchor);
            if (_beam != null) Object.Destroy(_beam);
        }

        [UnityTest]
        public IEnumerator DroppedUnderARigBelowABeamTheAnchorSnapsToTheBeamsUnderside()
        {
            // a static 4 × 0.2 × 0.4 m beam, underside 1.5 m above the D-ring (within the 2 m rest length)
            _beam = new GameObject("Beam");
            _beam.transform.position = new Vector3(0f, 4f, 0f);
            _beam.AddComponent<BoxCollider>().size = new Vector3(4f, 0.2f, 0.4f);
            _worker = new GameObject("Worker");
            _worker.transform.position = new Vector3(0f, 2f, 0f);
            var body = _worker.AddComponent<Rigidbody>();
            body.mass = 100f;
            _worker.AddComponent<CapsuleCollider>(); // the rig's own collider: the ray starts inside it, and it is the rig's
            var dRing = new GameObject("Harness D-Ring").transform;
            dRing.SetParent(_worker.transform, false);
            dRing.localPosition = new Vector3(0f, 0.4f, 0.1f);

            var ropeObject = new GameObject("Beam Lanyard"); // its own anchor name, whatever the other test left behind
            ropeObject.SetActive(false);
            ropeObject.transform.SetParent(_worker.transform, false);
            var rope = ropeObject.AddComponent<ElasticRope>();
            rope.RestLength = 2f;
            ropeObject.SetActive(true);

            var anchor = rope.StartAttachment.Point;
            Assert.That(anchor, Is.Not.Null);
            _anchor = anchor.gameObject;
            Assert.That(anchor.name, Is.EqualTo("Beam Lanyard Anchor"));
            Assert.That(rope.EndAttachment.Body, Is.SameAs(body));
            Assert.That((anchor.position - new Vector3(0f, 3.9f, 0.1f)).magnitude, Is.LessThan(1e-5f), "on the beam's underside");
            Assert.That((rope.GetParticlePosition(0) - anchor.position).magnitude, Is.LessThan(1e-5f));
            yield return new WaitForFixedUpdate();
            Assert.That(rope.IsBroken, Is.False);

            // gone before the next test looks for a beam or a root-level anchor (Destroy acts at the end of the frame)
            Object.Destroy(_beam);
            Object.Destroy(_anchor);
            Object.Destroy(_worker);
            yield return null;
        }

        [UnityTest]
        public IEnumerator DroppedUnderARigidbodyTheRopeWiresItselfInAwakeAndArrestsTheWorker()
        {
            _worker = new GameObject("Worker");
            _worker.transform.position = new Vector3(0f, 2f, 0f);
            var body = _worker.AddComponent<Rigidbody>();
            body.mass = 100f;
            var dRing = new GameObject("Harness D-Ring").transform;
            dRing.SetParent(_worker.transform, false);
            dRing.localPosition = new Vector3(0f, 0.4f, 0.1f);

            // the prefab's objects, activated once in place as Instantiate(prefab, worker) does
            var ropeObject = new GameObject("Elastic Rope");
            ropeObject.SetActive(false);
            ropeObject.transform.SetParent(_worker.transform, false);
            var ownAnchor = new GameObject("Anchor").transform;
            ownAnchor.SetParent(ropeObject.transform, false);
            ropeObject.AddComponent<MeshFilter>();
            ropeObject.AddComponent<MeshRenderer>();
            var rope = ropeObject.AddComponent<ElasticRope>();
            ropeObject.AddComponent<RopeMeshRenderer>();
            rope.StartAttachment.Point = ownAnchor;
            ropeObject.SetActive(true);

            Assert.That(rope.IsBuilt, Is.True, "Awake builds the rope in Play");
            Assert.That(rope.EndAttachment.Body, Is.SameAs(body));
            Assert.That(rope.EndAttachment.Point, Is.SameAs(dRing));
            var anchor = rope.StartAttachment.Point;
            Assert.That(anchor, Is.Not.SameAs(ownAnchor));
            _anchor = anchor.gameObject;
            Assert.That(anchor.parent, Is.Null);
            Assert.That(anchor.name, Is.EqualTo("Elastic Rope Anchor"));
            Assert.That((anchor.position - (dRing.position + new Vector3(0f, rope.RestLength, 0f))).magnitude, Is.LessThan(1e-5f));

            for (int i = 0; i < 150; i++) yield return new WaitForFixedUpdate();

            float k = rope.AxialStiffness / rope.RestLength, weight = body.mass * 9.81f;
            Assert.That(rope.PeakArrestForce, Is.GreaterThan(weight), "the lanyard took the worker's weight and more");
            Assert.That(rope.IsBroken, Is.False);
            Assert.That((dRing.position - anchor.position).magnitude, Is.LessThan(rope.RestLength + 2.1f * weight / k), "held");
        }
    }
}
