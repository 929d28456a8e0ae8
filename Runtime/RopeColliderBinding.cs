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
    /// (spheres and capsules use the largest relevant axis, as PhysX does). In
    /// <see cref="RopeCollisionMode.LayerMask"/> mode it also queries the colliders within the rope's reach,
    /// again before every step.
    /// </summary>
    internal sealed class RopeColliderBinding
    {
        static readonly Float3 Up = new Float3(0f, 1f, 0f);

        RopeCollisionMode _mode;
        LayerMask _layers;
        Transform[] _planeSource = Array.Empty<Transform>();
        float _friction;
        RopeEnd _start, _end;
        Component _owner;
        Transform _self;
        Collider[] _overlapBuffer;

        Collider[] _colliders = Array.Empty<Collider>();
        Transform[] _planes = Array.Empty<Transform>();
        int[] _colliderIds = Array.Empty<int>();
        int[] _planeIds = Array.Empty<int>();
        int _colliderCount;
        int _planeCount;

        /// <summary>
        /// Replaces the rope's colliders with those of <paramref name="mode"/>: none (Off), <paramref name="colliders"/>
        /// (Listed Colliders) or the colliders on <paramref name="layers"/> within <paramref name="reach"/> (Layer Mask),
        /// plus the <paramref name="planes"/> unless Off. <paramref name="origin"/> is the rope frame's origin (world, m),
        /// <paramref name="friction"/> the Coulomb coefficient (dimensionless). <paramref name="owner"/> is the rope's
        /// component: the colliders of its GameObject and of the ends' hierarchies are skipped (see <see cref="IsOwn"/>),
        /// unsupported ones reported on it.
        /// </summary>
        public void Bind(Rope rope, RopeCollisionMode mode, Collider[] colliders, LayerMask layers, Transform[] planes, float friction,
            Vector3 origin, RopeEnd start, RopeEnd end, in ColliderReach reach, Component owner)
        {
            _mode = mode;
            _layers = layers;
            _planeSource = planes ?? Array.Empty<Transform>();
            _friction = friction;
            _start = start;
            _end = end;
            _owner = owner;
            _self = owner != null ? owner.transform : null;
            switch (mode)
            {
                case RopeCollisionMode.ListedColliders:
                    Register(rope, colliders, colliders.Length, _planeSource, origin, friction, start, end, warnUnsupported: true);
                    break;
                case RopeCollisionMode.LayerMask:
                {
                    // query first: it creates (or grows) the buffer that is passed on
                    int count = QueryLayerColliders(rope, origin, reach);
                    Register(rope, _overlapBuffer, count, _planeSource, origin, friction, start, end, warnUnsupported: true);
                    break;
                }
                default:
                    Register(rope, Array.Empty<Collider>(), 0, Array.Empty<Transform>(), origin, friction, start, end, warnUnsupported: false);
                    break;
            }
        }

        /// <summary>
        /// Before every rope step: in Layer Mask mode, re-queries the colliders within <paramref name="reach"/> (colliders
        /// come and go: a worker walks past a beam) and re-registers them only when the set changed; then copies every
        /// collider and plane pose in. Allocation-free unless more colliders are in reach than ever before.
        /// </summary>
        public void BeforeStep(Rope rope, Vector3 origin, in ColliderReach reach)
        {
            if (_mode == RopeCollisionMode.LayerMask)
            {
                int count = QueryLayerColliders(rope, origin, reach);
                if (!HasSameColliders(_overlapBuffer, count, _start, _end))
                    Register(rope, _overlapBuffer, count, _planeSource, origin, _friction, _start, _end, warnUnsupported: false);
            }
            UpdatePoses(rope, origin);
        }

        /// <summary>Colliders on the layers within the rope's reach, into the overlap buffer (grown when full).</summary>
        int QueryLayerColliders(Rope rope, Vector3 origin, in ColliderReach reach)
        {
            _overlapBuffer ??= new Collider[16];
            Vector3 start = origin + rope.GetPosition(0).ToVector3(), end = origin + rope.GetPosition(rope.ParticleCount - 1).ToVector3();
            Vector3 center = (start + end) * 0.5f;
            // every particle lies within half the (longest expected) rope length of an end, and each end within half the span of the centre
            float radius = 0.5f * (Vector3.Distance(start, end) + reach.LongestLength) + reach.RopeRadius;
            while (true)
            {
                int count = Physics.OverlapSphereNonAlloc(center, radius, _overlapBuffer, _layers, QueryTriggerInteraction.Ignore);
                if (count < _overlapBuffer.Length) return count;
                _overlapBuffer = new Collider[_overlapBuffer.Length * 2];
            }
        }

        /// <summary>
        /// Replaces the rope's colliders with every supported collider and plane given; unsupported colliders (mesh,
        /// terrain…) are skipped (and reported when <paramref name="warnUnsupported"/>); triggers and the rope's own
        /// colliders (see <see cref="IsOwn"/>) are skipped silently. Allocates only when more shapes arrive than ever before.
        /// </summary>
        void Register(Rope rope, Collider[] colliders, int colliderCount, Transform[] planes, Vector3 origin, float friction,
            RopeEnd start, RopeEnd end, bool warnUnsupported)
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
                        Debug.LogWarning("ElasticRope: collider '" + collider.name + "' is not a Sphere, Capsule or Box collider; the rope ignores it.", _owner);
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
                var shape = ColliderShape.Plane(plane.position.RelativeTo(origin), plane.rotation.ToQuat().Rotate(Up), friction);
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
        bool HasSameColliders(Collider[] colliders, int count, RopeEnd start, RopeEnd end)
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

        bool Accepts(Collider collider, RopeEnd start, RopeEnd end)
        {
            if (collider == null || collider.isTrigger) return false;
            var t = collider.transform;
            return !IsInHierarchyOf(t, _self) && !IsOwn(collider, t, start) && !IsOwn(collider, t, end);
        }

        /// <summary>
        /// True for a collider that belongs to what <paramref name="end"/> is fixed to, and which the rope therefore never
        /// collides with (in both modes; the rope's own GameObject and its children are skipped likewise, in
        /// <see cref="Accepts"/>). The end's particle is pinned at (or loaded by) that object, usually inside or on
        /// its colliders: registered, such a collider would push the end particles out every step while the pin
        /// pulls them back in, and the rope would kink (and jitter) at the end. The rope's own colliders are:
        /// <list type="bullet">
        /// <item>any collider attached to the end's <see cref="RopeEnd.Body"/> (<c>attachedRigidbody == Body</c>: the
        /// worker's capsule and the other colliders of its compound body);</item>
        /// <item>a collider on the GameObject of the end's <see cref="RopeEnd.Point"/> or on any of its descendants
        /// (the anchor block, a bolt or shackle modelled as a child);</item>
        /// <item>a collider on an ancestor of the Point up to and including the first ancestor that carries a Rigidbody
        /// (a D-ring child of the harness: the worker's capsule on the body's GameObject, even when Body is left empty
        /// and the end is a Transform pin). The walk stops there, and does not start when the Point carries a
        /// Rigidbody itself: ancestors above the body, or of a Point under no body at all, are unrelated scene
        /// structure (an "Environment" root with the floor's collider must still catch the rope).</item>
        /// </list>
        /// A consequence: a collider on the GameObject of the Rigidbody an anchor rides on (a moving platform's deck) is
        /// skipped; put it on a child of its own. Allocation-free (parent walks and TryGetComponent), so it can run in
        /// every Layer Mask step through <see cref="HasSameColliders"/>.
        /// </summary>
        static bool IsOwn(Collider collider, Transform colliderTransform, RopeEnd end)
        {
            var endBody = end.Body;
            if (endBody != null)
            {
                var body = collider.attachedRigidbody;
                if (body != null && body == endBody) return true;
            }
            var point = end.Point;
            if (point == null) return false;
            if (IsInHierarchyOf(colliderTransform, point)) return true;
            // the Point's ancestors up to and including the first that carries a Rigidbody (the body the Point moves
            // with); none when the Point carries one itself or no ancestor does
            if (point.TryGetComponent<Rigidbody>(out _)) return false;
            bool passed = false;
            for (var t = point.parent; t != null; t = t.parent)
            {
                passed |= ReferenceEquals(t, colliderTransform);
                if (t.TryGetComponent<Rigidbody>(out _)) return passed;
            }
            return false;
        }

        /// <summary>True when <paramref name="t"/> is <paramref name="root"/> or one of its descendants (false for a null root).</summary>
        static bool IsInHierarchyOf(Transform t, Transform root)
        {
            if (root == null) return false;
            for (; t != null; t = t.parent)
                if (ReferenceEquals(t, root)) return true;
            return false;
        }

        static bool IsSupported(Collider collider) => collider is SphereCollider || collider is CapsuleCollider || collider is BoxCollider;

        static void Reserve<T>(ref T[] items, ref int[] ids, int count)
        {
            if (items.Length >= count) return;
            items = new T[count];
            ids = new int[count];
        }

        /// <summary>Copies the current collider and plane poses into the rope (allocation-free).</summary>
        void UpdatePoses(Rope rope, Vector3 origin)
        {
            for (int i = 0; i < _colliderCount; i++)
            {
                var collider = _colliders[i];
                if (collider == null) continue;
                var t = collider.transform;
                rope.SetColliderPose(_colliderIds[i], t.TransformPoint(LocalCenter(collider)).RelativeTo(origin), ShapeRotation(collider));
            }
            for (int i = 0; i < _planeCount; i++)
            {
                var plane = _planes[i];
                if (plane == null) continue;
                rope.SetColliderPose(_planeIds[i], plane.position.RelativeTo(origin),
                    Quat.FromToRotation(Up, plane.rotation.ToQuat().Rotate(Up)));
            }
        }

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
            var center = t.TransformPoint(LocalCenter(collider)).RelativeTo(origin);
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

    /// <summary>How far the Layer Mask query reaches around the rope's ends.</summary>
    internal readonly struct ColliderReach
    {
        /// <summary>Longest expected rope length (m): the rest length stretched to the break strain (or doubled).</summary>
        public readonly float LongestLength;

        /// <summary>Rest radius of the rope (m).</summary>
        public readonly float RopeRadius;

        /// <summary>A reach for a rope up to <paramref name="longestLength"/> long (m) of radius <paramref name="ropeRadius"/> (m).</summary>
        public ColliderReach(float longestLength, float ropeRadius)
        {
            LongestLength = longestLength;
            RopeRadius = ropeRadius;
        }
    }
}
