using NUnit.Framework;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): a 100 kg Rigidbody hangs on an ElasticRope pinned to an anchor Transform, coupled
    /// two-way through Unity physics. The body must settle where statics put it and the read-outs must match
    /// the textbook tensions.
    /// </summary>
    [TestFixture]
    public sealed class ElasticRopeStaticHangTests
    {
        const float G = 9.81f;
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        [Test]
        public void RigidbodyLoadIsHeldAtStaticStretch()
        {
            const float mass = 100f, length = 2f, axialStiffness = 30000f;
            var anchor = _scene.Point("Anchor", new Vector3(0f, 10f, 0f));
            var body = _scene.Body("Load", new Vector3(0f, 10f - length, 0f), mass);
            var rope = _scene.Rope("Rope", anchor.position);
            rope.RestLength = length;
            rope.AxialStiffness = axialStiffness;
            rope.SegmentCount = 16;
            rope.Substeps = 8;
            rope.Damping = 0.02f;
            rope.Fracture = false;
            rope.StartAttachment.Point = anchor;
            rope.EndAttachment.Body = body;
            rope.Rebuild();

            UnityRopeScene.Run(rope, 1200, 0.01f);

            float ropeMass = rope.LinearDensity * length;
            float expectedDrop = length + (mass + 0.5f * ropeMass) * G * length / axialStiffness;
            Assert.That(anchor.position.y - body.position.y, Is.EqualTo(expectedDrop).Within(0.003f));
            Assert.That(rope.TopTension, Is.EqualTo((mass + ropeMass) * G).Within(0.02f * mass * G));
            Assert.That(rope.ArrestForce, Is.EqualTo(mass * G).Within(0.02f * mass * G));
            Assert.That(rope.Elongation, Is.EqualTo(expectedDrop - length).Within(0.003f));
        }
    }
}
