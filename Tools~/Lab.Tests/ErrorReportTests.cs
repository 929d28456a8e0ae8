using System.Collections.Generic;
using System.Linq;
using HookeRope.Lab.Commands;
using HookeRope.Lab.Report;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>
    /// The report's grid, recommendation rule and families: both time integrators of the exact solve, the dissipation
    /// scenarios as columns that the recommendation must meet, backward Euler and BDF2 as separate lines of the plot.
    /// The measured cases run two configurations at the defaults (no timing assertions).
    /// </summary>
    [TestFixture]
    public sealed class ErrorReportTests
    {
        [TestCase(false, 36, 18)]
        [TestCase(true, 4, 2)]
        public void TheGridRunsTheExactSolveWithBothIntegratorsAndGaussSeidelWithBackwardEuler(bool quick, int gaussSeidel, int perIntegrator)
        {
            var grid = ErrorReport.Grid(quick);
            Assert.That(grid.Count(c => c.Method == SolverMethod.GaussSeidel), Is.EqualTo(gaussSeidel));
            Assert.That(grid.Where(c => c.Method == SolverMethod.GaussSeidel).All(c => c.Integrator == TimeIntegrator.BackwardEuler), Is.True);
            foreach (var integrator in new[] { TimeIntegrator.BackwardEuler, TimeIntegrator.Bdf2 })
                Assert.That(grid.Count(c => c.Method == SolverMethod.ExactChain && c.Integrator == integrator), Is.EqualTo(perIntegrator), integrator.ToString());
            Assert.That(grid.Select(c => c.Label).ToList(), Is.Unique);
            Assert.That(ErrorReport.ReferenceScenarios, Is.EqualTo(new[]
                { "static-hang", "spring-oscillator", "heavy-mass-ratio", "fall-arrest", "spring-amplitude", "slack-bounce", "steel-snatch" }));
        }

        [Test]
        public void AConfigurationRunsItsIntegratorOnTheReferenceScenario()
        {
            var config = new SolverConfig { Method = SolverMethod.ExactChain, Integrator = TimeIntegrator.Bdf2, Iterations = 2, Substeps = 16 };
            var s = ErrorReport.Configured("slack-bounce", config);
            Assert.That(s.Solver.Integrator, Is.EqualTo(TimeIntegrator.Bdf2));
            Assert.That(ScenarioRunner.Settings(s).Integrator, Is.EqualTo(TimeIntegrator.Bdf2), "through to the core settings");
            Assert.That(config.Label, Is.EqualTo("exact BDF2 2it × 16sub"));
            Assert.That(config.Family, Is.EqualTo("exact chain, BDF2, 2 iterations"));
        }

        /// <summary>A report of made-up cells: errors per scenario (7, in <see cref="ErrorReport.ReferenceScenarios"/> order) and one cost.</summary>
        static ReportResult Synthetic(params (SolverConfig Config, double[] Errors, double Cost, Convergence Verdict)[] rows)
        {
            var r = new ReportResult();
            r.Scenarios.AddRange(ErrorReport.ReferenceScenarios);
            foreach (var row in rows)
            {
                r.Configs.Add(row.Config);
                r.Cells.Add(row.Errors.Select(e => new ReportCell { Error = e, MsPerSecond = row.Cost, Verdict = row.Verdict }).ToArray());
            }
            return r;
        }

        static SolverConfig Exact(TimeIntegrator integrator, int substeps) =>
            new SolverConfig { Method = SolverMethod.ExactChain, Integrator = integrator, Iterations = 1, Substeps = substeps };

        [Test]
        public void TheRecommendationMustMeetTheDissipationScenariosToo()
        {
            var r = Synthetic(
                (Exact(TimeIntegrator.BackwardEuler, 8), new[] { 0.0002, 0.0007, 0.0001, 0.006, 0.75, 0.53, 0.074 }, 0.9, Convergence.Converged),
                (Exact(TimeIntegrator.Bdf2, 4), new[] { 0.0002, 0.003, 0.0001, 0.007, 0.009, 0.0147, 0.014 }, 0.5, Convergence.Converged),
                (Exact(TimeIntegrator.Bdf2, 8), new[] { 0.0002, 0.0007, 0.0001, 0.004, 0.0012, 0.0036, 0.003 }, 1.0, Convergence.Converged),
                (Exact(TimeIntegrator.Bdf2, 2), new[] { 0.0002, 0.001, 0.0001, 0.004, 0.001, 0.001, 0.001 }, 0.2, Convergence.Unconverged));
            Assert.That(r.Configs[r.Recommended()].Label, Is.EqualTo("exact BDF2 1it × 8sub"), "the cheaper ones miss a dissipation scenario or did not converge");
            Assert.That(r.Configs[r.Recommended(accuracyOnly: true)].Label, Is.EqualTo("exact BDF2 1it × 4sub"), "on the accuracy scenarios alone");
            Assert.That(r.Recommended(c => c.Integrator == TimeIntegrator.BackwardEuler), Is.EqualTo(-1));
            Assert.That(r.Configs[r.Recommended(c => c.Integrator == TimeIntegrator.BackwardEuler, accuracyOnly: true)].Label, Is.EqualTo("exact BE 1it × 8sub"));
            Assert.That(r.WorstError(0), Is.EqualTo(0.75));
            Assert.That(r.WorstError(0, accuracyOnly: true), Is.EqualTo(0.006));

            string lines = ErrorReport.Recommendations(r);
            Assert.That(lines, Does.Contain("**exact BDF2 1it × 8sub**"));
            Assert.That(lines, Does.Contain("Exact chain with backward Euler: no configuration of the grid keeps every dissipation scenario within 1 %; " +
                "cheapest within 1 % on the accuracy scenarios alone: exact BE 1it × 8sub"));
            Assert.That(lines, Does.Contain("spring-amplitude 75 %, slack-bounce 53 %, steel-snatch 7.4 %"));
        }

        [Test]
        public void TheHeadlineShowsEachIntegratorsParetoFrontBdf2First()
        {
            var r = Synthetic(
                (Exact(TimeIntegrator.BackwardEuler, 4), new[] { 0.0, 0.003, 0.0, 0.011, 0.94, 0.84, 0.14 }, 0.5, Convergence.Converged),
                (Exact(TimeIntegrator.BackwardEuler, 8), new[] { 0.0, 0.0007, 0.0, 0.006, 0.75, 0.53, 0.074 }, 0.9, Convergence.Converged),
                (Exact(TimeIntegrator.Bdf2, 4), new[] { 0.0, 0.003, 0.0, 0.007, 0.009, 0.0147, 0.014 }, 0.5, Convergence.Converged),
                (Exact(TimeIntegrator.Bdf2, 8), new[] { 0.0, 0.0007, 0.0, 0.004, 0.0012, 0.0036, 0.003 }, 1.0, Convergence.Converged));
            // a global front would drop both backward-Euler rows (BDF2 is as cheap and better); the headline keeps each family's
            Assert.That(r.ParetoFront().Select(i => r.Configs[i].Label).ToList(), Is.EqualTo(new[] { "exact BDF2 1it × 4sub", "exact BDF2 1it × 8sub" }));
            Assert.That(ErrorReport.HeadlineRows(r).Select(i => r.Configs[i].Label).ToList(),
                Is.EqualTo(new[] { "exact BDF2 1it × 4sub", "exact BDF2 1it × 8sub", "exact BE 1it × 4sub", "exact BE 1it × 8sub" }));
            string table = ErrorReport.HeadlineTable(r);
            Assert.That(table, Does.Contain("| spring-amplitude error | slack-bounce error | steel-snatch error |"));
            Assert.That(table, Does.Contain("| exact BE 1it × 8sub | 0 % | 0.07 % | 0 % | 0.6 % | 75 % | 53 % | 7.4 % | 0.90 |"));
        }

        [Test]
        public void AtTheDefaultsTheReportShowsBackwardEulersDampingAndRecommendsBdf2()
        {
            // the defaults, 8 substeps × 1 iteration at 1/90 s, with each integrator: the report's seven columns, measured
            var configs = new List<SolverConfig> { Exact(TimeIntegrator.BackwardEuler, 8), Exact(TimeIntegrator.Bdf2, 8) };
            var r = ErrorReport.Measure(configs, false, 1, null);
            for (int i = 0; i < 2; i++)
                TestContext.WriteLine(r.Configs[i].Label + ": " + string.Join(", ", r.Scenarios.Select((s, k) => s + " " + (r.Cells[i][k].Error * 100).ToString("G3") + " %")));
            Assert.That(r.Converged(0) && r.Converged(1), Is.True);
            for (int k = 0; k < r.Scenarios.Count; k++)
            {
                if (r.IsDissipation(k))
                {
                    Assert.That(r.Cells[0][k].Error, Is.GreaterThan(0.05), "backward Euler damps " + r.Scenarios[k]);
                    Assert.That(r.Cells[1][k].Error, Is.LessThan(0.01), "BDF2 keeps " + r.Scenarios[k]);
                }
                else
                    Assert.That(r.Cells[0][k].Error, Is.LessThan(0.01), "backward Euler is accurate on " + r.Scenarios[k]);
            }
            Assert.That(r.Recommended(), Is.EqualTo(1));
            Assert.That(r.Recommended(accuracyOnly: true), Is.GreaterThanOrEqualTo(0));

            var families = ReportCommand.Families(r);
            Assert.That(families.Select(f => f.Label).ToList(), Is.EqualTo(new[] { "exact chain, BDF2, 1 iteration", "exact chain, backward Euler, 1 iteration" }));
            Assert.That(families.Select(f => f.Dashed).ToList(), Is.EqualTo(new[] { false, true }), "backward Euler dashed");
            Assert.That(families[0].Colour, Is.EqualTo(families[1].Colour), "one colour per iteration count, the integrators told apart by the dash");
            var plot = HookeRope.Lab.Output.Plots.Pareto("t", families, r.MeanCost(1), r.WorstError(1), r.Configs[1].Label);
            var lines = plot.GetPlottables<ScottPlot.Plottables.Scatter>().Where(p => p.LineWidth > 0).ToList();
            Assert.That(lines.Single(p => p.LegendText == families[1].Label).LinePattern, Is.EqualTo(ScottPlot.LinePattern.Dashed), "backward Euler's line");
            Assert.That(lines.Single(p => p.LegendText == families[0].Label).LinePattern, Is.EqualTo(ScottPlot.LinePattern.Solid), "BDF2's line");
            string md = ErrorReport.Markdown(r, "p.png");
            Assert.That(md, Does.Contain("| exact BDF2 1it × 8sub **(recommended)** |"));
            Assert.That(md, Does.Contain("| exact BE 1it × 8sub |"));
            Assert.That(md, Does.Contain("Load average (1, 5, 15 min): "));
            Assert.That(md, Does.Contain("- `steel-snatch` (dissipation): relative error of the peak anchor force (substep max)"));
        }
    }
}
