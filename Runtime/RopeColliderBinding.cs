using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using UnityEngine;

namespace HookeRope
{
    /// <summary>
    /// Registers Unity Sphere, Capsule and Box colliders (and plane Transforms, whose up axis is the normal) with
    /// a core <see cref="Rope"/> and copies their poses in each step. Poses are converted to the rope's simulation
    /// frame (world axes, origin at <c>origin</c>). Scale is taken from <see cref="Transform.lossyScale"/>
    /// (spheres and capsules use the largest relevant axis, as PhysX does).
    /// </summary>
    internal sealed class RopeColliderBinding
    {
        static readonly Float3 Up = new Float3(0f, 1f, 0f);

        Collider[] _colliders = Array.Empty<Collider>();
        Transform[] _planes = Array.Empty<Transform>();
        int[] _colliderIds = Array.Empty<int>();
        int[] _planeIds = Array.Empty<int>();
        int _colliderCount;
        int _planeCount;

        /// <summary>
        /// Replaces the rope's colliders with every supported collider and plane given; unsupported colliders (mesh,
        /// terrain…) are skipped (and reported when <paramref name="warnUnsupported"/>); triggers and the rope's own
        /// colliders (see <see cref="IsOwn"/>) are skipped silently. Allocates only when more shapes arrive than ever before.
        /// </summary>
        public void Register(Rope rope, Collider[] colliders, int colliderCount, Transform[] planes, Vector3 origin, float friction,
            RopeEnd start, RopeEnd end, UnityEngine.Object context, bool warnUnsupported)
        {
            rope.ClearColliders();
            Reserve(ref _colliders, ref _colliderIds, colliderCount);
            _colliderCount = 0;
            for (int i = 0; i < colliderCount; i++)
            {
                var collider = colliders[i];
                if (!Accepts(collider, start, end)) continue;
                if (!TryShape(collider, origin, friction, out var shape))
                {
                    if (warnUnsupported)
                        Debug.LogWarning("ElasticRope: collider '" + collider.name + "' is not a Sphere, Capsule or Box collider; the rope ignores it.", context);
                    continue;
                }
                _colliders[_colliderCount] = collider;
                _colliderIds[_colliderCount] = rope.AddCollider(in shape);
                _colliderCount++;
            }

            int planeCount = planes == null ? 0 : planes.Length;
            Reserve(ref _planes, ref _planeIds, planeCount);
            _planeCount = 0;
            for (int i = 0; i < planeCount; i++)
            {
                var plane = planes[i];
                if (plane == null) continue;
                var shape = ColliderShape.Plane(Sim(plane.position, origin), plane.rotation.ToQuat().Rotate(Up), friction);
                _planes[_planeCount] = plane;
                _planeIds[_planeCount] = rope.AddCollider(in shape);
                _planeCount++;
            }
        }

        /// <summary>
        /// True when the supported colliders among the first <paramref name="count"/> of <paramref name="colliders"/>
        /// are exactly the registered ones (in any order), so a layer-mask query that found the same set needs no
        /// re-registration (which would also forget the current contacts). Allocation-free.
        /// </summary>
        public bool HasSameColliders(Collider[] colliders, int count, RopeEnd start, RopeEnd end)
        {
            int accepted = 0;
            for (int i = 0; i < count; i++)
            {
                var collider = colliders[i];
                if (!Accepts(collider, start, end) || !IsSupported(collider)) continue;
                accepted++;
                if (Array.IndexOf(_colliders, collider, 0, _colliderCount) < 0) return false;
            }
            return accepted == _colliderCount;
        }

        static bool Accepts(Collider collider, RopeEnd start, RopeEnd end) =>
            collider != null && !collider.isTrigger && !IsOwn(collider, start) && !IsOwn(collider, end);

        /// <summary>
        /// True for a collider the rope end is fixed in: on the end's Rigidbody (the worker's own capsule), or on the
        /// GameObject of the end's Transform (the anchor's or hand's own collider). A particle pinned inside such a
        /// collider would be pushed out every step and kink the rope at the end.
        /// </summary>
        static bool IsOwn(Collider collider, RopeEnd end)
        {
            var body = collider.attachedRigidbody;
            if (body != null && end.Body != null && body == end.Body) return true;
            return end.Point != null && collider.gameObject == end.Point.gameObject;
        }

        static bool IsSupported(Collider collider) => collider is SphereCollider || collider is CapsuleCollider || collider is BoxCollider;

        static void Reserve<T>(ref T[] items, ref int[] ids, int count)
        {
            if (items.Length >= count) return;
            items = new T[count];
            ids = new int[count];
        }

        /// <summary>Copies the current collider and plane poses into the rope (allocation-free).</summary>
        public void UpdatePoses(Rope rope, Vector3 origin)
        {
            for (int i = 0; i < _colliderCount; i++)
            {
                var collider = _colliders[i];
                if (collider == null) continue;
                var t = collider.transform;
                rope.SetColliderPose(_colliderIds[i], Sim(t.TransformPoint(LocalCenter(collider)), origin), ShapeRotation(collider));
            }
            for (int i = 0; i < _planeCount; i++)
            {
                var plane = _planes[i];
                if (plane == null) continue;
                rope.SetColliderPose(_planeIds[i], Sim(plane.position, origin),
                    Quat.FromToRotation(Up, plane.rotation.ToQuat().Rotate(Up)));
            }
        }

        static Float3 Sim(Vector3 world, Vector3 origin) => new Float3(world.x - origin.x, world.y - origin.y, world.z - origin.z);

        static Vector3 LocalCenter(Collider collider)
        {
            switch (collider)
            {
                case SphereCollider sphere: return sphere.center;
                case CapsuleCollider capsule: return capsule.center;
                case BoxCollider box: return box.center;
                default: return Vector3.zero;
            }
        }

        static Quat ShapeRotation(Collider collider)
        {
            var rotation = collider.transform.rotation.ToQuat();
            if (collider is CapsuleCollider capsule)
                return rotation * Quat.FromToRotation(Up, Axis(capsule.direction));
            return rotation;
        }

        static Float3 Axis(int direction) =>
            direction == 0 ? new Float3(1f, 0f, 0f) : direction == 2 ? new Float3(0f, 0f, 1f) : Up;

        static bool TryShape(Collider collider, Vector3 origin, float friction, out ColliderShape shape)
        {
            var t = collider.transform;
            var s = t.lossyScale;
            float sx = Math.Abs(s.x), sy = Math.Abs(s.y), sz = Math.Abs(s.z);
            var center = Sim(t.TransformPoint(LocalCenter(collider)), origin);
            switch (collider)
            {
                case SphereCollider sphere:
                    shape = ColliderShape.Sphere(center, Math.Max(1e-6f, sphere.radius * Math.Max(sx, Math.Max(sy, sz))), friction);
                    return true;
                case CapsuleCollider capsule:
                {
                    float axisScale = capsule.direction == 0 ? sx : capsule.direction == 2 ? sz : sy;
                    float radiusScale = capsule.direction == 0 ? Math.Max(sy, sz) : capsule.direction == 2 ? Math.Max(sx, sy) : Math.Max(sx, sz);
                    float radius = Math.Max(1e-6f, capsule.radius * radiusScale);
                    float halfHeight = Math.Max(0f, 0.5f * capsule.height * axisScale - radius);
                    shape = ColliderShape.Capsule(center, ShapeRotation(collider), radius, halfHeight, friction);
                    return true;
                }
                case BoxCollider box:
                {
                    var size = box.size;
                    var half = new Float3(Math.Max(1e-6f, 0.5f * Math.Abs(size.x) * sx), Math.Max(1e-6f, 0.5f * Math.Abs(size.y) * sy),
                        Math.Max(1e-6f, 0.5f * Math.Abs(size.z) * sz));
                    shape = ColliderShape.Box(center, ShapeRotation(collider), half, friction);
                    return true;
                }
                default:
                    shape = default;
                    return false;
            }
        }
    }
}
