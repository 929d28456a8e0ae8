using System;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the stand-in does not sweep a CharacterController, so after a Move it checks that the
    /// capsule is not inside another enabled non-trigger collider (sphere, capsule, box; not one on its own
    /// GameObject). Unity would have stopped or slid the character; the stand-in throws instead of going on with a
    /// wrong answer. Allocation-free.
    /// </summary>
    internal static class ControllerOverlap
    {
        internal static void ThrowIfInsideAnotherCollider(CharacterController controller)
        {
            var own = controller.PhysicsShape(null);
            var colliders = PhysicsWorld.Colliders;
            for (int i = 0; i < colliders.Count; i++)
            {
                var other = colliders[i];
                if (ReferenceEquals(other, controller) || !other.InScene || other.isTrigger) continue;
                if (ReferenceEquals(other.gameObject, controller.gameObject)) continue;
                if (!(other is SphereCollider || other is CapsuleCollider || other is BoxCollider || other is CharacterController)) continue;
                var body = other.attachedRigidbody;
                var shape = other.PhysicsShape(body is object && body.InScene ? body : null);
                if (!ShapeOverlap.Penetrate(own, shape)) continue;
                throw new NotSupportedException("The Unity stand-in does not sweep a CharacterController: Move left " + controller.Describe() +
                                                " inside " + other.Describe() + " (Unity would stop or slide it along the collider). Keep the character clear of colliders in stand-in tests.");
            }
        }
    }
}
