using System.Collections;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.Tests
{
    /// <summary>
    /// Play mode (in Unity and headless through the Unity stand-in's player loop): the drawn rope ends sit on their
    /// attachments' live poses in every rendered frame, although the rope steps at the 50 Hz fixed rate — a hand
    /// moved every rendered frame at 2 m/s, and a harness D-ring on a body falling at 8.9 m/s, interpolated or not.
    /// One fixed step of lag would be 4 cm and 18 cm; the drawn end must stay within 1 mm.
    /// </summary>
    public sealed class DrawnEndsTests
    {
        const float Tolerance = 1e-3f;
        GameObject _root;

        [TearDown]
        public void TearDown()
        {
            if (_root != null) Object.Destroy(_root);
        }

        ElasticRope DrawnRope(Transform start)
        {
            var go = new GameObject("Rope", typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer));
            go.transform.SetParent(_root.transform, false);
            go.transform.position = start.position;
            var rope = go.GetComponent<ElasticRope>();
            rope.RestLength = 4f;
            rope.SegmentCount = 24;
            rope.StartAttachment.Point = start;
            return rope;
        }

        /// <summary>Distance (m) from <paramref name="point"/> to the nearest vertex of the rope's last uploaded mesh (the end caps hold a vertex at each end).</summary>
        static float NearestDrawnVertex(ElasticRope rope, Vector3 point)
        {
            var mesh = rope.GetComponent<MeshFilter>().sharedMesh;
            var vertices = mesh.vertices;
            float nearest = float.PositiveInfinity;
            for (int v = 0; v < vertices.Length; v++)
            {
                float d = (rope.transform.TransformPoint(vertices[v]) - point).magnitude;
                if (d < nearest) nearest = d;
            }
            return nearest;
        }

        [UnityTest]
        public IEnumerator HandMovedEveryRenderedFrameIsDrawnAtTheRopeStart()
        {
            _root = new GameObject("Drawn ends");
            var hand = new GameObject("Hand").transform;
            hand.SetParent(_root.transform, false);
            hand.position = new Vector3(0f, 2f, 0f);
            var rope = DrawnRope(hand);
            rope.Rebuild();
            yield return null;
            float worst = 0f;
            for (int frame = 0; frame < 45; frame++)
            {
                // the previous frame's LateUpdate drew the rope with the hand where it is now
                if (frame > 0) worst = System.Math.Max(worst, NearestDrawnVertex(rope, hand.position));
                hand.position += new Vector3(2f * Time.deltaTime, 0f, 0f);
                yield return null;
            }
            Assert.That(hand.position.x, Is.GreaterThan(0.9f), "the hand moved about 1 m");
            Assert.That(worst, Is.LessThan(Tolerance));
        }

        [UnityTest]
        public IEnumerator FallingInterpolatedBodyIsDrawnAtItsDRing() => FallingBody(RigidbodyInterpolation.Interpolate);

        [UnityTest]
        public IEnumerator FallingBodyWithoutInterpolationIsDrawnAtItsDRing() => FallingBody(RigidbodyInterpolation.None);

        IEnumerator FallingBody(RigidbodyInterpolation interpolation)
        {
            _root = new GameObject("Drawn ends");
            var anchor = new GameObject("Anchor").transform;
            anchor.SetParent(_root.transform, false);
            anchor.position = new Vector3(0f, 10f, 0f);
            var worker = new GameObject("Worker");
            worker.transform.SetParent(_root.transform, false);
            worker.transform.position = new Vector3(0.3f, 9f, 0f);
            var body = worker.AddComponent<Rigidbody>();
            body.mass = 100f;
            body.interpolation = interpolation;
            body.velocity = new Vector3(0f, -8.9f, 0f);
            var dRing = new GameObject("D-ring").transform;
            dRing.SetParent(worker.transform, false);
            dRing.localPosition = new Vector3(0f, 0.7f, 0f);
            var rope = DrawnRope(anchor);
            rope.EndAttachment.Body = body;
            rope.EndAttachment.Point = dRing;
            rope.Rebuild();

            float worst = 0f;
            for (int frame = 0; frame < 20; frame++)
            {
                yield return null;
                // after Update the body's Transform holds this frame's pose: draw as LateUpdate will, then compare
                rope.GetComponent<RopeMeshRenderer>().Render((Time.time - Time.fixedTime) / Time.fixedDeltaTime);
                worst = System.Math.Max(worst, NearestDrawnVertex(rope, dRing.position));
            }
            Assert.That(body.velocity.y, Is.LessThan(-8.9f), "still falling: the 4 m lanyard is slack");
            Assert.That(worst, Is.LessThan(Tolerance));
        }
    }
}
