using System;
using NUnit.Framework;
using UnityEngine;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// Physics.Raycast and Physics.RaycastAll against analytic hits (Scripting Reference 2022.3): the entry point,
    /// outward normal and distance on spheres, boxes and capsules under moved, rotated and scaled Transforms; the
    /// nearest hit for Raycast, every hit for RaycastAll; maxDistance, the layer mask (DefaultRaycastLayers skips
    /// "Ignore Raycast"), triggers per QueryTriggerInteraction and Physics.queriesHitTriggers; a ray starting inside
    /// a collider does not detect it ("Notes" of Physics.Raycast); a zero direction hits nothing.
    /// </summary>
    [TestFixture]
    public sealed class RaycastFactsTests
    {
        const float Tolerance = 1e-5f;

        [SetUp] public void SetUp() => World.Reset();
        [TearDown] public void TearDown() => World.Reset();

        static T Shape<T>(string name, Vector3 position, Quaternion rotation, Vector3 scale) where T : Collider
        {
            var go = new GameObject(name);
            go.transform.position = position;
            go.transform.rotation = rotation;
            go.transform.localScale = scale;
            return go.AddComponent<T>();
        }

        static void AssertVector(Vector3 actual, Vector3 expected, string what)
        {
            Assert.That(actual.x, Is.EqualTo(expected.x).Within(Tolerance), what + ".x of " + actual);
            Assert.That(actual.y, Is.EqualTo(expected.y).Within(Tolerance), what + ".y of " + actual);
            Assert.That(actual.z, Is.EqualTo(expected.z).Within(Tolerance), what + ".z of " + actual);
        }

        static void AssertHit(RaycastHit hit, Collider collider, Vector3 point, Vector3 normal, float distance)
        {
            Assert.That(hit.collider, Is.SameAs(collider));
            AssertVector(hit.point, point, "point");
            AssertVector(hit.normal, normal, "normal");
            Assert.That(hit.distance, Is.EqualTo(distance).Within(Tolerance));
            Assert.That(hit.transform, Is.SameAs(collider.transform));
            Assert.That(hit.colliderInstanceID, Is.EqualTo(collider.GetInstanceID()));
        }

        [Test]
        public void ScaledSphereIsEnteredWhereTheLineMeetsIt()
        {
            // radius 0.5 × largest |scale| 3 = 1.5 around (0, 5, 0.5) + scaled centre (0, 0, 0.2·1) → (0, 5, 0.7)
            var sphere = Shape<SphereCollider>("Sphere", new Vector3(0f, 5f, 0.5f), Quaternion.identity, new Vector3(1f, 3f, 1f));
            sphere.center = new Vector3(0f, 0f, 0.2f);
            // up from (0, 0, 0.7 − 0.9): the line meets the sphere at z offset −0.9 → y = 5 − sqrt(1.5² − 0.9²) = 3.8
            var origin = new Vector3(0f, 0f, -0.2f);
            Assert.That(Physics.Raycast(origin, Vector3.up * 7f, out var hit), Is.True, "the direction need not be a unit vector");
            AssertHit(hit, sphere, new Vector3(0f, 3.8f, -0.2f), new Vector3(0f, -1.2f, -0.9f) / 1.5f, 3.8f);
            Assert.That(hit.rigidbody, Is.Null);
            Assert.That(hit.triangleIndex, Is.EqualTo(-1));
        }

        [Test]
        public void RotatedScaledBoxIsEnteredOnItsFace()
        {
            // a 4 × 0.2 × 0.3 beam (size (2, 0.1, 0.3) × scale (2, 2, 1)) turned 90° about y: its long axis along z
            var box = Shape<BoxCollider>("Beam", new Vector3(1f, 3f, 0f), Quaternion.Euler(0f, 90f, 0f), new Vector3(2f, 2f, 1f));
            box.size = new Vector3(2f, 0.1f, 0.3f);
            Assert.That(Physics.Raycast(new Vector3(1f, 1f, 1.5f), Vector3.up, out var hit, 10f), Is.True);
            AssertHit(hit, box, new Vector3(1f, 2.9f, 1.5f), Vector3.down, 1.9f);
            // sideways along x: the beam is 0.3 thick there (local z turned onto world x)
            Assert.That(Physics.Raycast(new Vector3(-2f, 3f, 0f), Vector3.right, out hit), Is.True);
            AssertHit(hit, box, new Vector3(0.85f, 3f, 0f), Vector3.left, 2.85f);
            Assert.That(Physics.Raycast(new Vector3(1f, 1f, 2.1f), Vector3.up, out hit), Is.False, "past the beam's end at z = 2");
        }

        [Test]
        public void CapsuleIsEnteredOnItsSideAndOnItsCap()
        {
            // along x (direction 0), height 4·scale 1, radius 0.5·max(scale y, z) = 0.5: segment x ∈ [−1.5, 1.5] at y = 2
            var capsule = Shape<CapsuleCollider>("Bar", new Vector3(0f, 2f, 0f), Quaternion.identity, Vector3.one);
            capsule.direction = 0;
            capsule.height = 4f;
            Assert.That(Physics.Raycast(new Vector3(1f, 0f, 0.3f), Vector3.up, out var hit), Is.True);
            AssertHit(hit, capsule, new Vector3(1f, 2f - 0.4f, 0.3f), new Vector3(0f, -0.4f, 0.3f) / 0.5f, 1.6f);
            Assert.That(Physics.Raycast(new Vector3(-5f, 2f, 0f), Vector3.right, out hit), Is.True);
            AssertHit(hit, capsule, new Vector3(-2f, 2f, 0f), Vector3.left, 3f);
            // into the end cap below its centre: |(x+1.5, −0.3)| = 0.5 → x = −1.9
            Assert.That(Physics.Raycast(new Vector3(-5f, 1.7f, 0f), Vector3.right, out hit), Is.True);
            AssertHit(hit, capsule, new Vector3(-1.9f, 1.7f, 0f), new Vector3(-0.4f, -0.3f, 0f) / 0.5f, 3.1f);
        }

        [Test]
        public void RaycastReturnsTheNearestAndRaycastAllEveryHitWithinMaxDistance()
        {
            var low = Shape<BoxCollider>("Low", new Vector3(0f, 2f, 0f), Quaternion.identity, Vector3.one);
            var high = Shape<SphereCollider>("High", new Vector3(0f, 5f, 0f), Quaternion.identity, Vector3.one);
            var higher = Shape<SphereCollider>("Higher", new Vector3(0f, 8f, 0f), Quaternion.identity, Vector3.one);
            // created in the other order too: the nearest does not depend on the scene's order
            Assert.That(Physics.Raycast(Vector3.zero, Vector3.up, out var hit), Is.True);
            AssertHit(hit, low, new Vector3(0f, 1.5f, 0f), Vector3.down, 1.5f);

            var all = Physics.RaycastAll(Vector3.zero, Vector3.up);
            Assert.That(all.Length, Is.EqualTo(3));
            Array.Sort(all, (a, b) => a.distance.CompareTo(b.distance));
            Assert.That(all[1].collider, Is.SameAs(high));
            Assert.That(all[1].distance, Is.EqualTo(4.5f).Within(Tolerance));
            Assert.That(all[2].collider, Is.SameAs(higher));
            Assert.That(all[2].distance, Is.EqualTo(7.5f).Within(Tolerance));

            Assert.That(Physics.RaycastAll(Vector3.zero, Vector3.up, 4.5f).Length, Is.EqualTo(2), "a hit at exactly maxDistance counts");
            Assert.That(Physics.RaycastAll(Vector3.zero, Vector3.up, 4.49f).Length, Is.EqualTo(1));
            Assert.That(Physics.Raycast(Vector3.zero, Vector3.up, out hit, 1.49f), Is.False);
            Assert.That(Physics.RaycastAll(Vector3.zero, Vector3.zero).Length, Is.EqualTo(0), "a zero direction");
            Assert.That(Physics.Raycast(Vector3.zero, Vector3.zero, out hit), Is.False);
        }

        [Test]
        public void ARayStartingInsideAColliderDoesNotDetectIt()
        {
            var outer = Shape<BoxCollider>("Room", Vector3.zero, Quaternion.identity, new Vector3(10f, 10f, 10f));
            var ball = Shape<SphereCollider>("Ball", new Vector3(0f, 3f, 0f), Quaternion.identity, Vector3.one);
            var all = Physics.RaycastAll(Vector3.zero, Vector3.up);
            Assert.That(all.Length, Is.EqualTo(1));
            Assert.That(all[0].collider, Is.SameAs(ball));
            Assert.That(Physics.Raycast(new Vector3(0f, 3f, 0f), Vector3.up, out _), Is.False, "inside the ball, inside the room");
            Assert.That(outer.enabled, Is.True);
        }

        [Test]
        public void LayersAndDisabledCollidersAreSkipped()
        {
            var ignored = Shape<SphereCollider>("IgnoreRaycast", new Vector3(0f, 2f, 0f), Quaternion.identity, Vector3.one);
            ignored.gameObject.layer = 2;
            var water = Shape<SphereCollider>("Water", new Vector3(0f, 4f, 0f), Quaternion.identity, Vector3.one);
            water.gameObject.layer = 4;
            var off = Shape<SphereCollider>("Off", new Vector3(0f, 1f, 0f), Quaternion.identity, Vector3.one);
            off.enabled = false;

            Assert.That(Physics.Raycast(Vector3.zero, Vector3.up, out var hit), Is.True);
            Assert.That(hit.collider, Is.SameAs(water), "DefaultRaycastLayers leaves out Ignore Raycast (layer 2)");
            Assert.That(Physics.Raycast(Vector3.zero, Vector3.up, out hit, 10f, Physics.AllLayers), Is.True);
            Assert.That(hit.collider, Is.SameAs(ignored));
            Assert.That(Physics.RaycastAll(Vector3.zero, Vector3.up, 10f, ~(1 << 4) & ~(1 << 2)).Length, Is.EqualTo(0));
        }

        [TestCase(QueryTriggerInteraction.Ignore, true, "Solid")]
        [TestCase(QueryTriggerInteraction.Collide, false, "Trigger")]
        [TestCase(QueryTriggerInteraction.UseGlobal, true, "Trigger")]
        [TestCase(QueryTriggerInteraction.UseGlobal, false, "Solid")]
        public void TriggersFollowQueryTriggerInteraction(QueryTriggerInteraction interaction, bool queriesHitTriggers, string expected)
        {
            Shape<SphereCollider>("Trigger", new Vector3(0f, 2f, 0f), Quaternion.identity, Vector3.one).isTrigger = true;
            Shape<SphereCollider>("Solid", new Vector3(0f, 4f, 0f), Quaternion.identity, Vector3.one);
            Physics.queriesHitTriggers = queriesHitTriggers;
            Assert.That(Physics.Raycast(Vector3.zero, Vector3.up, out var hit, 10f, Physics.DefaultRaycastLayers, interaction), Is.True);
            Assert.That(hit.collider.name, Is.EqualTo(expected));
        }

        [Test]
        public void PlaneAndQuadMeshCollidersAreHitOnlyOnTheirFrontFaces()
        {
            // Physics.queriesHitBackfaces is false by default: a mesh triangle is hit from its front side only
            var plane = GameObject.CreatePrimitive(PrimitiveType.Plane); // 10 × 10 m, facing +Y
            plane.transform.position = new Vector3(0f, 3f, 0f);
            Physics.SyncTransforms(); // a Transform moved after its collider was created reaches queries at a sync
            Assert.That(Physics.Raycast(new Vector3(1f, 5f, 2f), Vector3.down, out var hit), Is.True);
            AssertHit(hit, plane.GetComponent<MeshCollider>(), new Vector3(1f, 3f, 2f), Vector3.up, 2f);
            Assert.That(Physics.Raycast(new Vector3(1f, 0f, 2f), Vector3.up, out hit), Is.False, "from below: its back face");
            Assert.That(Physics.Raycast(new Vector3(6f, 5f, 0f), Vector3.down, out hit), Is.False, "past its 5 m half width");

            var quad = GameObject.CreatePrimitive(PrimitiveType.Quad); // 1 × 1 m, facing −Z
            quad.transform.position = new Vector3(0f, 10f, 2f);
            Physics.SyncTransforms();
            Assert.That(Physics.Raycast(new Vector3(0.2f, 10f, 0f), Vector3.forward, out hit), Is.True);
            AssertHit(hit, quad.GetComponent<MeshCollider>(), new Vector3(0.2f, 10f, 2f), Vector3.back, 2f);
            Assert.That(Physics.Raycast(new Vector3(0.2f, 10f, 4f), Vector3.back, out hit), Is.False, "from behind");
        }

        [Test]
        public void AColliderOnABodyIsHitWhereTheBodyIsAndNamesIt()
        {
            var go = new GameObject("Crate");
            go.transform.position = new Vector3(0f, 3f, 0f);
            var body = go.AddComponent<Rigidbody>();
            var box = go.AddComponent<BoxCollider>();
            Assert.That(Physics.Raycast(Vector3.zero, Vector3.up, out var hit), Is.True);
            Assert.That(hit.distance, Is.EqualTo(2.5f).Within(Tolerance));
            Assert.That(hit.collider, Is.SameAs(box));
            Assert.That(hit.rigidbody, Is.SameAs(body));
            Assert.That(hit.transform, Is.SameAs(go.transform));
        }
    }
}
