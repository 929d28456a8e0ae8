using System;
using System.Collections.Generic;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Capstan scenes (issue 15 item 3): a light rope wrapped by θ around a fixed collider with friction μ (a cylinder:
    /// a capsule along Z; or the edges of a box), a load m1 hanging from its heavy end and m2 from its light end. Where θ
    /// needs it, the light side is turned down by a frictionless cylinder so that both loads hang. The rope starts at
    /// rest, laid along its path at rest length. Capstan: the wrap holds while m1/m2 ≤ e^{μθ}; above, with a massless
    /// rope, the loads accelerate at a = g (m1 − m2 e^{μθ}) / (m1 + m2 e^{μθ}).
    /// </summary>
    internal static class CapstanScenes
    {
        public enum Shape { Cylinder, BoxEdges }

        /// <summary>Radius of the friction cylinder and the redirect cylinder, half side of the box (m).</summary>
        public const float Size = 0.1f;
        /// <summary>
        /// Rope radius and segment length (m) over the cylinder and over the box. Over a box the rope's centreline turns
        /// round each edge on a circle of the rope's radius; that turn must be resolved by a few particles (segments well
        /// under the radius), or two particles on the faces either side of an edge lock the rope like a lever whatever μ.
        /// </summary>
        public const float RopeRadius = 0.005f, BoxRopeRadius = 0.02f;
        /// <summary>Light load (kg); the heavy one is ratio × this.</summary>
        public const float LightLoad = 1f;
        /// <summary>Rope mass per metre (kg/m): 1.5 g in all, 0.15 % of the light load.</summary>
        public const float LinearDensity = 0.001f;
        /// <summary>Length (m) each load hangs below the wrap.</summary>
        public const float Drop = 0.5f;
        public const float SegmentLength = 0.01f, BoxSegmentLength = 0.0025f;

        /// <summary>The scene; <paramref name="heavy"/> and <paramref name="light"/> are the loads' indices (heavy: particle 0).</summary>
        public static Rope Build(Shape shape, double theta, float mu, double ratio, out int heavy, out int light)
        {
            var path = new Path(new Float3(0f, 0f, 0f));
            bool box = shape == Shape.BoxEdges;
            float r = box ? BoxRopeRadius : RopeRadius;
            float rc = Size + r;          // the rope's centreline around the cylinder
            float a = Size, e = Size + r; // the box's half side and the centreline's offset from its faces
            var colliders = new List<ColliderShape>();
            Quat alongZ = Quat.FromAxisAngle(new Float3(1f, 0f, 0f), MathF.PI / 2f);
            bool quarter = Math.Abs(theta - Math.PI / 2) < 1e-6, half = Math.Abs(theta - Math.PI) < 1e-6, full = Math.Abs(theta - 2 * Math.PI) < 1e-6;
            if (!quarter && !half && !full) throw new ArgumentOutOfRangeException(nameof(theta), theta, "theta must be π/2, π or 2π");
            if (shape == Shape.Cylinder)
            {
                colliders.Add(ColliderShape.Capsule(Float3.Zero, alongZ, Size, 0.5f, mu));
                path.Start(new Float3(rc, -Drop, 0f));
                path.LineTo(new Float3(rc, 0f, 0f));
                path.Arc(Float3.Zero, rc, 0.0, theta);
            }
            else
            {
                colliders.Add(ColliderShape.Box(Float3.Zero, Quat.Identity, new Float3(a, a, 0.5f), mu));
                path.Start(new Float3(e, -a - Drop, 0f));
                path.LineTo(new Float3(e, a, 0f));
                path.Arc(new Float3(a, a, 0f), r, 0.0, Math.PI / 2);
                if (!quarter)
                {
                    path.LineTo(new Float3(-a, e, 0f));
                    path.Arc(new Float3(-a, a, 0f), r, Math.PI / 2, Math.PI);
                }
                if (full)
                {
                    path.LineTo(new Float3(-e, -a, 0f));
                    path.Arc(new Float3(-a, -a, 0f), r, Math.PI, 1.5 * Math.PI);
                    path.LineTo(new Float3(a, -e, 0f));
                    path.Arc(new Float3(a, -a, 0f), r, 1.5 * Math.PI, 2 * Math.PI);
                }
            }
            // the light side: hangs down (π), or is turned down by the frictionless cylinder
            Float3 end = path.End;
            if (quarter)
            {
                // heading −X at the top: over the redirect cylinder's top, a quarter turn down its far side
                float cx = end.X - 0.4f, cy = end.Y - rc;
                colliders.Add(ColliderShape.Capsule(new Float3(cx, cy, 0f), alongZ, Size, 0.5f, 0f));
                path.LineTo(new Float3(cx, end.Y, 0f));
                path.Arc(new Float3(cx, cy, 0f), rc, Math.PI / 2, Math.PI);
                end = path.End;
            }
            else if (full)
            {
                // heading +Y on the right: up to the redirect cylinder above, half a turn over it
                float cx = end.X + rc, cy = 0.35f;
                colliders.Add(ColliderShape.Capsule(new Float3(cx, cy, 0f), alongZ, Size, 0.5f, 0f));
                path.LineTo(new Float3(end.X, cy, 0f));
                path.Arc(new Float3(cx, cy, 0f), rc, Math.PI, 0.0);
                end = path.End;
            }
            path.LineTo(new Float3(end.X, shape == Shape.Cylinder ? -Drop : -a - Drop, 0f));

            int segments = Math.Max(8, (int)Math.Round(path.Length / (box ? BoxSegmentLength : SegmentLength)));
            var settings = RopeTestKit.Legacy(length: (float)path.Length, segments: segments, radius: r);
            settings.LinearDensity = LinearDensity;
            settings.AxialStiffness = 2e4f;
            var rope = new Rope(settings, path.At(0.0), path.At(path.Length));
            for (int i = 0; i < rope.ParticleCount; i++) rope.SetPosition(i, path.At(path.Length * i / segments));
            foreach (var c in colliders) rope.AddCollider(c);
            heavy = rope.AddLoad(0, LightLoad);
            light = rope.AddLoad(rope.ParticleCount - 1, LightLoad);
            return rope;
        }

        /// <summary>Host steps (1/90 s) the rope settles with equal loads before the heavy one gets the rest of its mass.</summary>
        public const int SettleSteps = 45;
        /// <summary>Host steps (1/90 s) over which the heavy load grows to its mass after the settling, in equal parts.</summary>
        public const int RampSteps = 45;
        /// <summary>Host steps (1/90 s) measured after that: 2 s.</summary>
        public const int MeasureSteps = 180;
        /// <summary>The acceleration is fitted over the measured time from this on (s): the first part carries the load step's transient.</summary>
        public const double FitFrom = 0.5;

        /// <summary>What one capstan run measured: the heavy load's slide (m, downwards) after 2 s, its fitted acceleration (m/s²), the largest total-energy gain (J) after the load step, and whether every value stayed finite.</summary>
        public struct Result
        {
            public double Slide, Acceleration, EnergyGain;
            public bool Finite;
        }

        /// <summary>
        /// Builds the scene, lets the rope settle for <see cref="SettleSteps"/> with both loads m2 (balanced: it holds at
        /// any μ), adds (ratio − 1)·m2 to the heavy end over <see cref="RampSteps"/>, then steps 2 s: the slide of the
        /// heavy load, its acceleration (least-squares parabola over t ≥ <see cref="FitFrom"/>) and the largest gain of the
        /// total energy over its value at the start of those 2 s.
        /// </summary>
        public static Result Run(Shape shape, double theta, float mu, double ratio)
        {
            var rope = Build(shape, theta, mu, ratio, out int heavy, out _);
            for (int k = 0; k < SettleSteps; k++) rope.Step(RopeTestKit.HostStep);
            int p = rope.GetLoadParticle(heavy);
            // the rest of the heavy load comes on over RampSteps (a sudden step would overshoot the static tension and slip)
            for (int k = 0; k < RampSteps; k++)
            {
                if (ratio > 1.0) rope.AddLoad(p, (float)((ratio - 1.0) * LightLoad / RampSteps));
                rope.Step(RopeTestKit.HostStep);
            }
            double y0 = rope.GetPosition(p).Y;
            double e0 = rope.TotalEnergy();
            var result = new Result { Finite = true, EnergyGain = double.NegativeInfinity };
            // normal equations of y = c0 + c1 t + c2 t²
            double s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, b0 = 0, b1 = 0, b2 = 0;
            for (int k = 0; k < MeasureSteps; k++)
            {
                rope.Step(RopeTestKit.HostStep);
                double t = (k + 1) * (double)RopeTestKit.HostStep;
                double y = y0 - rope.GetPosition(p).Y;
                double e = rope.TotalEnergy() - e0;
                if (!double.IsFinite(y) || !double.IsFinite(e)) { result.Finite = false; break; }
                result.EnergyGain = Math.Max(result.EnergyGain, e);
                result.Slide = y;
                if (t < FitFrom) continue;
                s0 += 1; s1 += t; s2 += t * t; s3 += t * t * t; s4 += t * t * t * t;
                b0 += y; b1 += t * y; b2 += t * t * y;
            }
            // Cramer's rule for c2
            double det = s0 * (s2 * s4 - s3 * s3) - s1 * (s1 * s4 - s3 * s2) + s2 * (s1 * s3 - s2 * s2);
            double det2 = s0 * (s2 * b2 - b1 * s3) - s1 * (s1 * b2 - b1 * s2) + b0 * (s1 * s3 - s2 * s2);
            result.Acceleration = 2.0 * det2 / det;
            return result;
        }

        /// <summary>Capstan acceleration (m/s², the heavy load's, downwards) of a massless rope: g (m1 − m2 e^{μθ}) / (m1 + m2 e^{μθ}).</summary>
        public static double Acceleration(double theta, double mu, double ratio)
        {
            double grip = Math.Exp(mu * theta);
            return RopeTestKit.G * (ratio - grip) / (ratio + grip);
        }

        /// <summary>A path of lines and arcs in the XY plane, sampled by arc length.</summary>
        private sealed class Path
        {
            private readonly List<Float3> points = new List<Float3>();
            private readonly List<double> at = new List<double>();

            public Path(Float3 start) { }

            public double Length => at.Count == 0 ? 0.0 : at[at.Count - 1];
            public Float3 End => points[points.Count - 1];

            public void Start(Float3 p) { points.Clear(); at.Clear(); points.Add(p); at.Add(0.0); }

            public void LineTo(Float3 p)
            {
                double d = (p - End).Length;
                if (d < 1e-9) return;
                at.Add(Length + d);
                points.Add(p);
            }

            /// <summary>An arc around centre (radius ρ) from angle a0 to a1 (rad, counter-clockwise when a1 &gt; a0).</summary>
            public void Arc(Float3 centre, float radius, double a0, double a1)
            {
                int n = Math.Max(4, (int)(Math.Abs(a1 - a0) * 64));
                for (int k = 0; k <= n; k++)
                {
                    double t = a0 + (a1 - a0) * k / n;
                    LineTo(centre + new Float3((float)(radius * Math.Cos(t)), (float)(radius * Math.Sin(t)), 0f));
                }
            }

            public Float3 At(double s)
            {
                if (s <= 0.0) return points[0];
                for (int k = 1; k < points.Count; k++)
                {
                    if (s <= at[k] || k == points.Count - 1)
                    {
                        double f = Math.Min(1.0, (s - at[k - 1]) / (at[k] - at[k - 1]));
                        return Float3.Lerp(points[k - 1], points[k], (float)f);
                    }
                }
                return End;
            }
        }
    }
}
