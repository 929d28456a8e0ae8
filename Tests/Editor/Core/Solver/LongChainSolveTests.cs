using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// The exact solve's work on long hanging chains (issue 18 item 1; solver.md, "Why the exact solve is far from 25 ns"):
    /// 0.1 m segments of the default rope hanging from a pin with an 80 kg load, 8 substeps × 1 iteration, BDF2. At its
    /// static equilibrium a 4 096-segment chain holds g·Σm in every segment with one Newton iteration and one linear solve
    /// per substep; released at its rest length, a chain carries a tension front down at the axial wave speed
    /// c = √(E·A/μ), with the tension μ·c·v behind it (v = g·t the velocity of the falling chain it stops), and only while
    /// the front runs does the tension-only active set take more than one solve per iteration, never more Newton iterations.
    /// </summary>
    public sealed class LongChainSolveTests
    {
        private const float HostStep = 1f / 90f;

        private static Rope Hanging(int segments)
        {
            var settings = new RopeSettings { SegmentCount = segments, RestLength = 0.1f * segments, Substeps = 8, Iterations = 1 };
            var rope = new Rope(settings, Float3.Zero, new Float3(0f, -0.1f * segments, 0f));
            rope.AddPin(0, Float3.Zero);
            rope.AddLoad(segments, 80f);
            return rope;
        }

        /// <summary>Static tension (N) of every segment: g times the mass of the particles below it.</summary>
        private static double[] StaticTension(Rope rope)
        {
            int s = rope.SegmentCount;
            double g = -rope.Settings.Gravity.Y, below = 0.0;
            var tension = new double[s];
            for (int j = s - 1; j >= 0; j--)
            {
                below += rope.GetParticleMass(j + 1);
                tension[j] = g * below;
            }
            return tension;
        }

        [Test]
        public void AChainAtItsStaticEquilibriumHoldsItWithOneIterationAndOneSolvePerSubstep()
        {
            const int segments = 4096;
            Rope rope = Hanging(segments);
            double[] expected = StaticTension(rope);
            // segment j stretched to L·(1 + T_j/(E·A)), at rest
            double y = 0.0, stiffness = rope.Settings.AxialStiffness;
            for (int j = 0; j < segments; j++)
            {
                y -= rope.RestLengths[j] * (1.0 + expected[j] / stiffness);
                rope.SetPosition(j + 1, new Float3(0f, (float)y, 0f));
            }
            for (int step = 0; step < 10; step++)
            {
                StepReport report = rope.Step(HostStep);
                // the first substep estimates the geometric stiffness from no tension at all and adds one iteration
                Assert.That(report.SolveIterations, Is.EqualTo(step == 0 ? 9 : 8), "Newton iterations, step " + step);
                Assert.That(report.LinearSolves, Is.EqualTo(report.SolveIterations), "linear solves, step " + step);
                Assert.That(report.UnconvergedSubsteps, Is.EqualTo(0));
            }
            double worst = 0.0;
            for (int j = 0; j < segments; j++) worst = Math.Max(worst, Math.Abs(rope.Tensions[j] / expected[j] - 1.0));
            Assert.That(worst, Is.LessThan(1e-4), "largest relative deviation from g·Σm");
        }

        [TestCase(256)]
        [TestCase(1024)]
        public void AFreshChainTakesExtraSolvesOnlyWhileItsTensionFrontRuns(int segments)
        {
            Rope rope = Hanging(segments);
            double mu = rope.Settings.LinearDensity, c = Math.Sqrt(rope.Settings.AxialStiffness / mu);
            int arrival = (int)Math.Ceiling(0.1 * segments / c / HostStep); // host steps the front takes to the load
            float[] top = new float[arrival + 10];
            int extraSteps = 0, lastExtra = -1;
            for (int step = 0; step < top.Length; step++)
            {
                StepReport report = rope.Step(HostStep);
                top[step] = rope.Tensions[0];
                Assert.That(report.SolveIterations, Is.EqualTo(8), "one Newton iteration per substep, step " + step);
                Assert.That(report.LinearSolves, Is.LessThanOrEqualTo(8 * report.SolveIterations), "at most 8 active-set passes per iteration");
                if (report.LinearSolves > report.SolveIterations) { extraSteps++; lastExtra = step; }
            }
            Assert.That(extraSteps, Is.GreaterThan(0), "the front's released set moves between passes");
            Assert.That(lastExtra, Is.LessThan(arrival), "extra solves only before the front reaches the load (" + arrival + " steps)");
            // behind the front the tension at the pin rises by μ·c·g per second of fall
            double rise = (top[2] - top[1]) / HostStep, predicted = mu * c * -rope.Settings.Gravity.Y;
            Assert.That(rise, Is.EqualTo(predicted).Within(0.02 * predicted), "dT/dt at the pin, N/s");
        }
    }
}
