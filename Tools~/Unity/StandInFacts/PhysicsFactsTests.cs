using System;
using System.Text.RegularExpressions;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// The stand-in's physics against documented Unity facts, with numbers: ForceMode's velocity change per step
    /// (Rigidbody.AddForce page: Force F·dt/m, Acceleration F·dt, Impulse F/m, VelocityChange F, applied at the next
    /// simulation run), PhysX's semi-implicit Euler step (velocity, then position), drag, the 50 rad/s default angular
    /// speed limit (Physics.defaultMaxAngularSpeed), GetPointVelocity = v + ω × r, the Transform/body sync
    /// (Rigidbody.position, Physics.autoSyncTransforms off), Physics.Simulate outside Script mode, interpolation,
    /// OverlapSphereNonAlloc's layer, trigger and scale rules, and the stand-in's refusal to fake contacts.
    /// </summary>
    [TestFixture]
    public sealed class PhysicsFactsTests
    {
        const float Dt = 0.02f, G = -9.81f;
        bool _wasPlaying;

        [SetUp]
        public void SetUp()
        {
            _wasPlaying = World.IsPlaying;
            World.Reset();
            Physics.simulationMode = SimulationMode.Script;
        }

        [TearDown]
        public void TearDown()
        {
            World.Reset();
            World.IsPlaying = _wasPlaying;
        }

        static Rigidbody Body(string name, Vector3 position, float mass = 1f, bool gravity = false)
        {
            var go = new GameObject(name);
            go.transform.position = position;
            var body = go.AddComponent<Rigidbody>();
            body.mass = mass;
            body.useGravity = gravity;
            return body;
        }

        static void AssertVector(Vector3 actual, Vector3 expected, float tolerance = 1e-5f)
        {
            Assert.That(actual.x, Is.EqualTo(expected.x).Within(tolerance), "x of " + actual);
            Assert.That(actual.y, Is.EqualTo(expected.y).Within(tolerance), "y of " + actual);
            Assert.That(actual.z, Is.EqualTo(expected.z).Within(tolerance), "z of " + actual);
        }

        // ---- Rigidbody -----------------------------------------------------------------------------------------

        [Test]
        public void DefaultsAreUnitys()
        {
            var body = new GameObject("Body").AddComponent<Rigidbody>();
            Assert.That(body.mass, Is.EqualTo(1f));
            Assert.That(body.drag, Is.EqualTo(0f));
            Assert.That(body.angularDrag, Is.EqualTo(0.05f));
            Assert.That(body.useGravity, Is.True);
            Assert.That(body.isKinematic, Is.False);
            Assert.That(body.interpolation, Is.EqualTo(RigidbodyInterpolation.None));
            AssertVector(Physics.gravity, new Vector3(0f, -9.81f, 0f), 0f);
            Assert.That(Physics.queriesHitTriggers, Is.True);
            Assert.That(Physics.AllLayers, Is.EqualTo(-1));
            Assert.That(Physics.DefaultRaycastLayers, Is.EqualTo(~4));
            World.Reset();
            Assert.That(Physics.simulationMode, Is.EqualTo(SimulationMode.FixedUpdate));
        }

        // mass 2 kg, 10 N along x, one 0.02 s step
        [TestCase(ForceMode.Force, 0.1f)]
        [TestCase(ForceMode.Acceleration, 0.2f)]
        [TestCase(ForceMode.Impulse, 5f)]
        [TestCase(ForceMode.VelocityChange, 10f)]
        public void ForceModeVelocityChangeIsAppliedAtTheNextStep(ForceMode mode, float expectedDeltaV)
        {
            var body = Body("Body", Vector3.zero, mass: 2f);
            body.AddForce(new Vector3(10f, 0f, 0f), mode);
            AssertVector(body.velocity, Vector3.zero, 0f);

            Physics.Simulate(Dt);
            AssertVector(body.velocity, new Vector3(expectedDeltaV, 0f, 0f), 1e-6f);
            AssertVector(body.position, new Vector3(expectedDeltaV * Dt, 0f, 0f), 1e-6f);

            Physics.Simulate(Dt); // accumulated forces are cleared by the step
            AssertVector(body.velocity, new Vector3(expectedDeltaV, 0f, 0f), 1e-6f);
        }

        [TestCase(ForceMode.Force, 0.1f)]
        [TestCase(ForceMode.Acceleration, 0.02f)]
        [TestCase(ForceMode.Impulse, 5f)]
        [TestCase(ForceMode.VelocityChange, 1f)]
        public void TorqueModesUseTheInertiaOfTheColliders(ForceMode mode, float expectedDeltaOmega)
        {
            // solid sphere r = 0.5 m, m = 2 kg: I = 2/5·m·r² = 0.2 kg·m²; torque 1 N·m about y, 0.02 s
            var body = Body("Ball", Vector3.zero, mass: 2f);
            body.angularDrag = 0f;
            body.gameObject.AddComponent<SphereCollider>();
            body.AddTorque(new Vector3(0f, 1f, 0f), mode);
            Physics.Simulate(Dt);
            AssertVector(body.angularVelocity, new Vector3(0f, expectedDeltaOmega, 0f), 1e-5f);
        }

        [Test]
        public void ABodyWithoutCollidersHasUnitInertiaAndItsCentreAtItsOrigin()
        {
            var body = Body("Point", new Vector3(1f, 2f, 3f), mass: 5f);
            body.angularDrag = 0f;
            AssertVector(body.worldCenterOfMass, new Vector3(1f, 2f, 3f), 0f);
            body.AddTorque(new Vector3(0f, 0f, 1f), ForceMode.Impulse);
            Physics.Simulate(Dt);
            AssertVector(body.angularVelocity, new Vector3(0f, 0f, 1f), 1e-6f);
        }

        [Test]
        public void CentreOfMassAndInertiaComeFromTheCollidersByVolume()
        {
            // two equal boxes side by side: centre between them; I_y = Σ m/12·(a² + c²) + m·d²
            var body = Body("Dumbbell", new Vector3(0f, 1f, 0f), mass: 4f);
            body.angularDrag = 0f;
            var left = body.gameObject.AddComponent<BoxCollider>();
            left.center = new Vector3(-1f, 0f, 0f);
            var right = body.gameObject.AddComponent<BoxCollider>();
            right.center = new Vector3(1f, 0f, 0f);
            AssertVector(body.centerOfMass, Vector3.zero, 1e-6f);
            right.enabled = false; // a disabled collider is no simulation shape
            AssertVector(body.centerOfMass, new Vector3(-1f, 0f, 0f), 1e-6f);
            AssertVector(body.worldCenterOfMass, new Vector3(-1f, 1f, 0f), 1e-6f);
            right.enabled = true;

            float iy = 2f * (2f / 12f * (1f + 1f) + 2f * 1f * 1f);
            body.AddTorque(new Vector3(0f, 1f, 0f), ForceMode.Impulse);
            Physics.Simulate(Dt);
            Assert.That(body.angularVelocity.y, Is.EqualTo(1f / iy).Within(1e-5f));
        }

        [Test]
        public void FreeFallIsSemiImplicitEuler()
        {
            // v_n = n·g·dt, y_n = y0 + g·dt²·n(n+1)/2 (velocity first, then position: PhysX's order)
            const int n = 100;
            const float y0 = 50f;
            var body = Body("Stone", new Vector3(0f, y0, 0f), gravity: true);
            for (int i = 0; i < n; i++) Physics.Simulate(Dt);
            Assert.That(body.velocity.y, Is.EqualTo(n * G * Dt).Within(1e-3f));
            Assert.That(body.position.y, Is.EqualTo(y0 + G * Dt * Dt * n * (n + 1) / 2f).Within(1e-3f));
            Assert.That(body.transform.position.y, Is.EqualTo(body.position.y), "the Transform follows after each step");
        }

        [Test]
        public void DragScalesVelocityByOneMinusDragTimesDtNeverBelowZero()
        {
            var body = Body("Body", Vector3.zero);
            body.drag = 2f;
            body.velocity = new Vector3(10f, 0f, 0f);
            Physics.Simulate(0.1f);
            Assert.That(body.velocity.x, Is.EqualTo(8f).Within(1e-5f));
            body.drag = 20f;
            Physics.Simulate(0.1f);
            Assert.That(body.velocity.x, Is.EqualTo(0f));
        }

        [Test]
        public void AngularSpeedIsLimitedTo50RadiansPerSecond()
        {
            var body = Body("Spinner", Vector3.zero);
            body.angularDrag = 0f;
            body.angularVelocity = new Vector3(0f, 80f, 0f);
            Physics.Simulate(Dt);
            Assert.That(body.angularVelocity.magnitude, Is.EqualTo(50f).Within(1e-3f));
        }

        [Test]
        public void RotationTurnsByOmegaTimesDt()
        {
            var body = Body("Spinner", Vector3.zero);
            body.angularDrag = 0f;
            body.angularVelocity = new Vector3(0f, 1f, 0f);
            Physics.Simulate(0.5f);
            var turned = body.rotation * Vector3.forward;
            AssertVector(turned, new Vector3((float)Math.Sin(0.5), 0f, (float)Math.Cos(0.5)), 1e-5f);
        }

        [Test]
        public void GetPointVelocityIsVPlusOmegaCrossR()
        {
            var body = Body("Wheel", new Vector3(1f, 0f, 0f));
            body.gameObject.AddComponent<SphereCollider>();
            body.velocity = new Vector3(1f, 2f, 3f);
            body.angularVelocity = new Vector3(0f, 0f, 2f);
            // r = (0, 1, 0) from the centre of mass; ω × r = (−2, 0, 0)
            AssertVector(body.GetPointVelocity(new Vector3(1f, 1f, 0f)), new Vector3(-1f, 2f, 3f), 1e-6f);
        }

        [Test]
        public void ForceAtAPositionAlsoTurnsTheBody()
        {
            var body = Body("Body", Vector3.zero);
            body.angularDrag = 0f;
            body.AddForceAtPosition(new Vector3(0f, 0f, 1f), new Vector3(1f, 0f, 0f), ForceMode.Impulse);
            Physics.Simulate(Dt);
            AssertVector(body.velocity, new Vector3(0f, 0f, 1f), 1e-6f);
            AssertVector(body.angularVelocity, new Vector3(0f, -1f, 0f), 1e-6f); // r × F / I, I = 1 without colliders
        }

        [Test]
        public void KinematicBodiesAreNotMovedAndIgnoreForces()
        {
            var body = Body("Kinematic", new Vector3(0f, 3f, 0f), gravity: true);
            body.isKinematic = true;
            body.AddForce(new Vector3(100f, 0f, 0f), ForceMode.VelocityChange);
            for (int i = 0; i < 10; i++) Physics.Simulate(Dt);
            AssertVector(body.position, new Vector3(0f, 3f, 0f), 0f);
            AssertVector(body.velocity, Vector3.zero, 0f);
        }

        [Test]
        public void PositionSetterTeleportsAndTheTransformFollowsAfterTheNextStep()
        {
            var body = Body("Body", Vector3.zero);
            body.velocity = new Vector3(1f, 0f, 0f);
            body.position = new Vector3(0f, 5f, 0f);
            AssertVector(body.transform.position, Vector3.zero, 0f);
            Physics.Simulate(Dt);
            AssertVector(body.position, new Vector3(Dt, 5f, 0f), 1e-6f);
            AssertVector(body.transform.position, body.position, 0f);
        }

        [Test]
        public void ATransformMovedByAScriptIsPushedToTheBodyAtTheNextStep()
        {
            var body = Body("Body", Vector3.zero);
            body.velocity = new Vector3(1f, 0f, 0f);
            body.transform.position = new Vector3(0f, 7f, 0f);
            AssertVector(body.position, Vector3.zero, 0f);
            Physics.Simulate(Dt);
            AssertVector(body.position, new Vector3(Dt, 7f, 0f), 1e-6f);
            AssertVector(body.velocity, new Vector3(1f, 0f, 0f), 0f);
        }

        [Test]
        public void NestedBodiesEachGetTheirOwnPose()
        {
            var child = Body("Child", new Vector3(0f, 12f, 0f), gravity: true);
            var parent = Body("Parent", new Vector3(0f, 10f, 0f));
            child.transform.SetParent(parent.transform, true);
            parent.velocity = new Vector3(1f, 0f, 0f);
            for (int i = 0; i < 10; i++) Physics.Simulate(Dt);
            AssertVector(parent.transform.position, new Vector3(10f * Dt, 10f, 0f), 1e-5f);
            AssertVector(child.transform.position, new Vector3(0f, 12f + G * Dt * Dt * 55f, 0f), 1e-4f);
            AssertVector(child.position, child.transform.position, 0f);
        }

        [Test]
        public void NonFiniteMassIsRejectedWithUnitysError()
        {
            var body = Body("Body", Vector3.zero, mass: 3f);
            LogAssert.Expect(LogType.Error, new Regex("^rigidbody.mass assign attempt for 'Body' is not valid"));
            body.mass = float.NaN;
            Assert.That(body.mass, Is.EqualTo(3f));
        }

        // ---- Physics.Simulate and the player loop --------------------------------------------------------------

        [Test]
        public void SimulateOutsideScriptModeWarnsAndDoesNothing()
        {
            var body = Body("Stone", new Vector3(0f, 1f, 0f), gravity: true);
            Physics.simulationMode = SimulationMode.FixedUpdate;
            LogAssert.Expect(LogType.Warning, new Regex("^Physics.Simulate\\(...\\) was called but simulation mode is not set to Script"));
            Physics.Simulate(Dt);
            AssertVector(body.position, new Vector3(0f, 1f, 0f), 0f);
        }

        [Test]
        public void InterpolatedTransformLiesBetweenTheLastTwoPhysicsPoses()
        {
            World.IsPlaying = true;
            Physics.simulationMode = SimulationMode.FixedUpdate;
            var body = Body("Mover", Vector3.zero);
            body.interpolation = RigidbodyInterpolation.Interpolate;
            body.velocity = new Vector3(1f, 0f, 0f);
            for (int frame = 0; frame < 7; frame++)
            {
                PlayerLoop.RunUntil(LoopPoint.AfterUpdate);
                float alpha = (Time.time - Time.fixedTime) / Time.fixedDeltaTime;
                float after = body.position.x, before = after - Time.fixedDeltaTime; // 1 m/s
                Assert.That(alpha, Is.InRange(0f, 1f), "frame " + frame);
                Assert.That(body.transform.position.x, Is.EqualTo(before + alpha * (after - before)).Within(1e-5f), "frame " + frame);
                PlayerLoop.FinishFrame();
            }
        }

        [Test]
        public void AnInterpolatedBodyIgnoresTransformEditsButNotRigidbodyPosition()
        {
            // PhysicsScene.ResetInterpolationPoses (automatic for the default scene): interpolated Transforms are reset
            // to Rigidbody.position before simulating, so they are never synced into the engine
            World.IsPlaying = true;
            Physics.simulationMode = SimulationMode.FixedUpdate;
            var body = Body("Mover", Vector3.zero);
            body.interpolation = RigidbodyInterpolation.Interpolate;
            PlayerLoop.RunFrames(1);
            body.transform.position = new Vector3(0f, 5f, 0f);
            PlayerLoop.RunFrames(4);
            AssertVector(body.position, Vector3.zero, 0f);
            AssertVector(body.transform.position, Vector3.zero, 0f);

            body.position = new Vector3(0f, 5f, 0f);
            PlayerLoop.RunFrames(4);
            AssertVector(body.transform.position, new Vector3(0f, 5f, 0f), 0f);
        }

        [Test]
        public void WithoutInterpolationTheTransformShowsTheLastPhysicsPose()
        {
            World.IsPlaying = true;
            Physics.simulationMode = SimulationMode.FixedUpdate;
            var body = Body("Mover", Vector3.zero);
            body.velocity = new Vector3(1f, 0f, 0f);
            PlayerLoop.RunFrames(5);
            Assert.That(body.position.x, Is.GreaterThan(0f));
            AssertVector(body.transform.position, body.position, 0f);
        }

        // ---- OverlapSphereNonAlloc -------------------------------------------------------------------------------

        static SphereCollider Sphere(string name, Vector3 position, float radius, int layer = 0)
        {
            var go = new GameObject(name) { layer = layer };
            go.transform.position = position;
            var sphere = go.AddComponent<SphereCollider>();
            sphere.radius = radius;
            return sphere;
        }

        [Test]
        public void OverlapSphereHonoursTheLayerMask()
        {
            var onDefault = Sphere("Default", new Vector3(0f, 0f, 0f), 0.5f);
            var onWater = Sphere("Water", new Vector3(0f, 0f, 0.5f), 0.5f, LayerMask.NameToLayer("Water"));
            var results = new Collider[4];

            Assert.That(Physics.OverlapSphereNonAlloc(Vector3.zero, 1f, results), Is.EqualTo(2));
            Assert.That(Physics.OverlapSphereNonAlloc(Vector3.zero, 1f, results, LayerMask.GetMask("Water")), Is.EqualTo(1));
            Assert.That(results[0], Is.SameAs(onWater));
            Assert.That(Physics.OverlapSphereNonAlloc(Vector3.zero, 1f, results, ~LayerMask.GetMask("Water")), Is.EqualTo(1));
            Assert.That(results[0], Is.SameAs(onDefault));
            Assert.That(Physics.OverlapSphereNonAlloc(Vector3.zero, 1f, new Collider[1]), Is.EqualTo(1), "capped at the buffer");
            Assert.That(LayerMask.NameToLayer("Water"), Is.EqualTo(4));
            Assert.That(LayerMask.LayerToName(2), Is.EqualTo("Ignore Raycast"));
        }

        [TestCase(QueryTriggerInteraction.Ignore, true, 1)]
        [TestCase(QueryTriggerInteraction.Collide, false, 2)]
        [TestCase(QueryTriggerInteraction.UseGlobal, true, 2)]
        [TestCase(QueryTriggerInteraction.UseGlobal, false, 1)]
        public void OverlapSphereHonoursTriggers(QueryTriggerInteraction interaction, bool queriesHitTriggers, int expected)
        {
            Sphere("Solid", new Vector3(1f, 0f, 0f), 0.5f);
            Sphere("Trigger", new Vector3(-1f, 0f, 0f), 0.5f).isTrigger = true;
            Physics.queriesHitTriggers = queriesHitTriggers;
            Assert.That(Physics.OverlapSphereNonAlloc(Vector3.zero, 0.6f, new Collider[4], Physics.AllLayers, interaction), Is.EqualTo(expected));
        }

        [Test]
        public void OverlapSphereSkipsDisabledCollidersAndInactiveObjects()
        {
            var disabled = Sphere("Disabled", Vector3.zero, 0.5f);
            disabled.enabled = false;
            var inactive = Sphere("Inactive", Vector3.zero, 0.5f);
            inactive.gameObject.SetActive(false);
            Assert.That(Physics.OverlapSphereNonAlloc(Vector3.zero, 1f, new Collider[4]), Is.EqualTo(0));
        }

        [TestCase(1.9f, 1)]
        [TestCase(2.1f, 0)]
        public void SphereRadiusScalesWithTheLargestAxis(float distance, int expected)
        {
            // r = 0.5 · max(1, 3, 1) = 1.5; query radius 0.5 → reach 2.0
            var sphere = Sphere("Scaled", Vector3.zero, 0.5f);
            sphere.transform.localScale = new Vector3(1f, 3f, 1f);
            Physics.SyncTransforms();
            Assert.That(Physics.OverlapSphereNonAlloc(new Vector3(distance, 0f, 0f), 0.5f, new Collider[1]), Is.EqualTo(expected));
        }

        [TestCase(0f, 0f, 1.95f, 1)] // long axis: 4 m box turned 90° about y lies along z
        [TestCase(1.95f, 0f, 0f, 0)]
        [TestCase(0.55f, 0f, 0f, 1)]
        [TestCase(0f, 0.65f, 0f, 0)]
        public void BoxIsOrientedAndScaledPerAxis(float x, float y, float z, int expected)
        {
            var go = new GameObject("Box");
            go.transform.rotation = Quaternion.Euler(0f, 90f, 0f);
            go.transform.localScale = new Vector3(4f, 1f, 1f);
            go.AddComponent<BoxCollider>();
            Assert.That(Physics.OverlapSphereNonAlloc(new Vector3(x, y, z), 0.1f, new Collider[1]), Is.EqualTo(expected));
        }

        // scale (2, 1.5, 1), Y axis: height 2 · 1.5 = 3 (tips at y = ±1.5), radius 0.5 · max(2, 1) = 1; query radius 0.1
        [TestCase(0f, 1.55f, 0f, 1)]
        [TestCase(0f, 1.65f, 0f, 0)]
        [TestCase(1.05f, 0f, 0f, 1)]
        [TestCase(1.15f, 0f, 0f, 0)]
        public void CapsuleScalesHeightAlongItsAxisAndRadiusByTheLargerCrossAxis(float x, float y, float z, int expected)
        {
            var go = new GameObject("Capsule");
            go.transform.localScale = new Vector3(2f, 1.5f, 1f);
            go.AddComponent<CapsuleCollider>();
            Assert.That(Physics.OverlapSphereNonAlloc(new Vector3(x, y, z), 0.1f, new Collider[1]), Is.EqualTo(expected));
        }

        [Test]
        public void QueriesSeeATransformChangeOnlyAfterASync()
        {
            var sphere = Sphere("Moved", Vector3.zero, 0.5f);
            sphere.transform.position = new Vector3(10f, 0f, 0f);
            var results = new Collider[1];
            Assert.That(Physics.OverlapSphereNonAlloc(Vector3.zero, 0.6f, results), Is.EqualTo(1), "autoSyncTransforms is off: the old pose");
            Physics.SyncTransforms();
            Assert.That(Physics.OverlapSphereNonAlloc(Vector3.zero, 0.6f, results), Is.EqualTo(0));
            Assert.That(Physics.OverlapSphereNonAlloc(new Vector3(10f, 0f, 0f), 0.6f, results), Is.EqualTo(1));
        }

        [Test]
        public void QueriesSeeCollidersOfABodyWhereTheBodyIs()
        {
            var body = Body("Body", Vector3.zero);
            body.gameObject.AddComponent<SphereCollider>();
            body.position = new Vector3(0f, 4f, 0f);
            Assert.That(body.GetComponent<SphereCollider>().attachedRigidbody, Is.SameAs(body));
            Assert.That(Physics.OverlapSphereNonAlloc(new Vector3(0f, 4f, 0f), 0.1f, new Collider[1]), Is.EqualTo(1));
        }

        static MeshCollider MeshObject(string name, PrimitiveType type, Vector3 position, Vector3 scale)
        {
            var go = new GameObject(name);
            go.transform.position = position;
            go.transform.localScale = scale;
            go.AddComponent<MeshFilter>().sharedMesh = PrimitiveMeshes.Get(type);
            return go.AddComponent<MeshCollider>();
        }

        [TestCase(9.5f, 0.05f, -9.5f, 1)] // Plane: 10 × 10 in local XZ, scaled by 2
        [TestCase(10.5f, 0f, 0f, 0)]
        [TestCase(0f, 0.15f, 0f, 0)]
        public void APlaneMeshColliderIsAFlatRectangle(float x, float y, float z, int expected)
        {
            var plane = MeshObject("Ground", PrimitiveType.Plane, Vector3.zero, new Vector3(2f, 1f, 2f));
            Assert.That(plane.sharedMesh, Is.SameAs(PrimitiveMeshes.Get(PrimitiveType.Plane)), "a MeshCollider takes the MeshFilter's mesh");
            Assert.That(Physics.OverlapSphereNonAlloc(new Vector3(x, y, z), 0.1f, new Collider[1]), Is.EqualTo(expected));
        }

        [Test]
        public void AMeshColliderWithAnyOtherMeshIsUnsupported()
        {
            MeshObject("Rock", PrimitiveType.Cube, Vector3.zero, Vector3.one);
            var e = Assert.Throws<NotSupportedException>(() => Physics.OverlapSphereNonAlloc(Vector3.zero, 1f, new Collider[1]));
            Assert.That(e.Message, Does.Contain("'Rock' (MeshCollider)"));
        }

        // ---- contacts ----------------------------------------------------------------------------------------------

        [Test]
        public void ADynamicBodyReachingAnotherColliderThrows()
        {
            var floor = new GameObject("Floor");
            floor.transform.localScale = new Vector3(10f, 1f, 10f);
            floor.AddComponent<BoxCollider>();
            var ball = Body("Ball", new Vector3(0f, 1.2f, 0f), gravity: true);
            ball.gameObject.AddComponent<SphereCollider>();

            Physics.Simulate(Dt); // 0.2 m of clearance: no contact yet
            var e = Assert.Throws<NotSupportedException>(() => { for (int i = 0; i < 100; i++) Physics.Simulate(Dt); });
            Assert.That(e.Message, Does.Contain("does not solve contacts"));
            Assert.That(e.Message, Does.Contain("'Ball' (SphereCollider)"));
            Assert.That(e.Message, Does.Contain("'Floor' (BoxCollider)"));
        }

        [Test]
        public void ADynamicBodyFallingOntoAPlaneThrows()
        {
            MeshObject("Ground", PrimitiveType.Plane, Vector3.zero, Vector3.one);
            var ball = Body("Ball", new Vector3(0f, 0.6f, 0f), gravity: true);
            ball.gameObject.AddComponent<SphereCollider>();
            var e = Assert.Throws<NotSupportedException>(() => { for (int i = 0; i < 100; i++) Physics.Simulate(Dt); });
            Assert.That(e.Message, Does.Contain("'Ground' (MeshCollider)"));
            Assert.That(ball.position.y, Is.LessThan(0.5f).And.GreaterThan(0.4f), "thrown at the first step that penetrates");
        }

        sealed class TriggerListener : MonoBehaviour { }

        [Test]
        public void ATriggerOverlapThrowsOnlyWhenAScriptCouldHearIt()
        {
            var zone = Sphere("Zone", Vector3.zero, 1f);
            zone.isTrigger = true;
            var ball = Body("Ball", new Vector3(0.5f, 0f, 0f));
            ball.gameObject.AddComponent<SphereCollider>();
            Assert.DoesNotThrow(() => Physics.Simulate(Dt), "no script: nobody receives OnTriggerEnter");
            zone.gameObject.AddComponent<TriggerListener>();
            var e = Assert.Throws<NotSupportedException>(() => Physics.Simulate(Dt));
            Assert.That(e.Message, Does.Contain("does not send trigger messages"));
        }

        [Test]
        public void OverlapsWithoutADynamicBodyAreNoContacts()
        {
            Sphere("Static A", Vector3.zero, 0.5f);
            Sphere("Static B", new Vector3(0.5f, 0f, 0f), 0.5f);
            var kinematic = Body("Kinematic", new Vector3(0f, 0.5f, 0f));
            kinematic.isKinematic = true;
            kinematic.gameObject.AddComponent<BoxCollider>();
            var compound = Body("Compound", new Vector3(5f, 0f, 0f));
            compound.gameObject.AddComponent<SphereCollider>();
            compound.gameObject.AddComponent<BoxCollider>(); // colliders of one body never collide with each other
            Assert.DoesNotThrow(() => Physics.Simulate(Dt));
        }
    }
}
