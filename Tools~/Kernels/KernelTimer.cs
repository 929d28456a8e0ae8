using System;
using System.Diagnostics;
using System.Globalization;
using HookeRope.Solver;

namespace HookeRope.Kernels
{
    /// <summary>
    /// Wall-clock cost of the solver kernels against the segment count (Stopwatch, best of several rounds). The exact solve
    /// is timed on two ropes: the fresh <see cref="KernelScene.Hanging"/> rope, settled 30 steps (at 1 024 segments and more
    /// its tension front is still running down it, and its tension-only active set takes several linear solves per Newton
    /// iteration), and the <see cref="KernelScene.Resting"/> rope at its static equilibrium (one solve per iteration at
    /// every size). Each is reported per configured segment-iteration and per linear solve actually performed
    /// (<see cref="StepReport.LinearSolves"/>), with the Newton iterations per substep (<see cref="StepReport.SolveIterations"/>)
    /// and solves per iteration it did, so the flatness of the kernel cost shows apart from the work the scene asks for.
    /// </summary>
    internal static class KernelTimer
    {
        /// <summary>Host steps every timed rope is stepped before its rounds.</summary>
        public const int SettleSteps = 30;

        public static int Execute(bool quick)
        {
            int[] sizes = { 16, 64, 256, 1024, 4096, 10000 };
            int rounds = quick ? 3 : 7;
            Console.WriteLine("Exact solve at 8 substeps x 1 iteration (whole step); fresh: the rope released at its rest length, settled "
                + SettleSteps + " steps; at rest: at its static equilibrium. it/sub: Newton iterations per substep; solves/it: linear solves per iteration.");
            Console.WriteLine("| segments | GS ns / projection (8 × 1, whole step) | GS marginal ns / projection | fresh: it / sub | fresh: solves / it | fresh: ns / segment-iteration | fresh: ns / segment-solve | at rest: it / sub | at rest: solves / it | at rest: ns / segment-iteration | at rest: ns / segment-solve | at rest: marginal ns / segment-iteration |");
            Console.WriteLine("| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
            foreach (int n in sizes)
            {
                Timing gs = Time(Settled(KernelScene.Hanging(ConstraintSolverKind.GaussSeidel, RopeSettings.DefaultIntegrator, n, 8, 1)), rounds);
                double gsMarginal = Marginal(ConstraintSolverKind.GaussSeidel, n, rounds, false);
                Timing fresh = Time(Settled(KernelScene.Hanging(ConstraintSolverKind.ExactChain, RopeSettings.DefaultIntegrator, n, 8, 1)), rounds);
                Timing rest = Time(Settled(KernelScene.Resting(ConstraintSolverKind.ExactChain, RopeSettings.DefaultIntegrator, n, 8, 1)), rounds);
                double marginal = Marginal(ConstraintSolverKind.ExactChain, n, rounds, true);
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                    "| {0} | {1:F1} | {2:F1} | {3:F2} | {4:F2} | {5:F1} | {6:F1} | {7:F2} | {8:F2} | {9:F1} | {10:F1} | {11:F1} |", n,
                    gs.PerConfiguredIteration, gsMarginal, fresh.IterationsPerSubstep, fresh.SolvesPerIteration, fresh.PerConfiguredIteration, fresh.PerSolve,
                    rest.IterationsPerSubstep, rest.SolvesPerIteration, rest.PerConfiguredIteration, rest.PerSolve, marginal));
            }
            return 0;
        }

        /// <summary>A rope after <see cref="SettleSteps"/> host steps.</summary>
        internal static Rope Settled(Rope rope)
        {
            for (int i = 0; i < SettleSteps; i++) rope.Step(KernelScene.HostStep);
            return rope;
        }

        /// <summary>What the timed steps of one rope cost and did.</summary>
        internal struct Timing
        {
            /// <summary>Best ns per host step.</summary>
            public double StepNs;
            /// <summary>Segments, substeps and configured iterations per substep of the rope.</summary>
            public int Segments, Substeps, Iterations;
            /// <summary>Newton iterations and linear solves of the exact solve per host step, averaged over the timed steps (0 for Gauss–Seidel).</summary>
            public double SolveIterations, LinearSolves;

            /// <summary>ns per segment and configured iteration (substeps × iterations per step).</summary>
            public double PerConfiguredIteration => StepNs / ((double)Segments * Substeps * Iterations);
            /// <summary>ns per segment and linear solve performed.</summary>
            public double PerSolve => StepNs / (Segments * LinearSolves);
            public double IterationsPerSubstep => SolveIterations / Substeps;
            public double SolvesPerIteration => LinearSolves / SolveIterations;
        }

        /// <summary>Best ns per host step over rounds of a fixed work size, with the solve counts of every timed step.</summary>
        internal static Timing Time(Rope rope, int rounds)
        {
            int segments = rope.SegmentCount, substeps = rope.Settings.Substeps, iterations = rope.Settings.Iterations;
            int steps = Math.Max(4, 400000 / (segments * substeps * iterations));
            double best = double.MaxValue;
            long solveIterations = 0, linearSolves = 0;
            for (int round = 0; round < rounds; round++)
            {
                var watch = Stopwatch.StartNew();
                for (int i = 0; i < steps; i++)
                {
                    StepReport report = rope.Step(KernelScene.HostStep);
                    solveIterations += report.SolveIterations;
                    linearSolves += report.LinearSolves;
                }
                best = Math.Min(best, watch.Elapsed.TotalMilliseconds * 1e6 / steps);
            }
            double timed = (double)rounds * steps;
            return new Timing
            {
                StepNs = best, Segments = segments, Substeps = substeps, Iterations = iterations,
                SolveIterations = solveIterations / timed, LinearSolves = linearSolves / timed,
            };
        }

        /// <summary>
        /// (step at 10 iterations − step at 2) / (8 × segments), 1 substep: the per-step work cancels. The exact solve's on
        /// the rope at rest (<paramref name="resting"/>), whose every iteration is one solve.
        /// </summary>
        private static double Marginal(ConstraintSolverKind solver, int segments, int rounds, bool resting)
        {
            Func<int, Rope> build = iterations => resting
                ? KernelScene.Resting(solver, RopeSettings.DefaultIntegrator, segments, 1, iterations)
                : KernelScene.Hanging(solver, RopeSettings.DefaultIntegrator, segments, 1, iterations);
            double ten = Time(Settled(build(10)), rounds).StepNs;
            double two = Time(Settled(build(2)), rounds).StepNs;
            return (ten - two) / (8.0 * segments);
        }
    }
}
