using System;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: a body's centre of mass and inertia tensor (about that centre, in the body's frame), computed
    /// as PhysX's PxRigidBodyExt::setMassAndUpdateInertia does for Unity's automatic centre of mass and tensor: the
    /// body's mass spread over its simulation shapes (enabled, non-trigger colliders attached to it) in proportion to
    /// their volume; no shape gives the centre at the body's origin and the tensor (1, 1, 1).
    /// </summary>
    internal readonly struct MassProperties
    {
        internal readonly Vector3 CenterOfMass;
        internal readonly InertiaTensor Inertia;

        MassProperties(Vector3 centerOfMass, InertiaTensor inertia)
        {
            CenterOfMass = centerOfMass;
            Inertia = inertia;
        }

        /// <summary>The mass properties of <paramref name="body"/> from its colliders as they are now. Allocation-free.</summary>
        internal static MassProperties Of(Rigidbody body)
        {
            float mass = body.mass;
            var colliders = PhysicsWorld.Colliders;
            double volume = 0.0, cx = 0.0, cy = 0.0, cz = 0.0;
            for (int i = 0; i < colliders.Count; i++)
            {
                if (!TryShape(colliders[i], body, out var shape)) continue;
                double v = Volume(shape);
                volume += v;
                cx += v * shape.Center.x;
                cy += v * shape.Center.y;
                cz += v * shape.Center.z;
            }
            if (!(volume > 0.0)) return new MassProperties(Vector3.zero, InertiaTensor.Unit);
            var com = new Vector3((float)(cx / volume), (float)(cy / volume), (float)(cz / volume));
            var inertia = InertiaTensor.Zero;
            for (int i = 0; i < colliders.Count; i++)
            {
                if (!TryShape(colliders[i], body, out var shape)) continue;
                float m = (float)(mass * Volume(shape) / volume);
                inertia = inertia + UnitInertia(shape).Scaled(m) + InertiaTensor.PointMass(m, shape.Center - com);
            }
            return new MassProperties(com, inertia);
        }

        /// <summary>The collider's shape in the body's frame, when it is one of the body's simulation shapes.</summary>
        static bool TryShape(Collider collider, Rigidbody body, out WorldShape shape)
        {
            shape = default;
            if (!collider.InScene || collider.isTrigger || !ReferenceEquals(collider.attachedRigidbody, body)) return false;
            shape = collider.BuildShape(collider.FrameInBody(body));
            switch (shape.Kind)
            {
                case ShapeKind.Capsule:
                case ShapeKind.Box:
                    return true;
                case ShapeKind.Unsupported:
                    if (body.IsDynamic)
                        throw StandInError.Unsupported(shape.Unsupported + " on the non-kinematic Rigidbody '" + body.name +
                                                       "' (Unity supports only convex mesh colliders on dynamic bodies)");
                    return false;
                default:
                    return false;
            }
        }

        static double Volume(in WorldShape shape)
        {
            if (shape.Kind == ShapeKind.Box) return 8.0 * shape.Half.x * shape.Half.y * shape.Half.z;
            double r = shape.Radius, length = Vector3.Distance(shape.A, shape.B);
            return Math.PI * r * r * length + 4.0 / 3.0 * Math.PI * r * r * r;
        }

        /// <summary>Inertia per unit mass about the shape's own centre.</summary>
        static InertiaTensor UnitInertia(in WorldShape shape)
        {
            if (shape.Kind == ShapeKind.Box)
            {
                float x = shape.Half.x * shape.Half.x, y = shape.Half.y * shape.Half.y, z = shape.Half.z * shape.Half.z;
                return InertiaTensor.FromPrincipal(new Vector3((y + z) / 3f, (x + z) / 3f, (x + y) / 3f), shape.Rotation);
            }
            double r = shape.Radius, length = Vector3.Distance(shape.A, shape.B), h = 0.5 * length;
            double cylinder = Math.PI * r * r * length, spheres = 4.0 / 3.0 * Math.PI * r * r * r, total = cylinder + spheres;
            double fc = cylinder / total, fs = spheres / total;
            double axial = fc * r * r / 2.0 + fs * 2.0 * r * r / 5.0;
            // two hemispheres, each with its centroid 3r/8 beyond the end of the cylinder
            double transverse = fc * (r * r / 4.0 + length * length / 12.0) + fs * (2.0 * r * r / 5.0 + h * h + 3.0 * h * r / 4.0);
            var axis = length > 0.0 ? (shape.B - shape.A) / (float)length : new Vector3(0f, 1f, 0f);
            return InertiaTensor.Axisymmetric(axis, (float)axial, (float)transverse);
        }
    }
}
