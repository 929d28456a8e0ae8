using System;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;

namespace HookeRope.Kernels
{
    /// <summary>The ropes the kernel probe steps: the peer comparison's chain and the scenes hashed for bit-identity.</summary>
    internal static class KernelScene
    {
        /// <summary>Host step (s) of every scene: 90 steps are one simulated second.</summary>
        public const float HostStep = 1f / 90f;

        /// <summary>
        /// The peer comparison's chain: 16 segments, 1.6 m, the default rope material, pinned at particle 0 and released
        /// horizontal, so it swings (8 substeps × 1 iteration, defaults otherwise).
        /// </summary>
        public static Rope Chain(ConstraintSolverKind solver, TimeIntegrator integrator, int segments)
        {
            var settings = new RopeSettings
            {
                SegmentCount = segments,
                RestLength = 0.1f * segments,
                Solver = solver,
                Integrator = integrator,
                Substeps = 8,
                Iterations = 1,
            };
            var rope = new Rope(settings, Float3.Zero, new Float3(0.1f * segments, 0f, 0f));
            rope.AddPin(0, Float3.Zero);
            return rope;
        }

        /// <summary>Names of the scenes <see cref="Build"/> knows, in the order the hash command runs them.</summary>
        public static readonly string[] Names =
        {
            "gs-be-chain16", "gs-bdf2-load64", "gs-bilateral-softpin", "gs-plastic-absorber", "gs-drag-wind",
            "exact-bdf2-chain16", "exact-be-load64", "exact-bdf2-swing256", "exact-plastic-neck", "exact-drag-plane", "gs-plane",
            "exact-bilateral-softpin", "exact-goal-lanyard",
        };

        /// <summary>
        /// The simulation a scene steps through <see cref="RopeSimulation.Step"/> (radius model and read-outs included),
        /// or null for the scenes that step their <see cref="Rope"/> alone. <c>exact-goal-lanyard</c> is one lanyard of
        /// issue 18's goal scene (Tools~/Bench/GoalScene.cs, without its mesh): 64 segments at the default settings (exact
        /// chain, BDF2, 8 substeps × 1 iteration) and the default radius model, pinned at both ends 1.8 m apart, sagging.
        /// </summary>
        public static RopeSimulation Simulation(string name)
        {
            if (name != "exact-goal-lanyard") return null;
            var start = new Float3(0f, 2f, 0f);
            var end = new Float3(1.8f, 2f, 0f);
            var simulation = new RopeSimulation(new RopeSettings { SegmentCount = 64 }, start, end, new RadiusSettings());
            simulation.Rope.AddPin(0, start);
            simulation.Rope.AddPin(64, end);
            return simulation;
        }

        /// <summary>
        /// A scene by name (see <see cref="Names"/>), or <c>gs-load:N</c> / <c>exact-load:N</c> / <c>exact-rest:N</c> (the same at its static equilibrium, <see cref="Resting"/>): N segments of 0.1 m hanging
        /// straight down from a pin with an 80 kg load (taut), backward Euler / BDF2, 8 substeps × 1 iteration, for the
        /// instructions per segment-iteration against the segment count.
        /// </summary>
        public static Rope Build(string name)
        {
            int colon = name.IndexOf(':');
            if (colon > 0)
            {
                int segments = int.Parse(name.Substring(colon + 1), System.Globalization.CultureInfo.InvariantCulture);
                bool gs = name.StartsWith("gs-load", StringComparison.Ordinal);
                if (name.StartsWith("exact-rest", StringComparison.Ordinal)) return Resting(ConstraintSolverKind.ExactChain, TimeIntegrator.Bdf2, segments, 8, 1);
                return Hanging(gs ? ConstraintSolverKind.GaussSeidel : ConstraintSolverKind.ExactChain, gs ? TimeIntegrator.BackwardEuler : TimeIntegrator.Bdf2, segments, 8, 1);
            }
            switch (name)
            {
                case "gs-be-chain16": return Chain(ConstraintSolverKind.GaussSeidel, TimeIntegrator.BackwardEuler, 16);
                case "exact-bdf2-chain16": return Chain(ConstraintSolverKind.ExactChain, TimeIntegrator.Bdf2, 16);
                case "gs-bdf2-load64": return Loaded(ConstraintSolverKind.GaussSeidel, TimeIntegrator.Bdf2, 64, 80f);
                case "exact-be-load64": return Loaded(ConstraintSolverKind.ExactChain, TimeIntegrator.BackwardEuler, 64, 80f);
                case "exact-bdf2-swing256": return Chain(ConstraintSolverKind.ExactChain, TimeIntegrator.Bdf2, 256);
                case "gs-bilateral-softpin":
                case "exact-bilateral-softpin":
                {
                    // 2.4 m of rod pinned at both ends 1.73 m apart (the far end softly): it pushes and bows
                    bool gs = name.StartsWith("gs", StringComparison.Ordinal);
                    Rope rope = Chain(gs ? ConstraintSolverKind.GaussSeidel : ConstraintSolverKind.ExactChain, gs ? TimeIntegrator.BackwardEuler : TimeIntegrator.Bdf2, 24);
                    rope.Settings.Tension = TensionModel.Bilateral;
                    rope.AddPin(24, new Float3(1.5f, -0.8f, 0.3f), 1e-4f);
                    return rope;
                }
                case "gs-plastic-absorber":
                case "exact-plastic-neck":
                {
                    bool gs = name.StartsWith("gs", StringComparison.Ordinal);
                    Rope rope = Loaded(gs ? ConstraintSolverKind.GaussSeidel : ConstraintSolverKind.ExactChain, TimeIntegrator.Bdf2, 32, 100f);
                    if (gs) rope.Settings.UseEnergyAbsorber(2000f, 0.5f);
                    else rope.Settings.MaterialModel = MaterialModel.ElasticPlastic;
                    rope.SetLoadState(0, rope.GetPosition(32), new Float3(0f, -6f, 0f));
                    return rope;
                }
                case "gs-drag-wind":
                {
                    Rope rope = Chain(ConstraintSolverKind.GaussSeidel, TimeIntegrator.Bdf2, 32);
                    rope.Settings.ViscousDrag = 0.05f;
                    rope.Settings.DragCoefficient = 1.2f;
                    rope.Settings.Wind = new Float3(0f, 0f, 8f);
                    return rope;
                }
                case "exact-drag-plane":
                case "gs-plane":
                {
                    bool gs = name.StartsWith("gs", StringComparison.Ordinal);
                    Rope rope = Chain(gs ? ConstraintSolverKind.GaussSeidel : ConstraintSolverKind.ExactChain, TimeIntegrator.Bdf2, 48);
                    if (!gs) rope.Settings.DragCoefficient = 1.2f;
                    rope.AddCollider(ColliderShape.Plane(new Float3(0f, -2.5f, 0f), new Float3(0.2f, 1f, 0f).NormalizedOr(new Float3(0f, 1f, 0f)), 0.4f));
                    return rope;
                }
                case "gs-fast-chain16":
                {
                    // gs-be-chain16 with the opt-in fused single-precision kernel (not hashed: a new kernel, not a changed one)
                    Rope rope = Chain(ConstraintSolverKind.GaussSeidel, TimeIntegrator.BackwardEuler, 16);
                    rope.Settings.GaussSeidelKernel = GaussSeidelKernel.FusedSingle;
                    return rope;
                }
                default: throw new ArgumentException("unknown scene " + name + " (known: " + string.Join(", ", Names) + ")", nameof(name));
            }
        }

        /// <summary>A 0.1 m-per-segment rope hanging straight down from a pin with an 80 kg load (the kernel timer's and the load:N scenes' rope).</summary>
        public static Rope Hanging(ConstraintSolverKind solver, TimeIntegrator integrator, int segments, int substeps, int iterations)
        {
            var settings = new RopeSettings
            {
                SegmentCount = segments,
                RestLength = 0.1f * segments,
                Solver = solver,
                Integrator = integrator,
                Substeps = substeps,
                Iterations = iterations,
            };
            var rope = new Rope(settings, Float3.Zero, new Float3(0f, -0.1f * segments, 0f));
            rope.AddPin(0, Float3.Zero);
            rope.AddLoad(segments, 80f);
            return rope;
        }

        /// <summary>
        /// <see cref="Hanging"/> placed at its static equilibrium, at rest: segment j stretched to L·(1 + T_j/(E·A)) by the
        /// tension T_j = g·Σ_{i&gt;j} m_i of the particles (and the load) below it. The fresh <see cref="Hanging"/> rope starts
        /// at its rest length and falls: a tension front runs down from the pin at the axial wave speed √(E·A/μ) (363 m/s
        /// for the default rope: 2.8 s down the 1 km of 10 000 segments), with the chain below it in free fall and
        /// slack, and the exact solve's tension-only active set takes up to its 8 (MaxPasses)
        /// solves per iteration resolving it. This rope has no front: the scene for the kernel cost against the segment count.
        /// </summary>
        public static Rope Resting(ConstraintSolverKind solver, TimeIntegrator integrator, int segments, int substeps, int iterations)
        {
            Rope rope = Hanging(solver, integrator, segments, substeps, iterations);
            double stiffness = rope.Settings.AxialStiffness, g = -rope.Settings.Gravity.Y, below = 0.0, y = 0.0;
            double[] tension = new double[segments];
            for (int j = segments - 1; j >= 0; j--)
            {
                below += rope.GetParticleMass(j + 1);
                tension[j] = g * below;
            }
            for (int j = 0; j < segments; j++)
            {
                y -= rope.RestLengths[j] * (1.0 + tension[j] / stiffness);
                rope.SetPosition(j + 1, new Float3(0f, (float)y, 0f));
            }
            return rope;
        }

        /// <summary>A rope hanging straight down from a pin with a load at its end (segments × 0.1 m).</summary>
        private static Rope Loaded(ConstraintSolverKind solver, TimeIntegrator integrator, int segments, float load)
        {
            var settings = new RopeSettings
            {
                SegmentCount = segments,
                RestLength = 0.1f * segments,
                Solver = solver,
                Integrator = integrator,
            };
            var rope = new Rope(settings, Float3.Zero, new Float3(0.02f * segments, -0.1f * segments, 0f));
            rope.AddPin(0, Float3.Zero);
            rope.AddLoad(segments, load);
            return rope;
        }
    }
}
