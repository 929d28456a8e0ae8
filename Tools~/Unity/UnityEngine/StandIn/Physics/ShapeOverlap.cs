using System;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: exact overlap tests between <see cref="WorldShape"/>s — sphere and capsule against anything by
    /// closest distance (a convex 1-D minimisation for capsule–box), box–box by the 15-axis separating-axis test
    /// (slightly conservative on near-parallel edges). Allocation-free.
    /// </summary>
    internal static class ShapeOverlap
    {
        /// <summary>Whether the sphere touches or is inside <paramref name="shape"/> (distance ≤ <paramref name="radius"/>), as overlap queries report.</summary>
        internal static bool SphereTouches(Vector3 center, float radius, in WorldShape shape)
        {
            switch (shape.Kind)
            {
                case ShapeKind.Capsule:
                {
                    double reach = (double)radius + shape.Radius;
                    return reach >= 0.0 && PointSegmentDistanceSq(center, shape.A, shape.B) <= reach * reach;
                }
                case ShapeKind.Box:
                    return radius >= 0f && PointBoxDistanceSq(center, shape) <= (double)radius * radius;
                default:
                    return false;
            }
        }

        /// <summary>Whether the two shapes interpenetrate (touching is not enough): what the engine would have to push apart.</summary>
        internal static bool Penetrate(in WorldShape a, in WorldShape b)
        {
            if (a.Kind == ShapeKind.Capsule && b.Kind == ShapeKind.Capsule)
            {
                double reach = (double)a.Radius + b.Radius;
                return SegmentSegmentDistanceSq(a.A, a.B, b.A, b.B) < reach * reach;
            }
            if (a.Kind == ShapeKind.Capsule && b.Kind == ShapeKind.Box)
                return SegmentBoxDistanceSq(a.A, a.B, b) < (double)a.Radius * a.Radius;
            if (a.Kind == ShapeKind.Box && b.Kind == ShapeKind.Capsule)
                return SegmentBoxDistanceSq(b.A, b.B, a) < (double)b.Radius * b.Radius;
            if (a.Kind == ShapeKind.Box && b.Kind == ShapeKind.Box)
                return BoxesOverlap(a, b);
            return false;
        }

        /// <summary>Squared distance from <paramref name="p"/> to the segment a–b.</summary>
        internal static double PointSegmentDistanceSq(Vector3 p, Vector3 a, Vector3 b)
        {
            double abx = b.x - a.x, aby = b.y - a.y, abz = b.z - a.z;
            double apx = p.x - a.x, apy = p.y - a.y, apz = p.z - a.z;
            double len2 = abx * abx + aby * aby + abz * abz;
            double t = len2 > 0.0 ? Clamp01((apx * abx + apy * aby + apz * abz) / len2) : 0.0;
            double dx = apx - t * abx, dy = apy - t * aby, dz = apz - t * abz;
            return dx * dx + dy * dy + dz * dz;
        }

        /// <summary>Squared distance between the segments p1–q1 and p2–q2 (closest points by clamped parameters).</summary>
        internal static double SegmentSegmentDistanceSq(Vector3 p1, Vector3 q1, Vector3 p2, Vector3 q2)
        {
            double d1x = q1.x - p1.x, d1y = q1.y - p1.y, d1z = q1.z - p1.z;
            double d2x = q2.x - p2.x, d2y = q2.y - p2.y, d2z = q2.z - p2.z;
            double rx = p1.x - p2.x, ry = p1.y - p2.y, rz = p1.z - p2.z;
            double a = d1x * d1x + d1y * d1y + d1z * d1z;
            double e = d2x * d2x + d2y * d2y + d2z * d2z;
            double f = d2x * rx + d2y * ry + d2z * rz;
            double s, t;
            const double tiny = 1e-20;
            if (a <= tiny && e <= tiny)
            {
                s = t = 0.0;
            }
            else if (a <= tiny)
            {
                s = 0.0;
                t = Clamp01(f / e);
            }
            else
            {
                double c = d1x * rx + d1y * ry + d1z * rz;
                if (e <= tiny)
                {
                    t = 0.0;
                    s = Clamp01(-c / a);
                }
                else
                {
                    double b = d1x * d2x + d1y * d2y + d1z * d2z;
                    double denom = a * e - b * b;
                    s = denom > tiny * a * e ? Clamp01((b * f - c * e) / denom) : 0.0;
                    t = (b * s + f) / e;
                    if (t < 0.0) { t = 0.0; s = Clamp01(-c / a); }
                    else if (t > 1.0) { t = 1.0; s = Clamp01((b - c) / a); }
                }
            }
            double dx = rx + d1x * s - d2x * t, dy = ry + d1y * s - d2y * t, dz = rz + d1z * s - d2z * t;
            return dx * dx + dy * dy + dz * dz;
        }

        /// <summary>Squared distance from <paramref name="p"/> to the (solid) box.</summary>
        internal static double PointBoxDistanceSq(Vector3 p, in WorldShape box)
        {
            double dx = p.x - box.Center.x, dy = p.y - box.Center.y, dz = p.z - box.Center.z;
            double ex = Excess(dx * box.AxisX.x + dy * box.AxisX.y + dz * box.AxisX.z, box.Half.x);
            double ey = Excess(dx * box.AxisY.x + dy * box.AxisY.y + dz * box.AxisY.z, box.Half.y);
            double ez = Excess(dx * box.AxisZ.x + dy * box.AxisZ.y + dz * box.AxisZ.z, box.Half.z);
            return ex * ex + ey * ey + ez * ez;
        }

        /// <summary>
        /// Squared distance from the segment a–b to the box: the distance to a convex set is convex along the segment, so a
        /// golden-section search over the segment parameter converges to the minimum (to ~1e-13 of the segment length).
        /// </summary>
        internal static double SegmentBoxDistanceSq(Vector3 a, Vector3 b, in WorldShape box)
        {
            double fa = PointBoxDistanceSq(a, box), fb = PointBoxDistanceSq(b, box);
            if (fa == 0.0 || fb == 0.0 || a.Equals(b)) return Math.Min(fa, fb);
            const double inverseGolden = 0.6180339887498949;
            double lo = 0.0, hi = 1.0;
            double x1 = hi - inverseGolden * (hi - lo), x2 = lo + inverseGolden * (hi - lo);
            double f1 = PointBoxDistanceSq(Lerp(a, b, x1), box), f2 = PointBoxDistanceSq(Lerp(a, b, x2), box);
            for (int i = 0; i < 64 && f1 > 0.0 && f2 > 0.0; i++)
            {
                if (f1 <= f2)
                {
                    hi = x2; x2 = x1; f2 = f1;
                    x1 = hi - inverseGolden * (hi - lo);
                    f1 = PointBoxDistanceSq(Lerp(a, b, x1), box);
                }
                else
                {
                    lo = x1; x1 = x2; f1 = f2;
                    x2 = lo + inverseGolden * (hi - lo);
                    f2 = PointBoxDistanceSq(Lerp(a, b, x2), box);
                }
            }
            return Math.Min(Math.Min(fa, fb), Math.Min(f1, f2));
        }

        /// <summary>Separating-axis test of two oriented boxes (face normals of both and the 9 edge-edge cross products); touching counts as separate.</summary>
        internal static bool BoxesOverlap(in WorldShape a, in WorldShape b)
        {
            const double eps = 1e-6;
            Vector3 ax = a.AxisX, ay = a.AxisY, az = a.AxisZ, bx = b.AxisX, by = b.AxisY, bz = b.AxisZ;
            // rotation of b in a's frame and its absolute value (+eps against parallel edges)
            double r00 = Dot(ax, bx), r01 = Dot(ax, by), r02 = Dot(ax, bz);
            double r10 = Dot(ay, bx), r11 = Dot(ay, by), r12 = Dot(ay, bz);
            double r20 = Dot(az, bx), r21 = Dot(az, by), r22 = Dot(az, bz);
            double q00 = Math.Abs(r00) + eps, q01 = Math.Abs(r01) + eps, q02 = Math.Abs(r02) + eps;
            double q10 = Math.Abs(r10) + eps, q11 = Math.Abs(r11) + eps, q12 = Math.Abs(r12) + eps;
            double q20 = Math.Abs(r20) + eps, q21 = Math.Abs(r21) + eps, q22 = Math.Abs(r22) + eps;
            var d = b.Center - a.Center;
            double t0 = Dot(d, ax), t1 = Dot(d, ay), t2 = Dot(d, az);
            double a0 = a.Half.x, a1 = a.Half.y, a2 = a.Half.z, b0 = b.Half.x, b1 = b.Half.y, b2 = b.Half.z;

            // a's face normals
            if (Math.Abs(t0) >= a0 + b0 * q00 + b1 * q01 + b2 * q02) return false;
            if (Math.Abs(t1) >= a1 + b0 * q10 + b1 * q11 + b2 * q12) return false;
            if (Math.Abs(t2) >= a2 + b0 * q20 + b1 * q21 + b2 * q22) return false;
            // b's face normals
            if (Math.Abs(t0 * r00 + t1 * r10 + t2 * r20) >= a0 * q00 + a1 * q10 + a2 * q20 + b0) return false;
            if (Math.Abs(t0 * r01 + t1 * r11 + t2 * r21) >= a0 * q01 + a1 * q11 + a2 * q21 + b1) return false;
            if (Math.Abs(t0 * r02 + t1 * r12 + t2 * r22) >= a0 * q02 + a1 * q12 + a2 * q22 + b2) return false;
            // a_i × b_j
            if (Math.Abs(t2 * r10 - t1 * r20) >= a1 * q20 + a2 * q10 + b1 * q02 + b2 * q01) return false;
            if (Math.Abs(t2 * r11 - t1 * r21) >= a1 * q21 + a2 * q11 + b0 * q02 + b2 * q00) return false;
            if (Math.Abs(t2 * r12 - t1 * r22) >= a1 * q22 + a2 * q12 + b0 * q01 + b1 * q00) return false;
            if (Math.Abs(t0 * r20 - t2 * r00) >= a0 * q20 + a2 * q00 + b1 * q12 + b2 * q11) return false;
            if (Math.Abs(t0 * r21 - t2 * r01) >= a0 * q21 + a2 * q01 + b0 * q12 + b2 * q10) return false;
            if (Math.Abs(t0 * r22 - t2 * r02) >= a0 * q22 + a2 * q02 + b0 * q11 + b1 * q10) return false;
            if (Math.Abs(t1 * r00 - t0 * r10) >= a0 * q10 + a1 * q00 + b1 * q22 + b2 * q21) return false;
            if (Math.Abs(t1 * r01 - t0 * r11) >= a0 * q11 + a1 * q01 + b0 * q22 + b2 * q20) return false;
            if (Math.Abs(t1 * r02 - t0 * r12) >= a0 * q12 + a1 * q02 + b0 * q21 + b1 * q20) return false;
            return true;
        }

        static double Excess(double coordinate, float half)
        {
            double e = Math.Abs(coordinate) - half;
            return e > 0.0 ? e : 0.0;
        }

        static double Dot(Vector3 a, Vector3 b) => (double)a.x * b.x + (double)a.y * b.y + (double)a.z * b.z;

        static Vector3 Lerp(Vector3 a, Vector3 b, double t) =>
            new Vector3((float)(a.x + (b.x - a.x) * t), (float)(a.y + (b.y - a.y) * t), (float)(a.z + (b.z - a.z) * t));

        static double Clamp01(double v) => v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
    }
}
