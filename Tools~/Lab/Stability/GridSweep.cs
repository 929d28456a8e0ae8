using System;
using System.Collections.Generic;
using System.Threading.Tasks;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Lab.Stability
{
    /// <summary>
    /// Issue 14's stability grid on the core <see cref="Rope"/> (no radius model). Rope: R 5 mm, 1140 kg/m³, 8 substeps × 1
    /// iteration, exact chain, pinned at the origin and laid 30° off the vertical, so it swings as well as stretches.
    /// <list type="bullet">
    /// <item>Undamped: E 1 MPa – 200 GPa × mass ratio 1 – 10⁶ × host step 1/30 – 1/1000 s × 2 – 256 segments × initial
    /// stretch 1 and 10 × both integrators × both tension models × with and without a frictionless sphere (1 296 cases,
    /// 1 s each), plus 10 000 segments (36 cases, 0.25 s).</item>
    /// <item>Friction: the sphere with Coulomb friction μ 0.3, 16 segments at rest length, E × ratio × host step × both
    /// integrators × both tension models (108 cases, 1 s).</item>
    /// <item>Settle (damped): E × mass ratio × 2 – 256 segments × both integrators × both tension models × with and without
    /// the collider at 1/90 s, laid at rest length, and at 10× stretch with 16 segments (288 cases), with the drag and
    /// damping of <see cref="Damp"/> for 25 time constants of the slowest mode.</item>
    /// <item>Teleport: the anchor jumps 1 km after 0.5 s, the rope's own drag c 0.5 N·s/m² + C_d 1.2, β 0.05 s (24 cases,
    /// 40 s).</item>
    /// </list>
    /// Criteria (<see cref="GridOutcome"/>): finite; the total energy (kinetic + gravitational + elastic, the elastic part
    /// the least any state within the solve's round-off stores) never above the energy put in by more than the float32
    /// round-off bound accumulated so far (<see cref="GridOutcome.RoundOffPerSubstep"/>); at the end within reach of the
    /// anchor; a damped case at rest at the end (kinetic energy below 1e-6 of the energy it dissipated); a teleported
    /// rope's load back near its hanging point. A failing case is counted under a documented domain limit
    /// (<see cref="GridLimits"/>) or as an undocumented failure.
    /// </summary>
    public static class GridSweep
    {
        /// <summary>XPBD damping β (s) of the damped cases (settle and teleport).</summary>
        public const float RecoveryDamping = 0.05f;

        /// <summary>Coulomb friction coefficient μ of the sphere in the <see cref="GridFamily.Friction"/> cases (elsewhere the sphere is frictionless).</summary>
        public const float SphereFriction = 0.3f;

        /// <summary>
        /// The rope's own viscous drag c (N·s/m²) in the teleport cases: what brings a rope dragged 1 km back to rest under
        /// its new anchor (the rope's drag acts per metre of rope, on the load only through the rope).
        /// </summary>
        public const float TeleportViscousDrag = 0.5f;

        /// <summary>The rope's own quadratic air drag coefficient C_d in the teleport cases (air 1.2 kg/m³).</summary>
        public const float TeleportDragCoefficient = 1.2f;

        /// <summary>Simulated time of a teleport case, s: the anchor jumps at 0.5 s.</summary>
        public const double TeleportDuration = 40.0;

        /// <summary>
        /// Where the load of a teleport case must be at the end (39.5 s after the jump), m: within 0.1·L + the static
        /// elongation of its hanging point L + static elongation below the anchor.
        /// </summary>
        public const double HangingTolerance = 0.1;

        /// <summary>Time constants of the slowest mode a settle case runs for: its energy falls as exp(−k·t), e⁻²⁵ ≈ 10⁻¹¹.</summary>
        public const double SettleTimeConstants = 25.0;

        /// <summary>The cases: the whole grid, or the CI subset (<paramref name="full"/> false: 2 values per axis, 0.5 s, 96 undamped, 8 friction, 8 settle, 2 teleport cases: 114).</summary>
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
            var colliders = new[] { false, true };
            double duration = full ? 1.0 : 0.5;
            foreach (double e in moduli)
                foreach (double ratio in ratios)
                    foreach (double dt in steps)
                        foreach (int n in segments)
                            foreach (double stretch in stretches)
                                foreach (var integrator in integrators)
                                    foreach (var tension in tensions)
                                        foreach (bool collider in colliders)
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
            // the collider with Coulomb friction: E × mass ratio × host step × both integrators × both tension models, 16
            // segments laid at rest length (the CI subset: 1/90 s, the extreme E and ratios)
            foreach (double e in moduli)
                foreach (double ratio in ratios)
                    foreach (double dt in full ? steps : new[] { 1.0 / 90 })
                        foreach (var integrator in integrators)
                            foreach (var tension in tensions)
                            {
                                if (!full && tension == TensionModel.Bilateral) continue;
                                list.Add(new GridCase
                                {
                                    YoungsModulus = e, MassRatio = ratio, HostStep = dt, Segments = 16, Stretch = 1.0,
                                    Integrator = integrator, Tension = tension, Collider = true, Friction = SphereFriction,
                                    Family = GridFamily.Friction, Duration = duration,
                                });
                            }
            foreach (double e in moduli)
                foreach (double ratio in ratios)
                    foreach (int n in full ? segments : new[] { 16 })
                        foreach (double stretch in stretches)
                            foreach (var integrator in integrators)
                                foreach (var tension in full ? tensions : new[] { TensionModel.TensionOnly })
                                    foreach (bool collider in full ? colliders : new[] { false })
                                    {
                                        if (stretch > 1.0 && n != 16 || !full && stretch > 1.0) continue;
                                        var c = new GridCase
                                        {
                                            YoungsModulus = e, MassRatio = ratio, HostStep = 1.0 / 90, Segments = n, Stretch = stretch,
                                            Integrator = integrator, Tension = tension, Collider = collider, Family = GridFamily.Settle,
                                        };
                                        Damp(c);
                                        c.Duration = SettleTimeConstants / c.Drag;
                                        list.Add(c);
                                    }
            foreach (double e in full ? moduli : new[] { 1e9 })
                foreach (var integrator in integrators)
                    foreach (var tension in full ? tensions : new[] { TensionModel.TensionOnly })
                        foreach (bool collider in full ? colliders : new[] { false })
                        {
                            var c = new GridCase
                            {
                                YoungsModulus = e, MassRatio = 100.0, HostStep = 1.0 / 90, Segments = 16, Stretch = 1.0,
                                Integrator = integrator, Tension = tension, Collider = collider, Family = GridFamily.Teleport, Duration = TeleportDuration,
                                ViscousDrag = TeleportViscousDrag, DragCoefficient = TeleportDragCoefficient, Damping = RecoveryDamping,
                            };
                            list.Add(c);
                        }
            return list;
        }

        /// <summary>
        /// The damping of a settle or teleport case: β = <see cref="RecoveryDamping"/> and the linear drag rate k (1/s) equal
        /// to the lowest angular frequency of the case, ω = min(√(g/ℓ), √(E·A/(L·(M + m/3)))): the pendulum of the hanging
        /// length ℓ = L + static elongation, and the load on the rope's axial spring (m: the rope's mass). Every mode with
        /// ω ≥ k/2 is then underdamped and its energy falls as exp(−k·t) (the slowest, ζ = ½); the estimate is below the
        /// true lowest frequency of a hanging chain (1.2·√(g/L) unloaded), so no mode is overdamped.
        /// </summary>
        public static void Damp(GridCase c)
        {
            double area = Math.PI * 0.005 * 0.005, linearDensity = 1140.0 * area, length = c.RestLength;
            double rope = linearDensity * length, load = c.MassRatio * rope / c.Segments;
            double stiffness = c.YoungsModulus * area;
            double elongation = (load + rope / 2.0) * 9.81 * length / stiffness;
            double pendulum = Math.Sqrt(9.81 / (length + elongation));
            double axial = Math.Sqrt(stiffness / (length * (load + rope / 3.0)));
            c.Drag = Math.Min(pendulum, axial);
            c.Damping = RecoveryDamping;
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
                Damping = c.Damping,
                ViscousDrag = c.ViscousDrag,
                DragCoefficient = c.DragCoefficient,
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
            if (c.Collider) rope.AddCollider(ColliderShape.Sphere(new Float3(0f, -0.6f * (float)length, 0f), 0.1f * (float)length, c.Friction));
            return rope;
        }

        /// <summary>Runs one case.</summary>
        public static GridOutcome Run(GridCase c)
        {
            Rope rope = Build(c);
            float dt = (float)c.HostStep;
            int steps = (int)Math.Ceiling(c.Duration / c.HostStep);
            int teleportStep = c.Teleport ? (int)Math.Ceiling(0.5 / c.HostStep) : -1;
            float decay = (float)Math.Exp(-c.Drag * dt);
            var o = new GridOutcome { Case = c, Finite = true, Ceiling = Energy(rope, upper: true) };
            double motion = 0.0, total = 0.0;
            for (int s = 0; s < steps; s++)
            {
                if (s == teleportStep) rope.SetPinTarget(0, new Float3(1000f, 0f, 0f));
                StepReport report = rope.Step(dt);
                o.Substeps += report.Substeps;
                o.SolveIterations += report.SolveIterations;
                o.ViolentSubsteps += report.ViolentSubsteps;
                o.ShortenedSteps += report.ShortenedSteps;
                o.UnconvergedSubsteps += report.UnconvergedSubsteps;
                if (c.Drag > 0.0) Drag(rope, decay);
                for (int j = 0; j < rope.SegmentCount; j++) o.LargestPush = Math.Max(o.LargestPush, -rope.Tensions[j]);
                motion = rope.KineticEnergy() + rope.GravitationalEnergy();
                if (!double.IsFinite(motion) || !AllFinite(rope)) { o.Finite = false; break; }
                if (s == teleportStep) o.Ceiling = Math.Max(o.Ceiling, Energy(rope, upper: true));
                rope.ElasticEnergyBounds(out double lower, out double upper);
                total = motion + lower;
                o.RoundOff += report.Substeps * GridOutcome.RoundOffPerSubstep * (rope.KineticEnergy() + Math.Abs(rope.GravitationalEnergy()) + upper);
                o.EnergyGain = Math.Max(o.EnergyGain, total - o.Ceiling);
                o.Excess = Math.Max(o.Excess, total - o.Ceiling - o.RoundOff);
                o.MotionGain = Math.Max(o.MotionGain, motion - o.Ceiling);
            }
            Float3 anchor = rope.GetPinTarget(0);
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                o.Reach = Math.Max(o.Reach, (rope.GetPosition(i) - anchor).Length);
                o.FinalSpeed = Math.Max(o.FinalSpeed, rope.GetVelocity(i).Length);
            }
            o.FinalKinetic = rope.KineticEnergy();
            if (c.Teleport)
            {
                double elongation = StaticElongation(rope, c);
                Float3 load = rope.GetPosition(rope.ParticleCount - 1);
                var hanging = new Float3(anchor.X, anchor.Y - (float)(c.RestLength + elongation), anchor.Z);
                o.HangingOffset = (load - hanging).Length;
                o.HangingBound = HangingTolerance * c.RestLength + elongation;
            }
            o.Dissipated = o.Ceiling - total;
            o.ReachBound = 1.1 * Math.Max(c.RestLength * c.Stretch, c.RestLength + 2.0 * StaticElongation(rope, c));
            return o;
        }

        /// <summary>Total energy (J): kinetic + gravitational + the lower (or upper) bound of the elastic energy within round-off.</summary>
        public static double Energy(Rope rope, bool upper)
        {
            rope.ElasticEnergyBounds(out double lower, out double higher);
            return rope.KineticEnergy() + rope.GravitationalEnergy() + (upper ? higher : lower);
        }

        /// <summary>
        /// The drag of a damped case, applied after each host step: every free particle's velocity times exp(−k·Δt)
        /// (<paramref name="decay"/>), the exact solution of v̇ = −k·v over the step (a force −k·m·v on the rope and its load
        /// alike, mass-proportional or Rayleigh damping). It only takes kinetic energy out, at any k. Particle 0 is pinned.
        /// The rope's own drag (issue 15) acts per metre of rope, not on the load; this stand-in damps every mode of the case
        /// at one known rate, which is what the settle criterion needs.
        /// </summary>
        public static void Drag(Rope rope, float decay)
        {
            for (int i = 1; i < rope.ParticleCount; i++) rope.SetVelocity(i, rope.GetVelocity(i) * decay);
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
