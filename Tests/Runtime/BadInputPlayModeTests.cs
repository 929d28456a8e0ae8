using System.Collections;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.Tests
{
    /// <summary>
    /// Play mode (in Unity and headless through the Unity stand-in's player loop): the anchor of a rope destroyed with
    /// Object.Destroy during Play. FixedUpdate keeps stepping without an exception (the test fails on any), one warning
    /// names the rope and Start.Point, the rope falls free, and LateUpdate keeps drawing a finite mesh.
    /// </summary>
    public sealed class BadInputPlayModeTests
    {
        GameObject _anchor, _rope;
        int _destroyedWarnings;

        void Collect(string condition, string stackTrace, LogType type)
        {
            if (type == LogType.Warning && condition.Contains("ElasticRope 'Rope': Start.Point ('Anchor') was destroyed")) _destroyedWarnings++;
        }

        [SetUp] public void SetUp() => Application.logMessageReceived += Collect;

        [TearDown]
        public void TearDown()
        {
            Application.logMessageReceived -= Collect;
            if (_rope != null) Object.Destroy(_rope);
            if (_anchor != null) Object.Destroy(_anchor);
        }

        [UnityTest]
        public IEnumerator AnchorDestroyedDuringPlayFreesTheRopeWithOneWarning()
        {
            _anchor = new GameObject("Anchor");
            _anchor.transform.position = new Vector3(0f, 5f, 0f);
            _rope = new GameObject("Rope", typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer));
            _rope.transform.position = _anchor.transform.position;
            var rope = _rope.GetComponent<ElasticRope>();
            rope.StartAttachment.Point = _anchor.transform;
            rope.Rebuild();
            for (int i = 0; i < 10; i++) yield return new WaitForFixedUpdate();
            Assert.That(rope.GetParticlePosition(0).y, Is.EqualTo(5f).Within(1e-5f));

            Object.Destroy(_anchor);
            for (int i = 0; i < 25; i++) yield return new WaitForFixedUpdate();
            yield return null;

            Assert.That(_destroyedWarnings, Is.EqualTo(1));
            // released at rest, the top falls at least g·t²/2 over the last 0.5 s (it is also pulled down by the rope's tension)
            Assert.That(5f - rope.GetParticlePosition(0).y, Is.GreaterThan(0.5f * 9.81f * 0.25f * 0.9f));
            var vertices = _rope.GetComponent<RopeMeshRenderer>().Mesh.vertices;
            Assert.That(vertices.Length, Is.GreaterThan(0));
            foreach (var v in vertices)
                Assert.That(float.IsFinite(v.x) && float.IsFinite(v.y) && float.IsFinite(v.z), Is.True);
        }
    }
}
