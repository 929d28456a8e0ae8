using System;
using System.Diagnostics;
using System.Globalization;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Kernels
{
    /// <summary>Wall-clock cost of the solver kernels against the segment count (Stopwatch, best of several rounds).</summary>
    internal static class KernelTimer
    {
        public static int Execute(bool quick)
        {
            int[] sizes = quick ? new[] { 16, 256, 10000 } : new[] { 16, 64, 256, 1024, 4096, 10000 };
            Console.WriteLine("| segments | GS ns / projection (8 × 1, whole step) | GS marginal ns / projection | exact ns / segment-iteration (8 × 1, whole step) | exact marginal ns / segment-iteration |");
            Console.WriteLine("| ---: | ---: | ---: | ---: | ---: |");
            foreach (int n in sizes)
            {
                double gsStep = PerUnit(ConstraintSolverKind.GaussSeidel, n, 8, 1);
                double gsMarginal = Marginal(ConstraintSolverKind.GaussSeidel, n);
                double exStep = PerUnit(ConstraintSolverKind.ExactChain, n, 8, 1);
                double exMarginal = Marginal(ConstraintSolverKind.ExactChain, n);
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "| {0} | {1:F1} | {2:F1} | {3:F1} | {4:F1} |", n, gsStep, gsMarginal, exStep, exMarginal));
            }
            return 0;
        }

        /// <summary>The hanging loaded rope of <see cref="KernelScene.Hanging"/> (taut: the exact solve's geometric stiffness acts), settled 30 steps.</summary>
        private static Rope Hanging(ConstraintSolverKind solver, int segments, int substeps, int iterations)
        {
            Rope rope = KernelScene.Hanging(solver, RopeSettings.DefaultIntegrator, segments, substeps, iterations);
            for (int i = 0; i < 30; i++) rope.Step(KernelScene.HostStep);
            return rope;
        }

        /// <summary>Best ns per host step over rounds of a fixed work size.</summary>
        private static double StepNs(Rope rope, int segments)
        {
            int steps = Math.Max(4, 400000 / (segments * rope.Settings.Substeps * rope.Settings.Iterations));
            double best = double.MaxValue;
            for (int round = 0; round < 7; round++)
            {
                var watch = Stopwatch.StartNew();
                for (int i = 0; i < steps; i++) rope.Step(KernelScene.HostStep);
                best = Math.Min(best, watch.Elapsed.TotalMilliseconds * 1e6 / steps);
            }
            return best;
        }

        private static double PerUnit(ConstraintSolverKind solver, int segments, int substeps, int iterations) =>
            StepNs(Hanging(solver, segments, substeps, iterations), segments) / ((double)segments * substeps * iterations);

        /// <summary>(step at 10 iterations − step at 2) / (8 × segments), 1 substep: the per-step work cancels.</summary>
        private static double Marginal(ConstraintSolverKind solver, int segments)
        {
            double ten = StepNs(Hanging(solver, segments, 1, 10), segments);
            double two = StepNs(Hanging(solver, segments, 1, 2), segments);
            return (ten - two) / (8.0 * segments);
        }
    }
}
