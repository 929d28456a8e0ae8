using System;
using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>
    /// The conservative broad phase of a <see cref="CollisionSet"/>: two bounds per collider — over the whole host step
    /// (<see cref="SetSweep"/>, from its start and end poses) and in the current substep (<see cref="SetPose"/>) — each a
    /// plane's normal and offset or the world box of a sphere, capsule or box, and the test whether a
    /// <see cref="ParticleBox"/> can reach one (<see cref="Near"/>). A box is grown by its largest radius times
    /// 1 + <see cref="CollisionSet.ContactMarginFraction"/> (the farthest a particle can be and still be pushed, held,
    /// detected or rubbed by friction) and by a rounding allowance, so a collider it rules out is one the narrow phase
    /// would leave alone to the bit. NaN or ±∞ anywhere makes the test say "near". Allocation-free after
    /// <see cref="Reserve"/>.
    /// </summary>
    internal sealed class CollisionBroadPhase
    {
        /// <summary>
        /// Rounding allowance as a fraction of the magnitudes involved (coordinates, collider sizes, radius): the narrow
        /// phase's float32 distance is off by a few tens of float epsilons (6e-8) of them at most, and an nlerp of two equal
        /// rotations by a few, so this is far on the safe side.
        /// </summary>
        private const double RelativeTolerance = 1e-4;

        private const int Values = 7; // plane: nx ny nz, offset, –, –, scale; others: lo x y z, hi x y z, scale

        private ColliderKind[] kinds = new ColliderKind[0];
        private double[] bounds = new double[0]; // per collider: the sweep's values, then the substep's
        private bool[] unbounded = new bool[0];  // per collider: the sweep could not be bounded (a turning plane)

        /// <summary>Makes room for <paramref name="colliders"/> colliders (allocates only when they grow).</summary>
        public void Reserve(int colliders)
        {
            if (colliders <= kinds.Length) return;
            Array.Resize(ref kinds, colliders);
            Array.Resize(ref bounds, colliders * 2 * Values);
            Array.Resize(ref unbounded, colliders);
        }

        /// <summary>
        /// Bound of collider k over the host step, whose centre moves on the segment c0 → c1 (rope-local m) and whose rotation
        /// goes from q0 to q1 (unit). A turning collider is bounded by the ball its shape sweeps about its centre (a turning plane
        /// not at all: only its substep bound rules it out).
        /// </summary>
        public void SetSweep(int k, in ColliderShape shape, Float3 c0, Float3 c1, Quat q0, Quat q1)
        {
            kinds[k] = shape.Kind;
            bool turning = q0 != q1;
            unbounded[k] = turning && shape.Kind == ColliderKind.Plane;
            if (unbounded[k]) return;
            if (!turning)
            {
                Bound(k * 2 * Values, in shape, c0, c1, q0);
                return;
            }
            double[] b = bounds;
            int o = k * 2 * Values;
            double reach = shape.Kind == ColliderKind.Sphere ? shape.Radius
                : shape.Kind == ColliderKind.Capsule ? (double)shape.HalfHeight + shape.Radius
                : Math.Sqrt((double)shape.HalfExtents.X * shape.HalfExtents.X + (double)shape.HalfExtents.Y * shape.HalfExtents.Y
                            + (double)shape.HalfExtents.Z * shape.HalfExtents.Z);
            Span(b, o, c0, c1, reach, reach, reach);
            b[o + 6] = Magnitude(c0) + Magnitude(c1) + reach;
        }

        /// <summary>Bound of collider k in the current substep: its shape at rope-local centre (m) and unit rotation.</summary>
        public void SetPose(int k, in ColliderShape shape, Float3 centre, Quat q)
        {
            kinds[k] = shape.Kind;
            Bound((k * 2 + 1) * Values, in shape, centre, centre, q);
        }

        /// <summary>Writes into slot o the bound of the shape with unit rotation q whose centre is anywhere on c0 → c1.</summary>
        private void Bound(int o, in ColliderShape shape, Float3 c0, Float3 c1, Quat q)
        {
            double[] b = bounds;
            double scale = Magnitude(c0) + Magnitude(c1);
            switch (shape.Kind)
            {
                case ColliderKind.Plane:
                {
                    // the narrow phase's normal, to the bit; the offset of whichever end is the nearer to the particles' side
                    Float3 n = q.Rotate(new Float3(0f, 1f, 0f));
                    b[o] = n.X; b[o + 1] = n.Y; b[o + 2] = n.Z;
                    b[o + 3] = Math.Max(Dot(n, c0), Dot(n, c1));
                    b[o + 4] = 0.0; b[o + 5] = 0.0;
                    break;
                }
                case ColliderKind.Sphere:
                    Span(b, o, c0, c1, shape.Radius, shape.Radius, shape.Radius);
                    scale += shape.Radius;
                    break;
                case ColliderKind.Capsule:
                {
                    Float3 axis = q.Rotate(new Float3(0f, 1f, 0f)) * shape.HalfHeight;
                    double ax = Math.Abs(axis.X) + shape.Radius, ay = Math.Abs(axis.Y) + shape.Radius, az = Math.Abs(axis.Z) + shape.Radius;
                    Span(b, o, c0, c1, ax, ay, az);
                    scale += shape.HalfHeight + shape.Radius;
                    break;
                }
                default:
                {
                    Float3 e = shape.HalfExtents;
                    Float3 ex = q.Rotate(new Float3(1f, 0f, 0f)), ey = q.Rotate(new Float3(0f, 1f, 0f)), ez = q.Rotate(new Float3(0f, 0f, 1f));
                    Span(b, o, c0, c1,
                        Math.Abs(ex.X) * e.X + Math.Abs(ey.X) * e.Y + Math.Abs(ez.X) * e.Z,
                        Math.Abs(ex.Y) * e.X + Math.Abs(ey.Y) * e.Y + Math.Abs(ez.Y) * e.Z,
                        Math.Abs(ex.Z) * e.X + Math.Abs(ey.Z) * e.Y + Math.Abs(ez.Z) * e.Z);
                    scale += e.X + e.Y + e.Z;
                    break;
                }
            }
            b[o + 6] = scale;
        }

        private static double Dot(Float3 n, Float3 c) => (double)n.X * c.X + (double)n.Y * c.Y + (double)n.Z * c.Z;

        private static double Magnitude(Float3 c) => Math.Abs(c.X) + Math.Abs(c.Y) + Math.Abs(c.Z);

        /// <summary>Writes into slot o the box spanned by points a and c grown by (gx, gy, gz) (m).</summary>
        private static void Span(double[] b, int o, Float3 a, Float3 c, double gx, double gy, double gz)
        {
            b[o] = Math.Min(a.X, c.X) - gx; b[o + 1] = Math.Min(a.Y, c.Y) - gy; b[o + 2] = Math.Min(a.Z, c.Z) - gz;
            b[o + 3] = Math.Max(a.X, c.X) + gx; b[o + 4] = Math.Max(a.Y, c.Y) + gy; b[o + 5] = Math.Max(a.Z, c.Z) + gz;
        }

        /// <summary>
        /// False only when no particle in <paramref name="box"/> can be within reach of collider k's surface, or inside it,
        /// anywhere on its path over the host step (<paramref name="sweep"/>) or in the current substep (see <see cref="Within"/>).
        /// </summary>
        public bool Near(int k, in ParticleBox box, bool sweep) => Within(k, in box, Reach(k, in box, sweep), sweep);

        /// <summary>
        /// How far (m) a particle of <paramref name="box"/> can be from collider k's bound and still be pushed, held, detected or
        /// rubbed: the box's largest radius·(1 + contact margin) plus the rounding allowance for the box's and the collider's
        /// magnitudes. It also holds for any smaller box inside this one (a particle of it).
        /// </summary>
        public double Reach(int k, in ParticleBox box, bool sweep)
        {
            double scale = Math.Max(Math.Abs(box.LowX), Math.Abs(box.HighX)) + Math.Max(Math.Abs(box.LowY), Math.Abs(box.HighY))
                         + Math.Max(Math.Abs(box.LowZ), Math.Abs(box.HighZ));
            double r = box.Radius;
            return r * (1.0 + CollisionSet.ContactMarginFraction) + RelativeTolerance * (scale + bounds[Slot(k, sweep) + 6] + r);
        }

        /// <summary>
        /// False only when no point of <paramref name="box"/> comes within <paramref name="reach"/> (m) of collider k's bound
        /// (over the host step when <paramref name="sweep"/>, else in the current substep): the plane's smallest signed distance
        /// over the box's corners, or the overlap of the boxes. NaN anywhere gives true.
        /// </summary>
        public bool Within(int k, in ParticleBox box, double reach, bool sweep)
        {
            if (sweep && unbounded[k]) return true;
            int o = Slot(k, sweep);
            double[] b = bounds;
            double lx = box.LowX, ly = box.LowY, lz = box.LowZ, hx = box.HighX, hy = box.HighY, hz = box.HighZ;
            if (kinds[k] == ColliderKind.Plane)
            {
                double nx = b[o], ny = b[o + 1], nz = b[o + 2];
                double lowest = (nx >= 0.0 ? nx * lx : nx * hx) + (ny >= 0.0 ? ny * ly : ny * hy) + (nz >= 0.0 ? nz * lz : nz * hz) - b[o + 3];
                return !(lowest > reach);
            }
            return !(lx > b[o + 3] + reach || hx < b[o] - reach
                  || ly > b[o + 4] + reach || hy < b[o + 1] - reach
                  || lz > b[o + 5] + reach || hz < b[o + 2] - reach);
        }

        private static int Slot(int k, bool sweep) => (sweep ? k * 2 : k * 2 + 1) * Values;
    }
}
