using System;
using System.Collections.Generic;
using System.Diagnostics;
using HookeRope.Geometry;
using HookeRope.Lab.Report;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using HookeRope.Lab.Stability;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Lab.Bench
{
    /// <summary>One size of the scaling benchmark.</summary>
    public sealed class SizeResult
    {
        /// <summary>Segments.</summary>
        public int Segments;
        /// <summary>Gauss–Seidel: marginal ns per constraint projection (per-step work excluded).</summary>
        public double NsPerProjection;
        /// <summary>Exact chain: marginal ns per segment and iteration (per-step work excluded).</summary>
        public double NsPerSegmentIteration;
        /// <summary>Exact chain: µs per host step (4 substeps × 1 iteration).</summary>
        public double MicrosecondsPerStep;
        /// <summary>Tube mesh: ns per vertex.</summary>
        public double NsPerVertex;
        /// <summary>Managed bytes allocated per host step (exact chain, radius model on).</summary>
        public double BytesPerStep;
    }

    /// <summary>Cost of one optional feature at a fixed size.</summary>
    public sealed class FeatureResult
    {
        /// <summary>Feature and state.</summary>
        public string Name;
        /// <summary>µs per host step.</summary>
        public double MicrosecondsPerStep;
    }

    /// <summary>Stopwatch micro-benchmarks of the core: solver, radius model and tube mesh.</summary>
    public static class MicroBench
    {
        /// <summary>Segment counts measured.</summary>
        public static int[] Sizes(bool quick) => quick ? new[] { 16, 256, 1024 } : new[] { 16, 64, 256, 1024, 4096, 10000 };

        static Scenario Hanging(int segments, SolverMethod method, int substeps, int iterations)
        {
            var s = StabilitySweep.Base(SolverMethod.ExactChain, 1.0);
            s.Rope.Segments = segments;
            s.Solver.Method = method;
            s.Solver.Substeps = substeps;
            s.Solver.Iterations = iterations;
            return s;
        }

        /// <summary>Median wall time in ns of <paramref name="steps"/> calls of <paramref name="step"/> over 5 repeats (after a warm-up).</summary>
        static double TimeNs(Action step, int steps)
        {
            // Warm-up long enough for tiered JIT to install optimised code (≥ 0.25 s or 20 000 calls).
            var warm = Stopwatch.StartNew();
            for (int i = 0; i < 20000 && warm.ElapsedMilliseconds < 250; i++) step();
            var samples = new List<double>();
            for (int r = 0; r < 5; r++)
            {
                var watch = Stopwatch.StartNew();
                for (int i = 0; i < steps; i++) step();
                samples.Add(watch.Elapsed.TotalMilliseconds * 1e6 / steps);
            }
            return Stats.Median(samples);
        }

        static int StepsFor(int segments, int work, bool quick) =>
            Math.Max(20, (int)((quick ? 2e5 : 2e6) / ((double)segments * work)));

        /// <summary>
        /// Measures every size. Per-projection and per-segment-iteration costs are marginal: the
        /// difference between steps with many and few iterations (1 substep) divided by the extra
        /// projections, so the per-step work (prediction, velocities, tensions, residual) is not
        /// counted in them; it is reported separately as µs per step at 4 substeps × 1 iteration.
        /// </summary>
        public static List<SizeResult> Scaling(bool quick, Action<string> progress)
        {
            var list = new List<SizeResult>();
            float dt = 1f / 90f;
            const int few = 2, many = 10;
            foreach (int n in Sizes(quick))
            {
                var result = new SizeResult { Segments = n };
                result.NsPerProjection = MarginalNsPerSegmentIteration(n, SolverMethod.GaussSeidel, few, many, dt, quick);
                result.NsPerSegmentIteration = MarginalNsPerSegmentIteration(n, SolverMethod.ExactChain, few, many, dt, quick);

                var exactSetup = ScenarioRunner.Build(Hanging(n, SolverMethod.ExactChain, 4, 1), true);
                var exact = exactSetup.Rope;
                double stepNs = TimeNs(() => exact.Step(dt), StepsFor(n, 4, quick));
                result.MicrosecondsPerStep = stepNs / 1000;

                result.BytesPerStep = BytesPerStep(exactSetup, dt, 200);

                // the real pipeline: RopeSimulation.FillMesh (ring radii from the model, 8 sides from the scenario). A fill
                // of unchanged input is skipped, so two poses and two radius scales alternate: every timed fill rebuilds all.
                var sim = exactSetup.Simulation;
                var rope = sim.Rope;
                int particles = rope.ParticleCount;
                var poses = new float[2][][];
                for (int p = 0; p < 2; p++)
                {
                    poses[p] = new[] { rope.PositionX.ToArray(), rope.PositionY.ToArray(), rope.PositionZ.ToArray() };
                    for (int i = 0; i < particles; i++) poses[p][2][i] += 1e-4f * p * MathF.Sin(0.3f * i);
                }
                var vertices = new TubeVertex[2 * sim.GetVertexCount()];
                var indices = new int[2 * sim.GetIndexCount()];
                int count = sim.FillMesh(poses[0][0], poses[0][1], poses[0][2], vertices, indices).VertexCount;
                int fill = 0;
                double meshNs = TimeNs(() =>
                    {
                        int p = fill++ & 1;
                        count = sim.FillMesh(poses[p][0], poses[p][1], poses[p][2], vertices, indices, p == 0 ? 1f : 0.999f).VertexCount;
                    },
                    Math.Max(20, (int)((quick ? 2e5 : 2e6) / Math.Max(count, 1))));
                result.NsPerVertex = meshNs / Math.Max(count, 1);
                list.Add(result);
                progress?.Invoke(n + " segments");
            }
            return list;
        }

        /// <summary>ns per segment and iteration: (T(many) − T(few)) / (segments · (many − few)), one substep, medians.</summary>
        static double MarginalNsPerSegmentIteration(int n, SolverMethod method, int few, int many, float dt, bool quick)
        {
            var small = ScenarioRunner.Build(Hanging(n, method, 1, few), false).Rope;
            var large = ScenarioRunner.Build(Hanging(n, method, 1, many), false).Rope;
            int steps = StepsFor(n, many, quick);
            double tSmall = TimeNs(() => small.Step(dt), steps);
            double tLarge = TimeNs(() => large.Step(dt), steps);
            return Math.Max(0.0, tLarge - tSmall) / ((double)n * (many - few));
        }

        /// <summary>Managed bytes allocated per host step (solver + radius glue), after a warm-up.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveOptimization)]
        static double BytesPerStep(RopeSetup setup, float dt, int steps)
        {
            // Fully optimised at once: a tier-0 loop would allocate for on-stack replacement.
            for (int i = 0; i < 20; i++) setup.Step(dt);
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < steps; i++) setup.Step(dt);
            return (GC.GetAllocatedBytesForCurrentThread() - before) / (double)steps;
        }

        /// <summary>Fitted exponent p of time per step ∝ segments^p (exact chain).</summary>
        public static double ScalingExponent(List<SizeResult> sizes)
        {
            var x = new List<double>();
            var y = new List<double>();
            foreach (var s in sizes)
            {
                x.Add(s.Segments);
                y.Add(s.MicrosecondsPerStep);
            }
            return Stats.LogLogSlope(x, y);
        }

        /// <summary>
        /// Cost per host step of each optional feature, on and off, at 256 segments. The configurations
        /// are timed in turn, round after round, and each reports its median over the rounds, so that
        /// a slow spell of a shared machine hits every row alike.
        /// </summary>
        public static List<FeatureResult> Features(bool quick)
        {
            const int n = 256;
            float dt = 1f / 90f;
            int steps = quick ? 50 : 300;
            int rounds = quick ? 3 : 9;
            var names = new List<string>();
            var actions = new List<Action>();

            var baseline = ScenarioRunner.Build(Hanging(n, SolverMethod.ExactChain, 4, 1), false);
            names.Add("baseline: exact chain, 4 substeps, nothing optional");
            actions.Add(() => baseline.Rope.Step(dt));

            var collider = ScenarioRunner.Build(Hanging(n, SolverMethod.ExactChain, 4, 1), false);
            collider.Rope.AddCollider(ColliderShape.Plane(new Float3(0f, -100f, 0f), new Float3(0f, 1f, 0f)));
            names.Add("collisions on (one plane, never touched)");
            actions.Add(() => collider.Rope.Step(dt));

            var farColliders = ScenarioRunner.Build(Hanging(n, SolverMethod.ExactChain, 4, 1), false);
            farColliders.Rope.AddCollider(ColliderShape.Plane(new Float3(0f, -100f, 0f), new Float3(0f, 1f, 0f)));
            for (int k = 0; k < 9; k++)
                farColliders.Rope.AddCollider(ColliderShape.Sphere(new Float3(20f * MathF.Cos(0.7f * k), -5f, 20f * MathF.Sin(0.7f * k)), 1f));
            names.Add("collisions on (ten colliders out of reach: a plane, nine spheres)");
            actions.Add(() => farColliders.Rope.Step(dt));

            var radiusOff = ScenarioRunner.Build(Hanging(n, SolverMethod.ExactChain, 4, 1), true);
            radiusOff.Simulation.RadiusSettings.PoissonThinning = false;
            radiusOff.Simulation.RadiusSettings.Necking = false;
            radiusOff.Simulation.RadiusSettings.Fracture = false;
            names.Add("radius model present, all parts off");
            actions.Add(() => radiusOff.Step(dt));

            var poisson = ScenarioRunner.Build(Hanging(n, SolverMethod.ExactChain, 4, 1), true);
            poisson.Simulation.RadiusSettings.Necking = false;
            poisson.Simulation.RadiusSettings.Fracture = true;
            names.Add("radius on (Poisson thinning + break test)");
            actions.Add(() => poisson.Step(dt));

            var necking = ScenarioRunner.Build(Hanging(n, SolverMethod.ExactChain, 4, 1), true);
            necking.Simulation.RadiusSettings.NeckMode = HookeRope.Radius.NeckMode.Zone;
            necking.Simulation.RadiusSettings.Necking = true;
            necking.Simulation.RadiusSettings.NeckRadiusFraction = 0.999f;
            necking.Simulation.RadiusSettings.Fracture = true;
            names.Add("radius + necking (zone neck active)");
            actions.Add(() => necking.Step(dt));

            var meshed = ScenarioRunner.Build(Hanging(n, SolverMethod.ExactChain, 4, 1), true);
            var vertices = new TubeVertex[meshed.Simulation.GetVertexCount()];
            var indices = new int[meshed.Simulation.GetIndexCount()];
            names.Add("radius + tube mesh filled every step (RopeSimulation.FillMesh)");
            actions.Add(() =>
            {
                meshed.Step(dt);
                meshed.Simulation.FillMesh(vertices, indices);
            });

            var samples = new List<double>[actions.Count];
            for (int a = 0; a < actions.Count; a++)
            {
                samples[a] = new List<double>();
                var warm = Stopwatch.StartNew();
                for (int i = 0; i < 20000 && warm.ElapsedMilliseconds < 250; i++) actions[a]();
            }
            for (int r = 0; r < rounds; r++)
                for (int a = 0; a < actions.Count; a++)
                {
                    var watch = Stopwatch.StartNew();
                    for (int i = 0; i < steps; i++) actions[a]();
                    samples[a].Add(watch.Elapsed.TotalMilliseconds * 1e3 / steps);
                }
            var list = new List<FeatureResult>();
            for (int a = 0; a < actions.Count; a++)
                list.Add(new FeatureResult { Name = names[a], MicrosecondsPerStep = Stats.Median(samples[a]) });
            return list;
        }
    }
}
