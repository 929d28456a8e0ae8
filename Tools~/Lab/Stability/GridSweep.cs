using System;
using System.Collections.Generic;
using System.Threading.Tasks;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Lab.Stability
{
    /// <summary>
    /// Issue 14's stability grid on the core <see cref="Rope"/> (no radius model): E 1 MPa – 200 GPa × mass ratio 1 – 10⁶ ×
    /// host step 1/30 – 1/1000 s × 2 – 256 segments × initial stretch 1 and 10 × both integrators × both tension models ×
    /// with and without a sphere collider (1 296 cases, 1 s each, undamped), plus 10 000 segments (36 cases) and a 1 km
    /// anchor teleport (24 cases, 20 s, damped). Rope: R 5 mm, 1140 kg/m³, 8 substeps × 1 iteration, exact chain; laid 30°
    /// off the vertical, so it swings as well as stretches. Criteria: finite; kinetic + gravitational energy never above the
    /// energy put in by more than round-off; at the end within reach of the anchor (recovered).
    /// </summary>
    public static class GridSweep
    {
        /// <summary>XPBD damping β (s) of the teleport cases: the criterion there is recovery, which needs some damping once the integrator no longer supplies it.</summary>
        public const float RecoveryDamping = 0.05f;

        /// <summary>The cases: the whole grid, or the CI subset (<paramref name="full"/> false: 2 values per axis, 0.5 s, 2 teleports).</summary>
        public static List<GridCase> Cases(bool full)
        {
            var list = new List<GridCase>();
            double[] moduli = full ? new[] { 1e6, 1e9, 2e11 } : new[] { 1e6, 2e11 };
            double[] ratios = full ? new[] { 1.0, 1e3, 1e6 } : new[] { 1.0, 1e6 };
            double[] steps = full ? new[] { 1.0 / 30, 1.0 / 90, 1.0 / 1000 } : new[] { 1.0 / 30, 1.0 / 90 };
            int[] segments = full ? new[] { 2, 16, 256 } : new[] { 2, 16 };
            double[] stretches = { 1.0, 10.0 };
            var integrators = new[] { TimeIntegrator.BackwardEuler, TimeIntegrator.Bdf2 };
            var tensions = new[] { TensionModel.TensionOnly, TensionModel.Bilateral };
            double duration = full ? 1.0 : 0.5;
            foreach (double e in moduli)
                foreach (double ratio in ratios)
                    foreach (double dt in steps)
                        foreach (int n in segments)
                            foreach (double stretch in stretches)
                                foreach (var integrator in integrators)
                                    foreach (var tension in tensions)
                                        foreach (bool collider in new[] { false, true })
                                        {
                                            if (!full && (collider != (n == 16) || tension == TensionModel.Bilateral && stretch > 1)) continue;
                                            list.Add(new GridCase
                                            {
                                                YoungsModulus = e, MassRatio = ratio, HostStep = dt, Segments = n, Stretch = stretch,
                                                Integrator = integrator, Tension = tension, Collider = collider, Duration = duration,
                                            });
                                        }
            if (full)
                foreach (double e in moduli)
                    foreach (double ratio in ratios)
                        foreach (var integrator in integrators)
                            foreach (var tension in tensions)
                                list.Add(new GridCase
                                {
                                    YoungsModulus = e, MassRatio = ratio, HostStep = 1.0 / 90, Segments = 10000, Stretch = 1.0,
                                    Integrator = integrator, Tension = tension, Duration = 0.25,
                                });
            foreach (double e in full ? moduli : new[] { 1e9 })
                foreach (var integrator in integrators)
                    foreach (var tension in full ? tensions : new[] { TensionModel.TensionOnly })
                        foreach (bool collider in full ? new[] { false, true } : new[] { false })
                            list.Add(new GridCase
                            {
                                YoungsModulus = e, MassRatio = 100.0, HostStep = 1.0 / 90, Segments = 16, Stretch = 1.0,
                                Integrator = integrator, Tension = tension, Collider = collider, Teleport = true, Duration = 20.0,
                            });
            return list;
        }

        /// <summary>Runs every case on all cores (each case is deterministic on its own); outcomes in case order.</summary>
        public static GridOutcome[] RunAll(List<GridCase> cases)
        {
            var outcomes = new GridOutcome[cases.Count];
            // the expensive cases first, so the cores finish together
            var order = new int[cases.Count];
            for (int i = 0; i < order.Length; i++) order[i] = i;
            Array.Sort(order, (a, b) => Cost(cases[b]).CompareTo(Cost(cases[a])));
            Parallel.For(0, order.Length, k => outcomes[order[k]] = Run(cases[order[k]]));
            return outcomes;
        }

        private static double Cost(GridCase c) => c.Segments * c.Duration / c.HostStep;

        /// <summary>Builds the rope of a case: pinned at the origin, laid 30° off the vertical at Stretch × L, load at the end.</summary>
        public static Rope Build(GridCase c)
        {
            double length = c.RestLength;
            var settings = new RopeSettings
            {
                RestLength = (float)length,
                SegmentCount = c.Segments,
                Radius = 0.005f,
                YoungsModulus = (float)c.YoungsModulus,
                Density = 1140f,
                Damping = c.Teleport ? RecoveryDamping : 0f,
                Gravity = new Float3(0f, -9.81f, 0f),
                Substeps = 8,
                Iterations = 1,
                Solver = ConstraintSolverKind.ExactChain,
                Tension = c.Tension,
                Integrator = c.Integrator,
            };
            float reach = (float)(length * c.Stretch);
            var end = new Float3(0.5f * reach, -0.8660254f * reach, 0f);
            var rope = new Rope(settings, Float3.Zero, end);
            rope.AddPin(0, Float3.Zero);
            if (c.MassRatio > 0.0)
            {
                float particle = settings.LinearDensity * (float)length / c.Segments;
                rope.AddLoad(rope.ParticleCount - 1, (float)(particle * c.MassRatio));
            }
            // on the vertical below the anchor, where the swinging rope comes to hang: it wraps the sphere
            if (c.Collider) rope.AddCollider(ColliderShape.Sphere(new Float3(0f, -0.6f * (float)length, 0f), 0.1f * (float)length, 0.3f));
            return rope;
        }

        /// <summary>Runs one case.</summary>
        public static GridOutcome Run(GridCase c)
        {
            Rope rope = Build(c);
            float dt = (float)c.HostStep;
            int steps = (int)Math.Ceiling(c.Duration / c.HostStep);
            int teleportStep = c.Teleport ? (int)Math.Ceiling(0.5 / c.HostStep) : -1;
            var o = new GridOutcome { Case = c, Finite = true, Ceiling = rope.TotalEnergy() };
            for (int s = 0; s < steps; s++)
            {
                if (s == teleportStep) rope.SetPinTarget(0, new Float3(1000f, 0f, 0f));
                rope.Step(dt);
                double motion = rope.KineticEnergy() + rope.GravitationalEnergy();
                if (s == teleportStep) o.Ceiling = Math.Max(o.Ceiling, rope.TotalEnergy());
                if (!double.IsFinite(motion) || !AllFinite(rope)) { o.Finite = false; break; }
                o.EnergyGain = Math.Max(o.EnergyGain, motion - o.Ceiling);
            }
            Float3 anchor = rope.GetPinTarget(0);
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                o.Reach = Math.Max(o.Reach, (rope.GetPosition(i) - anchor).Length);
                o.FinalSpeed = Math.Max(o.FinalSpeed, rope.GetVelocity(i).Length);
            }
            o.ReachBound = 1.1 * Math.Max(c.RestLength * c.Stretch, c.RestLength + 2.0 * StaticElongation(rope, c));
            return o;
        }

        /// <summary>Static elongation (M + m/2)·g·L/(E·A) of the case's rope, m.</summary>
        private static double StaticElongation(Rope rope, GridCase c)
        {
            RopeSettings s = rope.Settings;
            double ropeMass = s.LinearDensity * c.RestLength;
            double load = 0.0;
            for (int l = 0; l < rope.LoadCount; l++) load += rope.GetParticleMass(rope.GetLoadParticle(l)) - ropeMass / (2.0 * c.Segments);
            return (load + ropeMass / 2.0) * 9.81 * c.RestLength / s.AxialStiffness;
        }

        private static bool AllFinite(Rope rope)
        {
            for (int i = 0; i < rope.ParticleCount; i++)
                if (!float.IsFinite(rope.PositionX[i]) || !float.IsFinite(rope.PositionY[i]) || !float.IsFinite(rope.PositionZ[i]) || !rope.GetVelocity(i).IsFinite) return false;
            for (int j = 0; j < rope.SegmentCount; j++) if (!float.IsFinite(rope.Tensions[j])) return false;
            return true;
        }
    }
}
