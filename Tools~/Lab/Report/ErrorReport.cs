using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using HookeRope.Solver;

namespace HookeRope.Lab.Report
{
    /// <summary>One solver configuration of the report grid.</summary>
    public sealed class SolverConfig
    {
        /// <summary>Constraint solver.</summary>
        public SolverMethod Method;
        /// <summary>Time integrator of each substep.</summary>
        public TimeIntegrator Integrator = TimeIntegrator.BackwardEuler;
        /// <summary>Substeps per host step.</summary>
        public int Substeps;
        /// <summary>Iterations per substep.</summary>
        public int Iterations;

        /// <summary>"BE" or "BDF2".</summary>
        public string IntegratorShort => Integrator == TimeIntegrator.Bdf2 ? "BDF2" : "BE";

        /// <summary>"exact BDF2 1it × 8sub" or "GS BE 4it × 8sub" (iterations × substeps).</summary>
        public string Label => (Method == SolverMethod.GaussSeidel ? "GS " : "exact ") + IntegratorShort + " " + Iterations + "it × " + Substeps + "sub";

        /// <summary>Solver and integrator, e.g. "exact chain, BDF2": the groups of the headline table.</summary>
        public string Group => (Method == SolverMethod.GaussSeidel ? "Gauss–Seidel, " : "exact chain, ") + (Integrator == TimeIntegrator.Bdf2 ? "BDF2" : "backward Euler");

        /// <summary>Solver, integrator and iteration count, e.g. "exact chain, BDF2, 1 iteration": one joined line of the Pareto plot (substeps grow along it).</summary>
        public string Family => Group + ", " + Iterations + (Iterations == 1 ? " iteration" : " iterations");
    }

    /// <summary>Error and cost of one configuration on one reference scenario.</summary>
    public sealed class ReportCell
    {
        /// <summary>Relative error of the scenario's primary quantity (∞ when the run produced NaN).</summary>
        public double Error;
        /// <summary>Best (smallest) wall time per simulated second over the repeats, in ms: on a shared machine the load only ever adds time.</summary>
        public double MsPerSecond;
        /// <summary>Convergence verdict of the first repeat (<see cref="ConvergenceVerdict"/>).</summary>
        public Convergence Verdict;

        /// <summary>True when the run has no usable result: diverged, NaN, or no measurable quantity.</summary>
        public bool Failed => Verdict == Convergence.Diverged || !double.IsFinite(Error);
    }

    /// <summary>Everything the report measured.</summary>
    public sealed class ReportResult
    {
        /// <summary>Reference scenario names (columns).</summary>
        public List<string> Scenarios = new List<string>();
        /// <summary>What each scenario's error measures.</summary>
        public List<string> Quantities = new List<string>();
        /// <summary>Configurations (rows).</summary>
        public List<SolverConfig> Configs = new List<SolverConfig>();
        /// <summary>Cells[config][scenario].</summary>
        public List<ReportCell[]> Cells = new List<ReportCell[]>();
        /// <summary>Machine description.</summary>
        public string Machine;
        /// <summary>Timed rounds over the whole grid (a cell's cost is its best round).</summary>
        public int Repeats;
        /// <summary>Accuracy target for the recommendation (relative).</summary>
        public double Target = 0.01;

        /// <summary>Load average of the machine (1, 5, 15 min) when the measurement started and when it ended.</summary>
        public string LoadBefore = "", LoadAfter = "";

        /// <summary>True for the scenarios that measure numerical damping (<see cref="ErrorReport.DissipationScenarios"/>).</summary>
        public bool IsDissipation(int scenario) => Array.IndexOf(ErrorReport.DissipationScenarios, Scenarios[scenario]) >= 0;

        /// <summary>Largest error of a configuration over the scenarios (only the accuracy scenarios when <paramref name="accuracyOnly"/>).</summary>
        public double WorstError(int config, bool accuracyOnly = false)
        {
            double worst = 0;
            for (int k = 0; k < Cells[config].Length; k++)
                if (!accuracyOnly || !IsDissipation(k)) worst = Math.Max(worst, Cells[config][k].Error);
            return worst;
        }

        /// <summary>Mean cost of a configuration over the scenarios, ms per simulated second.</summary>
        public double MeanCost(int config)
        {
            double sum = 0;
            foreach (var cell in Cells[config]) sum += cell.MsPerSecond;
            return sum / Cells[config].Length;
        }

        /// <summary>
        /// The recommendation rule (Documentation~/lab.md): the cheapest configuration (of those <paramref name="filter"/>
        /// accepts) that converged on every reference scenario and whose error on every one of them, the dissipation
        /// scenarios included (only the accuracy scenarios when <paramref name="accuracyOnly"/>), is within
        /// <see cref="Target"/>; −1 when none is.
        /// </summary>
        public int Recommended(Func<SolverConfig, bool> filter = null, bool accuracyOnly = false)
        {
            int best = -1;
            for (int i = 0; i < Configs.Count; i++)
            {
                if (filter != null && !filter(Configs[i])) continue;
                if (!(WorstError(i, accuracyOnly) <= Target) || !Converged(i)) continue;
                if (best < 0 || MeanCost(i) < MeanCost(best)) best = i;
            }
            return best;
        }

        /// <summary>True when a configuration failed (diverged, NaN or no result) on any scenario.</summary>
        public bool Failed(int config)
        {
            foreach (var cell in Cells[config]) if (cell.Failed) return true;
            return false;
        }

        /// <summary>"converged", "unconverged", "diverged" or "no result": the worst over the scenarios of a configuration.</summary>
        public string WorstVerdict(int config)
        {
            var worst = Convergence.Converged;
            bool noResult = false;
            foreach (var cell in Cells[config])
            {
                if (cell.Verdict > worst) worst = cell.Verdict;
                if (!double.IsFinite(cell.Error)) noResult = true;
            }
            if (worst == Convergence.Diverged) return "diverged";
            if (noResult) return "no result";
            return worst == Convergence.Converged ? "converged" : "unconverged";
        }

        /// <summary>True when a configuration converged (<see cref="ConvergenceVerdict"/>) on every scenario with a finite error.</summary>
        public bool Converged(int config)
        {
            foreach (var cell in Cells[config]) if (cell.Failed || cell.Verdict != Convergence.Converged) return false;
            return true;
        }

        /// <summary>
        /// Converged configurations (of those <paramref name="filter"/> accepts) not beaten by another accepted converged
        /// one on both worst error and mean cost, cheapest first (an unconverged or diverged run is never Pareto-optimal,
        /// however cheap).
        /// </summary>
        public List<int> ParetoFront(Func<SolverConfig, bool> filter = null)
        {
            var front = new List<int>();
            for (int i = 0; i < Configs.Count; i++)
            {
                if (!Converged(i) || (filter != null && !filter(Configs[i]))) continue;
                bool dominated = false;
                for (int j = 0; j < Configs.Count && !dominated; j++)
                    if (j != i && Converged(j) && (filter == null || filter(Configs[j])) && WorstError(j) <= WorstError(i) && MeanCost(j) <= MeanCost(i) &&
                        (WorstError(j) < WorstError(i) || MeanCost(j) < MeanCost(i)))
                        dominated = true;
                if (!dominated) front.Add(i);
            }
            front.Sort((a, b) => MeanCost(a).CompareTo(MeanCost(b)));
            return front;
        }

        /// <summary>The solver × integrator groups of the grid in headline order (exact BDF2, exact backward Euler, Gauss–Seidel), each with the filter that selects its configurations.</summary>
        public List<(string Group, Func<SolverConfig, bool> Filter)> Groups()
        {
            var names = new List<string>();
            foreach (var c in Configs) if (!names.Contains(c.Group)) names.Add(c.Group);
            names.Sort((a, b) => Rank(a).CompareTo(Rank(b)));
            var list = new List<(string, Func<SolverConfig, bool>)>();
            foreach (var name in names) list.Add((name, c => c.Group == name));
            return list;
        }

        static int Rank(string group) => group.StartsWith("exact", StringComparison.Ordinal) ? (group.EndsWith("BDF2", StringComparison.Ordinal) ? 0 : 1) : 2;
    }

    /// <summary>
    /// The error-against-run-time report: reference scenarios with analytic answers (four accuracy scenarios and three
    /// that measure numerical damping), run with every configuration of a Gauss–Seidel iterations × substeps grid and of
    /// the exact chain solve with both time integrators.
    /// </summary>
    public static class ErrorReport
    {
        /// <summary>Accuracy scenarios: static answers and a period, which numerical damping barely moves.</summary>
        public static readonly string[] AccuracyScenarios = { "static-hang", "spring-oscillator", "heavy-mass-ratio", "fall-arrest" };

        /// <summary>Dissipation scenarios (issue 14, undamped): amplitude after 10 periods, rebound height, snatch peak read inside the step.</summary>
        public static readonly string[] DissipationScenarios = { "spring-amplitude", "slack-bounce", "steel-snatch" };

        /// <summary>Every reference scenario (each has an analytic answer in <see cref="PhysicsChecks"/>), the columns of the report.</summary>
        public static readonly string[] ReferenceScenarios = Concat(AccuracyScenarios, DissipationScenarios);

        static string[] Concat(string[] a, string[] b)
        {
            var all = new string[a.Length + b.Length];
            a.CopyTo(all, 0);
            b.CopyTo(all, a.Length);
            return all;
        }

        /// <summary>
        /// The configuration grid (reduced when <paramref name="quick"/>): Gauss–Seidel (backward Euler, as the package
        /// runs it) with iterations × substeps, and the exact chain solve with each integrator × iterations × substeps.
        /// </summary>
        public static List<SolverConfig> Grid(bool quick)
        {
            var list = new List<SolverConfig>();
            int[] counts = quick ? new[] { 1, 4 } : new[] { 1, 2, 4, 8, 16, 32 };  // substeps of both, GS iterations
            foreach (int it in counts)
                foreach (int sub in counts)
                    list.Add(new SolverConfig { Method = SolverMethod.GaussSeidel, Integrator = TimeIntegrator.BackwardEuler, Iterations = it, Substeps = sub });
            int[] exactIterations = quick ? new[] { 1 } : new[] { 1, 2, 4 };
            foreach (var integrator in new[] { TimeIntegrator.BackwardEuler, TimeIntegrator.Bdf2 })
                foreach (int it in exactIterations)
                    foreach (int sub in counts)
                        list.Add(new SolverConfig { Method = SolverMethod.ExactChain, Integrator = integrator, Iterations = it, Substeps = sub });
            return list;
        }

        /// <summary>A built-in reference scenario with the solver of <paramref name="config"/>.</summary>
        public static Scenario Configured(string scenario, SolverConfig config)
        {
            var s = BuiltInScenarios.Load(scenario);
            s.Solver.Method = config.Method;
            s.Solver.Integrator = config.Integrator;
            s.Solver.Substeps = config.Substeps;
            s.Solver.Iterations = config.Iterations;
            return s;
        }

        /// <summary>Runs the grid; <paramref name="progress"/> gets a label per finished cell.</summary>
        public static ReportResult Measure(bool quick, int repeats, Action<string> progress) => Measure(Grid(quick), !quick, repeats, progress);

        /// <summary>
        /// Runs <paramref name="configs"/> on every reference scenario (after a JIT warm-up when <paramref name="warmUp"/>),
        /// <paramref name="repeats"/> rounds over the whole grid so that a slow spell of the shared machine hits every
        /// configuration alike; a cell's cost is its best round, its error and verdict those of the first round
        /// (deterministic). <paramref name="progress"/> gets a label per run.
        /// </summary>
        public static ReportResult Measure(List<SolverConfig> configs, bool warmUp, int repeats, Action<string> progress)
        {
            var result = new ReportResult { Machine = MachineInfo.Describe(), Repeats = Math.Max(1, repeats), LoadBefore = MachineInfo.LoadAverage() };
            result.Scenarios.AddRange(ReferenceScenarios);
            foreach (var _ in ReferenceScenarios) result.Quantities.Add("?");
            result.Configs.AddRange(configs);
            if (warmUp) ScenarioRunner.Run(BuiltInScenarios.Load(ReferenceScenarios[0]), RunOptions.Lean());  // JIT warm-up
            foreach (var _ in result.Configs)
            {
                var cells = new ReportCell[ReferenceScenarios.Length];
                for (int k = 0; k < cells.Length; k++) cells[k] = new ReportCell { Error = double.NaN, MsPerSecond = double.PositiveInfinity };
                result.Cells.Add(cells);
            }
            for (int round = 0; round < result.Repeats; round++)
                for (int i = 0; i < result.Configs.Count; i++)
                    for (int k = 0; k < ReferenceScenarios.Length; k++)
                    {
                        var s = Configured(ReferenceScenarios[k], result.Configs[i]);
                        var run = ScenarioRunner.Run(s, RunOptions.Lean());
                        var cell = result.Cells[i][k];
                        cell.MsPerSecond = Math.Min(cell.MsPerSecond, run.WallSeconds / s.Duration * 1000);
                        if (round == 0)
                        {
                            var checks = PhysicsChecks.Evaluate(run);
                            cell.Error = PrimaryError(run, checks);
                            cell.Verdict = ConvergenceVerdict.Judge(run).Kind;
                            if (checks.Count > 0) result.Quantities[k] = checks[0].Quantity;
                        }
                        progress?.Invoke(result.Configs[i].Label + " · " + ReferenceScenarios[k]);
                    }
            result.LoadAfter = MachineInfo.LoadAverage();
            return result;
        }

        /// <summary>Relative error of the first check of a run; +∞ when the run went non-finite.</summary>
        public static double PrimaryError(RunResult run) =>
            run.NonFinite ? double.PositiveInfinity : PrimaryError(run, PhysicsChecks.Evaluate(run));

        static double PrimaryError(RunResult run, List<CheckResult> checks)
        {
            if (run.NonFinite) return double.PositiveInfinity;
            if (checks.Count == 0) return double.NaN;
            double e = checks[0].Error;
            return double.IsFinite(e) ? e : double.PositiveInfinity;
        }

        static string Pct(double e) => double.IsPositiveInfinity(e) ? "NaN/∞" : double.IsNaN(e) ? "n/a" :
            (e * 100).ToString(e < 0.001 ? "G2" : "G3", CultureInfo.InvariantCulture) + " %";

        static string Ms(double ms) => ms.ToString(ms < 10 ? "F2" : "F1", CultureInfo.InvariantCulture);

        /// <summary>The rows of the headline table: each solver × integrator group's Pareto-optimal configurations, cheapest first, groups in <see cref="ReportResult.Groups"/> order.</summary>
        public static List<int> HeadlineRows(ReportResult r)
        {
            var rows = new List<int>();
            foreach (var (_, filter) in r.Groups()) rows.AddRange(r.ParetoFront(filter));
            return rows;
        }

        /// <summary>The headline table (Markdown): per solver × integrator, its Pareto-optimal configurations, cheapest first.</summary>
        public static string HeadlineTable(ReportResult r)
        {
            var sb = new StringBuilder();
            sb.Append("| configuration (iterations × substeps) |");
            foreach (var s in r.Scenarios) sb.Append(' ').Append(s).Append(" error |");
            sb.Append(" mean ms per simulated s |\n|---|");
            foreach (var _ in r.Scenarios) sb.Append("---:|");
            sb.Append("---:|\n");
            int recommended = r.Recommended();
            foreach (int i in HeadlineRows(r))
            {
                sb.Append("| ").Append(r.Configs[i].Label).Append(i == recommended ? " **(recommended)**" : "").Append(" |");
                foreach (var cell in r.Cells[i]) sb.Append(' ').Append(Pct(cell.Error)).Append(" |");
                sb.Append(' ').Append(Ms(r.MeanCost(i))).Append(" |\n");
            }
            return sb.ToString();
        }

        /// <summary>Errors of a configuration on the dissipation scenarios, "spring-amplitude 74.7 %, …".</summary>
        static string DissipationErrors(ReportResult r, int config)
        {
            var parts = new List<string>();
            for (int k = 0; k < r.Scenarios.Count; k++)
                if (r.IsDissipation(k)) parts.Add(r.Scenarios[k] + " " + Pct(r.Cells[config][k].Error));
            return string.Join(", ", parts);
        }

        /// <summary>The "Recommended defaults" lines (Markdown list): the overall rule, then per integrator of the exact solve, then Gauss–Seidel.</summary>
        public static string Recommendations(ReportResult r)
        {
            var sb = new StringBuilder();
            string target = r.Target.ToString("P0", CultureInfo.InvariantCulture);
            int rec = r.Recommended();
            sb.Append(rec >= 0
                ? $"- Cheapest configuration that converged on every reference scenario and is within {target} on each, the dissipation scenarios included: **{r.Configs[rec].Label}** ({Ms(r.MeanCost(rec))} ms per simulated second on average).\n"
                : $"- No configuration of the grid converged on every reference scenario within {target} on each, the dissipation scenarios included.\n");
            foreach (var integrator in new[] { TimeIntegrator.Bdf2, TimeIntegrator.BackwardEuler })
            {
                string name = integrator == TimeIntegrator.Bdf2 ? "BDF2" : "backward Euler";
                bool Exact(SolverConfig c) => c.Method == SolverMethod.ExactChain && c.Integrator == integrator;
                bool any = false;
                foreach (var c in r.Configs) any |= Exact(c);
                if (!any) continue;
                int all = r.Recommended(Exact);
                int accuracy = r.Recommended(Exact, accuracyOnly: true);
                if (all >= 0)
                    sb.Append($"- Exact chain with {name}: cheapest within {target} on every scenario: {r.Configs[all].Label} ({Ms(r.MeanCost(all))} ms/s)");
                else
                    sb.Append($"- Exact chain with {name}: no configuration of the grid keeps every dissipation scenario within {target}");
                if (accuracy >= 0 && accuracy != all)
                    sb.Append($"; cheapest within {target} on the accuracy scenarios alone: {r.Configs[accuracy].Label} ({Ms(r.MeanCost(accuracy))} ms/s), where the dissipation errors are {DissipationErrors(r, accuracy)}");
                sb.Append(".\n");
            }
            int gs = r.Recommended(c => c.Method == SolverMethod.GaussSeidel);
            sb.Append(gs >= 0
                ? $"- Cheapest Gauss–Seidel configuration within {target}: {r.Configs[gs].Label} ({Ms(r.MeanCost(gs))} ms per simulated second).\n"
                : $"- No Gauss–Seidel configuration of the grid reaches {target} on every scenario (the heavy mass ratio defeats it): use the exact chain solve.\n");
            return sb.ToString();
        }

        /// <summary>
        /// What <c>report --headline FILE</c> writes into README.md and the manual: where and how it was measured (machine,
        /// load average, date, rounds), the headline table and the recommendations.
        /// </summary>
        public static string Headline(ReportResult r)
        {
            var sb = new StringBuilder();
            sb.Append("Measured by `report` (best of ").Append(r.Repeats).Append(r.Repeats == 1 ? " round" : " rounds").Append(" over the grid) on ").Append(r.Machine)
              .Append(", load average (1, 5, 15 min) ").Append(r.LoadBefore).Append(" at the start and ").Append(r.LoadAfter).Append(" at the end, ")
              .Append(DateTime.UtcNow.ToString("yyyy-MM-dd", CultureInfo.InvariantCulture))
              .Append(". The error columns are deterministic; the ms column, and with it which rows are Pareto-optimal and the recommendation where two costs are close, depends on the load.\n\n");
            sb.Append(HeadlineTable(r));
            foreach (var (group, filter) in r.Groups())
                if (r.ParetoFront(filter).Count == 0) sb.Append("\n").Append(group).Append(": no configuration of the grid converged on every reference scenario.\n");
            sb.Append('\n').Append(Recommendations(r));
            return sb.ToString();
        }

        /// <summary>The full Markdown report.</summary>
        public static string Markdown(ReportResult r, string plotFile)
        {
            var sb = new StringBuilder();
            sb.Append("# HookeRope: error against run time\n\n");
            sb.Append("Machine: ").Append(r.Machine).Append("  \n");
            sb.Append("Load average (1, 5, 15 min): ").Append(r.LoadBefore).Append(" at the start, ").Append(r.LoadAfter).Append(" at the end  \n");
            sb.Append("Date (UTC): ").Append(DateTime.UtcNow.ToString("yyyy-MM-dd HH:mm", CultureInfo.InvariantCulture)).Append("  \n");
            sb.Append("Timings: best of ").Append(r.Repeats).Append(" round(s) over the whole grid per cell, wall time of the stepping loop divided by the simulated time. ");
            sb.Append("The error columns and verdicts are deterministic; the ms columns depend on the machine's load, and with them which configurations are Pareto-optimal and recommended where two costs are close.\n\n");
            sb.Append("Reference scenarios (built-in, `run <name>` shows each), accuracy first, then numerical damping (undamped, issue 14):\n\n");
            for (int k = 0; k < r.Scenarios.Count; k++)
                sb.Append("- `").Append(r.Scenarios[k]).Append("`").Append(r.IsDissipation(k) ? " (dissipation)" : "").Append(": relative error of the ").Append(r.Quantities[k]).Append(" against its analytic value.\n");
            sb.Append("\n## Headline: Pareto-optimal configurations of each solver and integrator\n\n");
            sb.Append(HeadlineTable(r));
            foreach (var (group, filter) in r.Groups())
                if (r.ParetoFront(filter).Count == 0) sb.Append("\n").Append(group).Append(": no configuration of the grid converged on every reference scenario (see the full table).\n");
            sb.Append('\n');
            sb.Append("![error against run time](").Append(plotFile).Append(")\n\n");
            sb.Append("## Recommended defaults\n\n");
            sb.Append(Recommendations(r));
            sb.Append("\n## All configurations\n\nverdict: the worst convergence verdict over the scenarios (only converged configurations can be Pareto-optimal or recommended).\n\n| configuration | verdict | worst error | mean ms/s |");
            foreach (var s in r.Scenarios) sb.Append(' ').Append(s).Append(" error | ms/s |");
            sb.Append("\n|---|---|---:|---:|");
            foreach (var _ in r.Scenarios) sb.Append("---:|---:|");
            sb.Append('\n');
            for (int i = 0; i < r.Configs.Count; i++)
            {
                sb.Append("| ").Append(r.Configs[i].Label).Append(" | ").Append(r.WorstVerdict(i)).Append(" | ").Append(Pct(r.WorstError(i))).Append(" | ").Append(Ms(r.MeanCost(i))).Append(" |");
                foreach (var cell in r.Cells[i]) sb.Append(' ').Append(Pct(cell.Error)).Append(" | ").Append(Ms(cell.MsPerSecond)).Append(" |");
                sb.Append('\n');
            }
            return sb.ToString();
        }
    }
}
