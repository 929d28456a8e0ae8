using System;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.Events;
using UnityEngine.TestTools.Constraints;
using Is = UnityEngine.TestTools.Constraints.Is;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// The stand-in's CharacterController and UnityEvent invocation against documented Unity facts: defaults (radius
    /// 0.5, height 2, center 0, minMoveDistance 0.001), Move translates by the motion and returns CollisionFlags,
    /// velocity is the displacement of the last Move over Time.deltaTime (zero after a Move below minMoveDistance:
    /// "it will not move at all"), CollisionFlags' values (UCR Dynamics.cs), the refusal to fake a sweep into a
    /// collider, and UnityEvent.Invoke allocating nothing once warm (UCR InvokableCallList.PrepareInvoke caches).
    /// </summary>
    [TestFixture]
    public sealed class CharacterControllerFactsTests
    {
        FreshWorld _world;

        [SetUp] public void SetUp() => _world = new FreshWorld();
        [TearDown] public void TearDown() => _world.Dispose();

        static CharacterController Controller(Vector3 position)
        {
            var go = new GameObject("Character", typeof(CharacterController));
            go.transform.position = position;
            return go.GetComponent<CharacterController>();
        }

        [Test]
        public void DefaultsAndFlagValuesAreUnitys()
        {
            var controller = Controller(Vector3.zero);
            Assert.That(controller.radius, Is.EqualTo(0.5f));
            Assert.That(controller.height, Is.EqualTo(2f));
            Assert.That(controller.center, Is.EqualTo(Vector3.zero));
            Assert.That(controller.minMoveDistance, Is.EqualTo(0.001f));
            Assert.That(controller, Is.InstanceOf<Collider>());
            Assert.That((int)CollisionFlags.None, Is.EqualTo(0));
            Assert.That((int)CollisionFlags.Sides, Is.EqualTo(1));
            Assert.That((int)CollisionFlags.Above, Is.EqualTo(2));
            Assert.That((int)CollisionFlags.Below, Is.EqualTo(4));
            Assert.That(CollisionFlags.CollidedBelow, Is.EqualTo(CollisionFlags.Below));
        }

        /// <summary>Moves its controller by <see cref="Motion"/> in every FixedUpdate.</summary>
        sealed class FixedMover : MonoBehaviour
        {
            public CharacterController Controller;
            public Vector3 Motion;
            public CollisionFlags Flags = CollisionFlags.Above;
            void FixedUpdate() => Flags = Controller.Move(Motion);
        }

        [Test]
        public void MoveTranslatesAndVelocityIsTheLastMoveOverDeltaTime()
        {
            World.IsPlaying = true;
            Time.fixedDeltaTime = 0.02f;
            var controller = Controller(new Vector3(1f, 2f, 3f));
            var mover = controller.gameObject.AddComponent<FixedMover>();
            mover.Controller = controller;
            mover.Motion = new Vector3(0.1f, -0.2f, 0f);
            PlayerLoop.RunSeconds(0.1f);
            int steps = (int)Math.Round(Time.fixedTime / 0.02f) + 1;   // the first fixed step is at t = 0
            Assert.That(mover.Flags, Is.EqualTo(CollisionFlags.None));
            Assert.That(controller.transform.position.y, Is.EqualTo(2f - 0.2f * steps).Within(1e-4f));
            Assert.That(controller.transform.position.x, Is.EqualTo(1f + 0.1f * steps).Within(1e-4f));
            Assert.That(controller.velocity.y, Is.EqualTo(-0.2f / 0.02f).Within(1e-3f), "the last Move over Time.deltaTime (fixedDeltaTime in FixedUpdate)");
            Assert.That(controller.isGrounded, Is.False);
            // below minMoveDistance (1 mm) it does not move at all, and its velocity is zero
            var before = controller.transform.position;
            mover.Motion = new Vector3(0f, -0.0005f, 0f);
            PlayerLoop.RunSeconds(0.05f);
            Assert.That(controller.transform.position, Is.EqualTo(before));
            Assert.That(controller.velocity, Is.EqualTo(Vector3.zero));
            controller.minMoveDistance = 0f;
            PlayerLoop.RunSeconds(0.05f);
            Assert.That(controller.transform.position.y, Is.LessThan(before.y - 0.0009f));
            Assert.That(controller.velocity.y, Is.EqualTo(-0.0005f / 0.02f).Within(1e-5f));
        }

        [Test]
        public void MovingIntoAColliderThrowsInsteadOfFakingASweep()
        {
            var controller = Controller(new Vector3(0f, 3f, 0f));
            var box = new GameObject("Box", typeof(BoxCollider));
            box.transform.position = Vector3.zero;   // 1 m cube, top at 0.5 m; the capsule's bottom is at 2 m
            controller.Move(new Vector3(0f, -1.4f, 0f));   // bottom at 0.6 m: clear
            var error = Assert.Throws<NotSupportedException>(() => controller.Move(new Vector3(0f, -0.2f, 0f)));
            Assert.That(error.Message, Does.Contain("'Box' (BoxCollider)"));
        }

        int _calls;
        float _sum;
        void Listener(float a, float b) { _calls++; _sum += a + b; }

        [Test]
        public void UnityEventInvokeAllocatesNothingOnceWarm()
        {
            var unityEvent = new UnityEvent<float, float>();
            unityEvent.AddListener(Listener);
            unityEvent.Invoke(1f, 2f);
            Assert.That(() => unityEvent.Invoke(3f, 4f), Is.Not.AllocatingGCMemory());
            Assert.That(_calls, Is.EqualTo(2));
            Assert.That(_sum, Is.EqualTo(10f));
            // a listener added later is called from the next Invoke on
            unityEvent.AddListener(Listener);
            unityEvent.Invoke(0f, 1f);
            Assert.That(_calls, Is.EqualTo(4));
        }
    }
}
