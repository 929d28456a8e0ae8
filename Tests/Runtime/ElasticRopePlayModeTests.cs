using System.Collections;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.Tests
{
    /// <summary>
    /// Play mode (in Unity and headless through the Unity stand-in's player loop): the component's own lifecycle — Awake builds the rope, FixedUpdate steps it,
    /// LateUpdate renders it. A rope hanging from an anchor under its own weight reaches the static top tension
    /// μ·L·g and its mesh is finite.
    /// </summary>
    public sealed class ElasticRopePlayModeTests
    {
        GameObject _anchor, _rope;

        [TearDown]
        public void TearDown()
        {
            if (_rope != null) Object.Destroy(_rope);
            if (_anchor != null) Object.Destroy(_anchor);
        }

        [UnityTest]
        public IEnumerator HangingRopeSettlesAndRendersThroughTheUnityLoop()
        {
            _anchor = new GameObject("Anchor");
            _anchor.transform.position = new Vector3(0f, 5f, 0f);
            _rope = new GameObject("Rope", typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer));
            _rope.transform.position = _anchor.transform.position;
            var rope = _rope.GetComponent<ElasticRope>();
            Assert.That(rope.IsBuilt, Is.True, "Awake builds the rope in Play");
            rope.StartAttachment.Point = _anchor.transform;
            rope.Damping = 0.005f;
            rope.Rebuild();

            for (int i = 0; i < 100; i++) yield return new WaitForFixedUpdate();
            yield return null;

            float weight = rope.LinearDensity * rope.RestLength * 9.81f;
            Assert.That(rope.TopTension, Is.EqualTo(weight).Within(0.05f * weight));
            Assert.That(rope.GetParticlePosition(rope.ParticleCount - 1).y, Is.EqualTo(5f - rope.RestLength).Within(0.01f));
            var mesh = _rope.GetComponent<MeshFilter>().sharedMesh;
            Assert.That(mesh, Is.Not.Null);
            var vertices = mesh.vertices;
            Assert.That(vertices.Length, Is.GreaterThan(0));
            for (int v = 0; v < vertices.Length; v++)
                Assert.That(float.IsNaN(vertices[v].x + vertices[v].y + vertices[v].z), Is.False, "vertex " + v);
        }
    }
}
