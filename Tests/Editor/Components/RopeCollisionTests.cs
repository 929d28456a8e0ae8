using NUnit.Framework;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): a rope lowered onto a SphereCollider stays outside it (to
    /// its particle radius), listed or found by layer mask; the colliders of the ends' hierarchies and of the rope's own
    /// object are never registered, unrelated ones (a floor on the anchor's scene root) are.
    /// </summary>
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

        [TestCase(false, TestName = "LayerMaskIgnoresTheWorkersCapsuleAboveATransformDRing")]
        [TestCase(true, TestName = "LayerMaskIgnoresTheWorkersCapsuleAboveARigidbodyDRing")]
        public void LayerMaskIgnoresTheCollidersOfTheBodyTheEndHangsFrom(bool bodyAttached)
        {
            // an 80 kg worker (kinematic: it stays put) with a 1.8 m x 0.3 m capsule; the rope hangs from a D-ring child
            // 0.1 m inside the capsule's chest, down through the capsule, in Layer Mask mode (all layers)
            var worker = _scene.Body("Worker", new Vector3(0f, 1.6f, 0f), 80f);
            worker.isKinematic = true;
            var capsule = worker.gameObject.AddComponent<CapsuleCollider>();
            capsule.radius = 0.3f;
            capsule.height = 1.8f;
            var dRing = new GameObject("D-ring").transform;
            dRing.SetParent(worker.transform, false);
            dRing.localPosition = new Vector3(0f, 0.4f, 0.1f);
            Beam();

            var rope = HangingRope(dRing.position);
            rope.StartAttachment.Point = dRing;
            if (bodyAttached) rope.StartAttachment.Body = worker;
            rope.Rebuild();
            for (int step = 0; step < 300; step++) rope.Simulate(0.01f);

            Assert.That(rope.Simulation.Rope.ColliderCount, Is.EqualTo(1), "the beam in reach is registered, the worker's capsule is not");
            // a Rigidbody end carries the rope's weight as a load on the body (no pin tension to compare)
            AssertHangsStraightFrom(rope, dRing.position, checkTension: !bodyAttached);
        }

        [TestCase(RopeCollisionMode.LayerMask)]
        [TestCase(RopeCollisionMode.ListedColliders)]
        public void CollidersUnderTheAnchorAndOnTheRopesOwnObjectAreIgnored(RopeCollisionMode mode)
        {
            // a shackle (sphere, child of the anchor) 10 cm under the anchor, a housing box on the rope's own GameObject
            // and a guard sphere on a child of it, all around the hanging rope's first 40 cm
            var anchor = _scene.Point("Anchor", new Vector3(0f, 2f, 0f));
            var shackle = new GameObject("Shackle").transform;
            shackle.SetParent(anchor, false);
            shackle.localPosition = new Vector3(0f, -0.1f, 0f);
            var shackleCollider = shackle.gameObject.AddComponent<SphereCollider>();
            shackleCollider.radius = 0.1f;
            var beam = Beam();

            var rope = HangingRope(anchor.position);
            var housing = rope.gameObject.AddComponent<BoxCollider>();
            housing.size = new Vector3(0.2f, 0.2f, 0.2f);
            var guard = new GameObject("Guard").transform;
            guard.SetParent(rope.transform, false);
            guard.localPosition = new Vector3(0f, -0.3f, 0f);
            var guardCollider = guard.gameObject.AddComponent<SphereCollider>();
            guardCollider.radius = 0.1f;
            rope.CollisionMode = mode;
            rope.Colliders = new Collider[] { shackleCollider, housing, guardCollider, beam };
            rope.StartAttachment.Point = anchor;
            rope.Rebuild();
            for (int step = 0; step < 300; step++) rope.Simulate(0.01f);

            Assert.That(rope.Simulation.Rope.ColliderCount, Is.EqualTo(1), "only the beam is registered");
            AssertHangsStraightFrom(rope, anchor.position);
        }

        [Test]
        public void LayerMaskKeepsTheFloorOnAnUnrelatedRootOfTheAnchor()
        {
            // "Environment" (no Rigidbody) carries a 4 m x 1 m x 4 m floor slab, top at y = 0, and the anchor block 1.2 m
            // above it; the 1.5 m rope, built hanging straight down to y = -0.3 m (inside the slab), must end up on top
            var environment = _scene.Track(new GameObject("Environment"));
            var floor = environment.AddComponent<BoxCollider>();
            floor.center = new Vector3(0f, -0.5f, 0f);
            floor.size = new Vector3(4f, 1f, 4f);
            var anchor = new GameObject("Anchor block").transform;
            anchor.SetParent(environment.transform, false);
            anchor.localPosition = new Vector3(0f, 1.2f, 0f);
            anchor.gameObject.AddComponent<BoxCollider>().size = new Vector3(0.2f, 0.2f, 0.2f);
            Beam();

            var rope = HangingRope(anchor.position);
            rope.StartAttachment.Point = anchor;
            rope.Rebuild();
            for (int step = 0; step < 300; step++) rope.Simulate(0.01f);

            Assert.That(rope.Simulation.Rope.ColliderCount, Is.EqualTo(2), "the floor on the anchor's root and the beam are registered, the anchor block is not");
            float lowest = float.PositiveInfinity;
            for (int i = 0; i < rope.ParticleCount; i++)
                lowest = System.Math.Min(lowest, rope.GetParticlePosition(i).y - rope.GetParticleRadius(i));
            Assert.That(lowest, Is.GreaterThan(-2e-3f), "the rope lies on the floor");
            Assert.That(rope.GetParticlePosition(rope.ParticleCount - 1).y, Is.LessThan(0.05f), "the free end reached the floor");
        }

        /// <summary>A 10 cm sphere at (0.3, 1.2, 0) m: in the rope's reach, clear of the rope hanging along x = 0.</summary>
        SphereCollider Beam()
        {
            var beam = _scene.Track(new GameObject("Beam"));
            beam.transform.position = new Vector3(0.3f, 1.2f, 0f);
            var sphere = beam.AddComponent<SphereCollider>();
            sphere.radius = 0.1f;
            return sphere;
        }

        /// <summary>A 1.5 m rope (30 segments, no fracture) at <paramref name="position"/> in Layer Mask mode; the caller attaches it and rebuilds.</summary>
        ElasticRope HangingRope(Vector3 position)
        {
            var rope = _scene.Rope("Rope", position);
            rope.RestLength = 1.5f;
            rope.SegmentCount = 30;
            rope.Fracture = false;
            rope.Damping = 0.02f;
            rope.CollisionMode = RopeCollisionMode.LayerMask;
            return rope;
        }

        /// <summary>Every particle on the vertical through <paramref name="top"/> (none pushed out sideways), top tension = weight (2 %).</summary>
        static void AssertHangsStraightFrom(ElasticRope rope, Vector3 top, bool checkTension = true)
        {
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                var p = rope.GetParticlePosition(i);
                Assert.That(System.Math.Abs(p.x - top.x) + System.Math.Abs(p.z - top.z), Is.LessThan(1e-3f), "particle " + i + " at " + p);
                Assert.That(p.y, Is.LessThanOrEqualTo(top.y + 1e-3f), "particle " + i + " at " + p);
            }
            if (!checkTension) return;
            float weight = rope.LinearDensity * rope.RestLength * 9.81f;
            Assert.That(rope.TopTension, Is.EqualTo(weight).Within(0.02f * weight));
        }

        static float Mathf_Min(float a, float b) => a < b ? a : b;
    }
}
