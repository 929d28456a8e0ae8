using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// A static or moving collider the rope's particles cannot enter (each particle is a sphere of
    /// <see cref="Rope.ParticleRadius"/>). Build one with <see cref="Plane"/>, <see cref="Sphere"/>,
    /// <see cref="Capsule"/> or <see cref="Box"/>; move it with <see cref="Rope.SetColliderPose"/>.
    /// </summary>
    public readonly struct ColliderShape
    {
        /// <summary>Shape kind.</summary>
        public readonly ColliderKind Kind;
        /// <summary>World position in metres (plane: a point on it; others: the centre).</summary>
        public readonly Float3 Position;
        /// <summary>World rotation (plane normal = Rotation·(0, 1, 0); capsule axis = Rotation·(0, 1, 0)).</summary>
        public readonly Quat Rotation;
        /// <summary>Sphere or capsule radius in metres.</summary>
        public readonly float Radius;
        /// <summary>Capsule half length of the core segment along local Y in metres (total length 2·HalfHeight + 2·Radius).</summary>
        public readonly float HalfHeight;
        /// <summary>Box half extents along local X, Y, Z in metres.</summary>
        public readonly Float3 HalfExtents;
        /// <summary>Coulomb friction coefficient of sliding, μ_k (dimensionless, ≥ 0; 0 = frictionless).</summary>
        public readonly float Friction;
        /// <summary>
        /// Coulomb friction coefficient of sticking, μ_s (dimensionless, ≥ 0): the friction cone a contact must leave to
        /// start sliding. Equal to <see cref="Friction"/> unless set with <see cref="WithStaticFriction"/>; a value below
        /// <see cref="Friction"/> acts as <see cref="Friction"/> (a sliding contact could not stop otherwise).
        /// </summary>
        public readonly float StaticFriction;

        private ColliderShape(ColliderKind kind, Float3 position, Quat rotation, float radius, float halfHeight, Float3 halfExtents, float friction)
        {
            if (!position.IsFinite) throw new ArgumentException("position must be finite (metres)", nameof(position));
            if (!rotation.IsFinite || !(rotation.LengthSquared > 1e-12f)) throw new ArgumentException("rotation must be a finite, non-zero quaternion", nameof(rotation));
            if (!float.IsFinite(friction) || friction < 0f) throw new ArgumentOutOfRangeException(nameof(friction), friction, "friction must be finite and in [0, +inf)");
            Kind = kind;
            Position = position;
            Rotation = rotation.Normalized();
            Radius = radius;
            HalfHeight = halfHeight;
            HalfExtents = halfExtents;
            Friction = friction;
            StaticFriction = friction;
        }

        private ColliderShape(in ColliderShape shape, float staticFriction)
        {
            this = shape;
            StaticFriction = staticFriction;
        }

        /// <summary>
        /// This shape with a static friction coefficient μ_s (dimensionless, finite, ≥ 0) of its own; <see cref="Friction"/>
        /// stays the sliding coefficient μ_k. Unity's PhysicMaterial has both (staticFriction, dynamicFriction).
        /// </summary>
        public ColliderShape WithStaticFriction(float staticFriction)
        {
            if (!float.IsFinite(staticFriction) || staticFriction < 0f)
                throw new ArgumentOutOfRangeException(nameof(staticFriction), staticFriction, "staticFriction must be finite and in [0, +inf)");
            return new ColliderShape(this, staticFriction);
        }

        /// <summary>Plane through <paramref name="point"/> (m) with outward <paramref name="normal"/> (any length, non-zero).</summary>
        public static ColliderShape Plane(Float3 point, Float3 normal, float friction = 0f)
        {
            if (!normal.IsFinite || !(normal.LengthSquared > 1e-20f)) throw new ArgumentException("normal must be finite and non-zero", nameof(normal));
            return new ColliderShape(ColliderKind.Plane, point, Quat.FromToRotation(new Float3(0f, 1f, 0f), normal), 0f, 0f, Float3.Zero, friction);
        }

        /// <summary>Sphere of <paramref name="radius"/> (m, &gt; 0) about <paramref name="center"/> (m).</summary>
        public static ColliderShape Sphere(Float3 center, float radius, float friction = 0f)
        {
            CheckPositive(radius, nameof(radius));
            return new ColliderShape(ColliderKind.Sphere, center, Quat.Identity, radius, 0f, Float3.Zero, friction);
        }

        /// <summary>Capsule about <paramref name="center"/> (m), axis = rotation·Y, core half length <paramref name="halfHeight"/> (m, ≥ 0), radius (m, &gt; 0).</summary>
        public static ColliderShape Capsule(Float3 center, Quat rotation, float radius, float halfHeight, float friction = 0f)
        {
            CheckPositive(radius, nameof(radius));
            if (!float.IsFinite(halfHeight) || halfHeight < 0f) throw new ArgumentOutOfRangeException(nameof(halfHeight), halfHeight, "halfHeight must be finite and in [0, +inf) metres");
            return new ColliderShape(ColliderKind.Capsule, center, rotation, radius, halfHeight, Float3.Zero, friction);
        }

        /// <summary>Oriented box about <paramref name="center"/> (m) with <paramref name="halfExtents"/> (m, each &gt; 0).</summary>
        public static ColliderShape Box(Float3 center, Quat rotation, Float3 halfExtents, float friction = 0f)
        {
            CheckPositive(halfExtents.X, nameof(halfExtents));
            CheckPositive(halfExtents.Y, nameof(halfExtents));
            CheckPositive(halfExtents.Z, nameof(halfExtents));
            return new ColliderShape(ColliderKind.Box, center, rotation, 0f, 0f, halfExtents, friction);
        }

        private static void CheckPositive(float value, string name)
        {
            if (!float.IsFinite(value) || value <= 0f) throw new ArgumentOutOfRangeException(name, value, name + " must be finite and in (0, +inf) metres");
        }
    }
}
