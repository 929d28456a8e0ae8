using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Very small substeps (up to 1000 per 1/45 s host step, h = 2.2e-5 s), where a substep changes a velocity by a·h, far
    /// below its float resolution (2e-4 m/s against 9.5e-7 m/s at 9.81 m/s), and moves a particle by v·h, a displacement
    /// whose float step (4e-12 m at 4e-5 m) is a velocity step of 1e-7 m/s once divided by h. Before the velocities were
    /// double and the solves' corrections kept their sub-float part (ChainState.DLow), both were rounded every substep with
    /// the same sign substep after substep: a free fall read its velocity 1e-4 (BDF2) and 3e-4 (backward Euler) off g·t after
    /// 1 s at 1000 substeps, and a swinging rope's segment angles drifted by up to 4.6e-4 rad from their converged values.
    /// </summary>
    public sealed class SmallSubstepTests
    {
        static readonly int[] FallSubsteps = { 8, 64, 256, 1000 };

        /// <summary>
        /// A free 2 m rope (4 segments, no pin) falls for 1 s in 45 host steps: its velocity is g·t to float read-out
        /// resolution, and its position ½·g·t·(t + h) for backward Euler (x_n = g·h²·n(n+1)/2, exact) and ½·g·t² within g·h²
        /// (the error of the backward-Euler first substep that starts BDF2's history) for BDF2.
        /// </summary>
        [TestCase(TimeIntegrator.Bdf2)]
        [TestCase(TimeIntegrator.BackwardEuler)]
        public void FreeFallKeepsItsVelocityAtEverySubstepCount(TimeIntegrator integrator)
        {
            foreach (int substeps in FallSubsteps)
            {
                var settings = new RopeSettings { SegmentCount = 4, Integrator = integrator, Substeps = substeps };
                var rope = new Rope(settings, Float3.Zero, new Float3(2f, 0f, 0f));
                for (int k = 0; k < 45; k++) rope.Step(1f / 45f);
                double t = rope.Time, g = settings.Gravity.Y, h = (double)(1f / 45f) / substeps;
                double velocity = rope.GetVelocity(2).Y, height = rope.GetPosition(2).Y;
                double expected = integrator == TimeIntegrator.BackwardEuler ? 0.5 * g * t * (t + h) : 0.5 * g * t * t;
                double allowed = integrator == TimeIntegrator.BackwardEuler ? 0.0 : -g * h * h;
                TestContext.WriteLine($"{integrator} {substeps,4} substeps: v {velocity:R} m/s (g·t {g * t:R}, {(velocity / (g * t) - 1):E2}), " +
                    $"y {height:R} m (expected {expected:R}, {height - expected:E2} m)");
                // float read-out: half an ulp of 9.81 m/s is 4.8e-7 m/s, of 4.9 m 2.4e-7 m
                Assert.That(velocity, Is.EqualTo(g * t).Within(1e-6), substeps + " substeps: velocity");
                Assert.That(height, Is.EqualTo(expected).Within(allowed + 5e-7), substeps + " substeps: position");
            }
        }

        /// <summary>Segment angles (rad) after 1 s (45 host steps of 1/45 s) of a 2 m, 4-segment rope pinned at the origin and released at 30°.</summary>
        private static double[] AnglesAfterOneSecond(TimeIntegrator integrator, ConstraintSolverKind solver, int substeps) =>
            RopeTestKit.AnglesAfterOneSecond(new RopeSettings { SegmentCount = 4, Integrator = integrator, Solver = solver, Substeps = substeps });

        private static double LargestDifference(double[] a, double[] b)
        {
            double largest = 0.0;
            for (int j = 0; j < a.Length; j++) largest = Math.Max(largest, Math.Abs(a[j] - b[j]));
            return largest;
        }

        /// <summary>
        /// BDF2 has converged at 128 substeps (its error there is ~1e-6 rad): 256, 512 and 1000 substeps stay within 3e-5 rad of
        /// it, with either chain solve (measured: 4e-7 rad exact, 6e-6 rad Gauss–Seidel; before, 4.6e-4 and 4.7e-4 rad at 1000).
        /// </summary>
        [TestCase(ConstraintSolverKind.ExactChain)]
        [TestCase(ConstraintSolverKind.GaussSeidel)]
        public void Bdf2SwingStaysConvergedUpToAThousandSubsteps(ConstraintSolverKind solver)
        {
            double[] reference = AnglesAfterOneSecond(TimeIntegrator.Bdf2, solver, 128);
            foreach (int substeps in new[] { 256, 512, 1000 })
            {
                double difference = LargestDifference(AnglesAfterOneSecond(TimeIntegrator.Bdf2, solver, substeps), reference);
                TestContext.WriteLine($"{solver} {substeps} substeps: {difference:E2} rad from 128");
                Assert.That(difference, Is.LessThan(3e-5), substeps + " substeps");
            }
        }

        /// <summary>
        /// Backward Euler stays first order down to h = 2.2e-5 s: its angle error C·h makes the change from 256 to 512 substeps
        /// (1/256 − 1/512)/(1/512 − 1/1000) = 2.05 times the change from 512 to 1000 (measured 2.05; before, 7.5).
        /// </summary>
        [Test]
        public void BackwardEulerSwingStaysFirstOrderUpToAThousandSubsteps()
        {
            double[] a256 = AnglesAfterOneSecond(TimeIntegrator.BackwardEuler, ConstraintSolverKind.ExactChain, 256);
            double[] a512 = AnglesAfterOneSecond(TimeIntegrator.BackwardEuler, ConstraintSolverKind.ExactChain, 512);
            double[] a1000 = AnglesAfterOneSecond(TimeIntegrator.BackwardEuler, ConstraintSolverKind.ExactChain, 1000);
            double ratio = LargestDifference(a256, a512) / LargestDifference(a512, a1000);
            TestContext.WriteLine($"changes {LargestDifference(a256, a512):E3} rad (256 → 512), {LargestDifference(a512, a1000):E3} rad (512 → 1000), ratio {ratio:F3}");
            Assert.That(ratio, Is.InRange(1.9, 2.2));
        }
    }
}
