using System.IO;
using HookeRope.Lab.Commands;
using HookeRope.Lab.Report;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Stability;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>Smoke runs of report and stability on their reduced sets (no timing assertions).</summary>
    [TestFixture]
    public sealed class CommandSmokeTests : TempFolderTest
    {
        [Test]
        public void QuickReportWritesMarkdownAndParetoPlotAndTheExactSolveWins()
        {
            var output = new StringWriter();
            int code = ReportCommand.Execute(LabConsole.Plain(output), dir, true, 1);
            Assert.That(code, Is.EqualTo(0));
            string md = File.ReadAllText(Path.Combine(dir, "report.md"));
            Assert.That(md, Does.Contain("Machine:"));
            Assert.That(md, Does.Contain("Pareto-optimal"));
            Assert.That(md, Does.Contain("Recommended defaults"));
            Assert.That(md, Does.Contain("| exact BE 1it × 4sub | converged |"));
            Assert.That(md, Does.Contain("| GS BE 4it × 4sub | unconverged |").Or.Contain("| GS BE 4it × 4sub | no result |"), "Gauss–Seidel under these heavy loads is never converged");
            Assert.That(new FileInfo(Path.Combine(dir, "report-pareto.png")).Length, Is.GreaterThan(1000));

            // The physics the report rests on: at a mass ratio of 10⁵ the exact chain solve lands within
            // 5 % of (M + m/2)·g·L/(E·A) with 4 substeps × 1 iteration, where Gauss–Seidel with 4 iterations is off by more than 50 %.
            var result = ErrorReport.Measure(true, 1, null);
            int heavy = result.Scenarios.IndexOf("heavy-mass-ratio");
            int exact = -1, gs = -1;
            for (int i = 0; i < result.Configs.Count; i++)
            {
                var c = result.Configs[i];
                if (c.Substeps == 4 && c.Iterations == 1 && c.Method == SolverMethod.ExactChain) exact = i;
                if (c.Substeps == 4 && c.Iterations == 4 && c.Method == SolverMethod.GaussSeidel) gs = i;
            }
            Assert.That(result.Cells[exact][heavy].Error, Is.LessThan(0.05));
            Assert.That(result.Cells[gs][heavy].Error, Is.GreaterThan(0.5));
        }

        [Test]
        public void QuickStabilitySweepPassesAndWritesItsTable()
        {
            var output = new StringWriter();
            int code = StabilityCommand.Execute(LabConsole.Plain(output), dir, true);
            Assert.That(code, Is.EqualTo(0), output.ToString());
            string md = File.ReadAllText(Path.Combine(dir, "stability-quick.md"));
            Assert.That(md, Does.Contain("mass ratio"));
            Assert.That(md, Does.Contain("10× length"));
            Assert.That(md, Does.Contain("teleported"));
        }

        [Test]
        public void StabilityFlagsANonFiniteRunAsAFailure()
        {
            // A planted defect: a case whose outcome is NaN must fail the sweep (exit code logic).
            var c = new StabilityCase { Name = "planted", Scenario = StabilitySweep.Base(SolverMethod.ExactChain, 0.1) };
            var outcome = new StabilityOutcome { Case = c, NonFinite = true };
            Assert.That(outcome.Failed, Is.True);
            var real = StabilitySweep.Run(c);
            Assert.That(real.Failed, Is.False);
            Assert.That(real.NonFinite, Is.False);
            Assert.That(real.MaxConstraintError, Is.LessThan(1e-3));
        }
    
        [Test]
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveOptimization)]
        public void SteppingWithTheRadiusModelAllocatesNothing()  // fully optimised: no on-stack-replacement allocations in the loops
        {
            var setup = HookeRope.Lab.Simulation.ScenarioRunner.Build(BuiltInScenarios.Load("necking"), true);
            for (int i = 0; i < 300; i++) setup.Step(1f / 90f);
            long a0 = System.GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 400; i++) setup.Rope.Step(1f / 90f);
            long a1 = System.GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 400; i++) setup.UpdateRadii();
            long a2 = System.GC.GetAllocatedBytesForCurrentThread();
            Assert.That(a2 - a0, Is.EqualTo(0), $"Rope.Step: {a1 - a0} B, radius glue: {a2 - a1} B over 400 steps");
        }
    
        [Test]
        public void QuickBenchMeasuresEverySizeWithoutAllocating()
        {
            // Smoke run only: timings are printed, never asserted.
            var sizes = HookeRope.Lab.Bench.MicroBench.Scaling(true, null);
            Assert.That(sizes.Count, Is.EqualTo(3));
            foreach (var s in sizes)
            {
                // marginal costs are differences of two timings: never negative, never NaN
                Assert.That(s.NsPerProjection, Is.GreaterThanOrEqualTo(0));
                Assert.That(s.NsPerSegmentIteration, Is.GreaterThanOrEqualTo(0));
                Assert.That(s.NsPerVertex, Is.GreaterThan(0));
                Assert.That(s.BytesPerStep, Is.EqualTo(0), s.Segments + " segments: bytes allocated per step");
            }
            Assert.That(double.IsFinite(HookeRope.Lab.Bench.MicroBench.ScalingExponent(sizes)), Is.True);
            Assert.That(HookeRope.Lab.Bench.MicroBench.Features(true).Count, Is.EqualTo(7));
        }
    }
}
