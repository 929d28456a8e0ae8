using System;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: where a ray first enters a <see cref="WorldShape"/> — capsules (spheres included) as the
    /// nearest of the cylinder side and the two end spheres, boxes (flat rectangles included) by the slab method in
    /// the box's frame. A ray that starts inside a shape does not hit it (Unity: "Raycasts will not detect Colliders
    /// for which the Raycast origin is inside the Collider"). Exact up to float rounding; allocation-free.
    /// </summary>
    internal static class ShapeRaycast
    {
        /// <summary>
        /// The distance along the unit <paramref name="direction"/> from <paramref name="origin"/> at which the ray
        /// enters <paramref name="shape"/>, and the outward surface normal there; false when it misses or starts inside.
        /// </summary>
        internal static bool Enter(Vector3 origin, Vector3 direction, in WorldShape shape, out double distance, out Vector3 normal)
        {
            switch (shape.Kind)
            {
                case ShapeKind.Capsule: return EnterCapsule(origin, direction, shape, out distance, out normal);
                case ShapeKind.Box: return EnterBox(origin, direction, shape, out distance, out normal);
                default:
                    distance = 0.0;
                    normal = default;
                    return false;
            }
        }

        static bool EnterCapsule(Vector3 origin, Vector3 direction, in WorldShape shape, out double distance, out Vector3 normal)
        {
            distance = 0.0;
            normal = default;
            double r = shape.Radius;
            if (ShapeOverlap.PointSegmentDistanceSq(origin, shape.A, shape.B) < r * r) return false;

            double best = double.PositiveInfinity;
            if (SphereEntry(origin, direction, shape.A, r, out double t) && t < best) best = t;
            if (SphereEntry(origin, direction, shape.B, r, out t) && t < best) best = t;
            if (CylinderEntry(origin, direction, shape.A, shape.B, r, out t) && t < best) best = t;
            if (double.IsPositiveInfinity(best)) return false;

            distance = best;
            var hit = At(origin, direction, best);
            normal = (hit - ClosestOnSegment(hit, shape.A, shape.B)).normalized;
            return true;
        }

        /// <summary>The smaller non-negative root of |o + t·d − c|² = r² (d a unit vector).</summary>
        static bool SphereEntry(Vector3 origin, Vector3 direction, Vector3 center, double radius, out double t)
        {
            double mx = origin.x - center.x, my = origin.y - center.y, mz = origin.z - center.z;
            double b = mx * direction.x + my * direction.y + mz * direction.z;
            double c = mx * mx + my * my + mz * mz - radius * radius;
            double disc = b * b - c;
            t = 0.0;
            if (disc < 0.0) return false;
            t = -b - Math.Sqrt(disc);
            return t >= 0.0;
        }

        /// <summary>Where the ray enters the side of the cylinder of radius r around a–b, between its end planes.</summary>
        static bool CylinderEntry(Vector3 origin, Vector3 direction, Vector3 a, Vector3 b, double radius, out double t)
        {
            t = 0.0;
            double ax = b.x - a.x, ay = b.y - a.y, az = b.z - a.z;
            double length = Math.Sqrt(ax * ax + ay * ay + az * az);
            if (length <= 0.0) return false;
            ax /= length; ay /= length; az /= length;
            double mx = origin.x - a.x, my = origin.y - a.y, mz = origin.z - a.z;
            double md = mx * ax + my * ay + mz * az, dd = direction.x * ax + direction.y * ay + direction.z * az;
            // components perpendicular to the axis
            double px = mx - md * ax, py = my - md * ay, pz = mz - md * az;
            double qx = direction.x - dd * ax, qy = direction.y - dd * ay, qz = direction.z - dd * az;
            double qa = qx * qx + qy * qy + qz * qz;
            if (qa <= 1e-18) return false; // parallel to the axis: only the end spheres can be entered
            double qb = px * qx + py * qy + pz * qz;
            double qc = px * px + py * py + pz * pz - radius * radius;
            double disc = qb * qb - qa * qc;
            if (disc < 0.0) return false;
            t = (-qb - Math.Sqrt(disc)) / qa;
            if (t < 0.0) return false;
            double along = md + t * dd;
            return along >= 0.0 && along <= length;
        }

        static bool EnterBox(Vector3 origin, Vector3 direction, in WorldShape shape, out double distance, out Vector3 normal)
        {
            distance = 0.0;
            normal = default;
            var offset = origin - shape.Center;
            double near = double.NegativeInfinity, far = double.PositiveInfinity;
            int nearAxis = -1;
            double nearSign = 0.0;
            bool inside = true;
            for (int axis = 0; axis < 3; axis++)
            {
                var unit = axis == 0 ? shape.AxisX : axis == 1 ? shape.AxisY : shape.AxisZ;
                double half = axis == 0 ? shape.Half.x : axis == 1 ? shape.Half.y : shape.Half.z;
                double o = Vector3.Dot(offset, unit), d = Vector3.Dot(direction, unit);
                if (!(Math.Abs(o) < half)) inside = false;
                if (Math.Abs(d) <= 1e-12)
                {
                    if (Math.Abs(o) > half) return false;
                    continue;
                }
                double t1 = (-half - o) / d, t2 = (half - o) / d;
                if (t1 > t2) (t1, t2) = (t2, t1);
                if (t1 > near)
                {
                    near = t1;
                    nearAxis = axis;
                    nearSign = d > 0.0 ? -1.0 : 1.0;
                }
                if (t2 < far) far = t2;
                if (near > far) return false;
            }
            if (inside || nearAxis < 0 || near < 0.0 || far < 0.0) return false;
            distance = near;
            var n = nearAxis == 0 ? shape.AxisX : nearAxis == 1 ? shape.AxisY : shape.AxisZ;
            normal = n * (float)nearSign;
            return true;
        }

        /// <summary>origin + t·direction, in double before rounding.</summary>
        internal static Vector3 At(Vector3 origin, Vector3 direction, double t) =>
            new Vector3((float)(origin.x + t * direction.x), (float)(origin.y + t * direction.y), (float)(origin.z + t * direction.z));

        static Vector3 ClosestOnSegment(Vector3 p, Vector3 a, Vector3 b)
        {
            var ab = b - a;
            double len2 = Vector3.Dot(ab, ab);
            double t = len2 > 0.0 ? Vector3.Dot(p - a, ab) / len2 : 0.0;
            t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
            return At(a, ab, t);
        }
    }
}
