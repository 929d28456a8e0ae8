using NUnit.Framework;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>Edit mode (in Unity and headless on the Unity stand-in): a rope lowered onto a SphereCollider stays outside it (to its particle radius), listed or found by layer mask.</summary>
    [TestFixture]
    public sealed class RopeCollisionTests
    {
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        [Test]
        public void ParticlesStayOutsideTheListedSphere()
        {
            var sphereObject = _scene.Track(new GameObject("Sphere"));
            sphereObject.transform.position = new Vector3(0f, 1f, 0f);
            var sphere = sphereObject.AddComponent<SphereCollider>();
            sphere.radius = 0.3f;

            var rope = LowerableRope(RopeCollisionMode.ListedColliders, new Collider[] { sphere }, out var left, out var right);
            Lower(rope, left, right);

            float closest = float.PositiveInfinity;
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                float d = (rope.GetParticlePosition(i) - sphereObject.transform.position).magnitude - rope.GetParticleRadius(i);
                if (d < closest) closest = d;
            }
            Assert.That(closest, Is.GreaterThan(0.3f - 0.01f));
            Assert.That(rope.GetParticlePosition(rope.ParticleCount / 2).y, Is.GreaterThan(1.2f), "the rope drapes over the sphere");
        }

        [Test]
        public void LayerMaskFindsASphereThatAppearsAfterTheRopeWasBuilt()
        {
            var rope = LowerableRope(RopeCollisionMode.LayerMask, new Collider[0], out var left, out var right);
            for (int step = 0; step < 20; step++) rope.Simulate(0.01f);

            // the sphere arrives after the build: the per-step layer query must pick it up
            var sphereObject = _scene.Track(new GameObject("Sphere"));
            sphereObject.transform.position = new Vector3(0f, 1f, 0f);
            sphereObject.AddComponent<SphereCollider>().radius = 0.3f;
            Lower(rope, left, right);
            Assert.That(rope.GetParticlePosition(rope.ParticleCount / 2).y, Is.GreaterThan(1.2f), "the rope drapes over the new sphere");
        }

        /// <summary>A 2.4 m cord (E·A 2 kN, 40 segments) between two anchors 2 m apart at y = 1.6 m.</summary>
        ElasticRope LowerableRope(RopeCollisionMode mode, Collider[] colliders, out Transform left, out Transform right)
        {
            left = _scene.Point("Left", new Vector3(-1f, 1.6f, 0f));
            right = _scene.Point("Right", new Vector3(1f, 1.6f, 0f));
            var rope = _scene.Rope("Rope", left.position);
            rope.RestLength = 2.4f;
            rope.SegmentCount = 40;
            rope.Radius = 0.01f;
            rope.AxialStiffness = 2000f;
            rope.Fracture = false;
            rope.CollisionMode = mode;
            rope.Colliders = colliders;
            rope.StartAttachment.Point = left;
            rope.EndAttachment.Point = right;
            rope.Rebuild();
            return rope;
        }

        /// <summary>Lowers both anchors by 1.2 m over 1 s, then holds them for 1 s (0.01 s steps).</summary>
        static void Lower(ElasticRope rope, Transform left, Transform right)
        {
            for (int step = 0; step < 200; step++)
            {
                float y = 1.6f - 1.2f * Mathf_Min(1f, step / 100f);
                left.position = new Vector3(-1f, y, 0f);
                right.position = new Vector3(1f, y, 0f);
                rope.Simulate(0.01f);
            }
        }

        [Test]
        public void LayerMaskFindsASphereAlreadyInReachWhenTheRopeIsBuilt()
        {
            var sphereObject = _scene.Track(new GameObject("Sphere"));
            sphereObject.transform.position = new Vector3(0f, 1f, 0f);
            sphereObject.AddComponent<SphereCollider>().radius = 0.3f;
            var rope = LowerableRope(RopeCollisionMode.LayerMask, new Collider[0], out var left, out var right);
            Lower(rope, left, right);
            Assert.That(rope.GetParticlePosition(rope.ParticleCount / 2).y, Is.GreaterThan(1.2f), "the rope drapes over the sphere");
        }

        [Test]
        public void LayerMaskIgnoresTheAnchorsOwnCollider()
        {
            // a 20 cm anchor block with a BoxCollider; the rope hangs from its centre in Layer Mask mode (all layers)
            var anchor = _scene.Point("Anchor block", new Vector3(0f, 2f, 0f));
            anchor.gameObject.AddComponent<BoxCollider>().size = new Vector3(0.2f, 0.2f, 0.2f);
            var beam = _scene.Track(new GameObject("Beam"));
            beam.transform.position = new Vector3(0.3f, 1.2f, 0f);
            beam.AddComponent<SphereCollider>().radius = 0.1f;

            var rope = _scene.Rope("Rope", anchor.position);
            rope.RestLength = 1.5f;
            rope.SegmentCount = 30;
            rope.Fracture = false;
            rope.Damping = 0.02f;
            rope.CollisionMode = RopeCollisionMode.LayerMask;
            rope.StartAttachment.Point = anchor;
            rope.Rebuild();
            for (int step = 0; step < 300; step++) rope.Simulate(0.01f);

            Assert.That(rope.Simulation.Rope.ColliderCount, Is.EqualTo(1), "the beam in reach is registered, the anchor's own block is not");
            // hanging straight down from the pin: no particle pushed out of the block (which would need |x| or |z| >= 0.1 m)
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                var p = rope.GetParticlePosition(i);
                Assert.That(System.Math.Abs(p.x) + System.Math.Abs(p.z), Is.LessThan(1e-3f), "particle " + i + " at " + p);
            }
            float weight = rope.LinearDensity * rope.RestLength * 9.81f;
            Assert.That(rope.TopTension, Is.EqualTo(weight).Within(0.02f * weight));
        }

        static float Mathf_Min(float a, float b) => a < b ? a : b;
    }
}
