using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;

namespace HookeRope.Lab.Report
{
    /// <summary>One solver configuration of the report grid.</summary>
    public sealed class SolverConfig
    {
        /// <summary>Constraint solver.</summary>
        public SolverMethod Method;
        /// <summary>Substeps per host step.</summary>
        public int Substeps;
        /// <summary>Iterations per substep.</summary>
        public int Iterations;

        /// <summary>"GS 4×8" (iterations × substeps) or "exact 1×4".</summary>
        public string Label => (Method == SolverMethod.GaussSeidel ? "GS " : "exact ") + Iterations + "it × " + Substeps + "sub";
    }

    /// <summary>Error and cost of one configuration on one reference scenario.</summary>
    public sealed class ReportCell
    {
        /// <summary>Relative error of the scenario's primary quantity (∞ when the run produced NaN).</summary>
        public double Error;
        /// <summary>Median wall time per simulated second in ms.</summary>
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
        /// <summary>Timed repeats per cell.</summary>
        public int Repeats;
        /// <summary>Accuracy target for the recommendation (relative).</summary>
        public double Target = 0.01;

        /// <summary>Largest error of a configuration over the scenarios.</summary>
        public double WorstError(int config)
        {
            double worst = 0;
            foreach (var cell in Cells[config]) worst = Math.Max(worst, cell.Error);
            return worst;
        }

        /// <summary>Mean cost of a configuration over the scenarios, ms per simulated second.</summary>
        public double MeanCost(int config)
        {
            double sum = 0;
            foreach (var cell in Cells[config]) sum += cell.MsPerSecond;
            return sum / Cells[config].Length;
        }

        /// <summary>Cheapest configuration (optionally of one method) whose worst error meets the target, or −1.</summary>
        public int Recommended(SolverMethod? method = null)
        {
            int best = -1;
            for (int i = 0; i < Configs.Count; i++)
            {
                if (method.HasValue && Configs[i].Method != method.Value) continue;
                if (!(WorstError(i) <= Target) || !Converged(i)) continue;
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

        /// <summary>Converged configurations not beaten by another converged one on both worst error and mean cost, cheapest first (an unconverged or diverged run is never Pareto-optimal, however cheap).</summary>
        public List<int> ParetoFront()
        {
            var front = new List<int>();
            for (int i = 0; i < Configs.Count; i++)
            {
                if (!Converged(i)) continue;
                bool dominated = false;
                for (int j = 0; j < Configs.Count && !dominated; j++)
                    if (j != i && Converged(j) && WorstError(j) <= WorstError(i) && MeanCost(j) <= MeanCost(i) &&
                        (WorstError(j) < WorstError(i) || MeanCost(j) < MeanCost(i)))
                        dominated = true;
                if (!dominated) front.Add(i);
            }
            front.Sort((a, b) => MeanCost(a).CompareTo(MeanCost(b)));
            return front;
        }
    }

    /// <summary>
    /// The error-against-run-time report: reference scenarios with analytic answers, run with every
    /// configuration of a Gauss–Seidel iterations × substeps grid and the exact chain solve.
    /// </summary>
    public static class ErrorReport
    {
        /// <summary>Reference scenarios (each has an analytic answer in <see cref="PhysicsChecks"/>).</summary>
        public static readonly string[] ReferenceScenarios = { "static-hang", "spring-oscillator", "heavy-mass-ratio", "fall-arrest" };

        /// <summary>The configuration grid (reduced when <paramref name="quick"/>).</summary>
        public static List<SolverConfig> Grid(bool quick)
        {
            var list = new List<SolverConfig>();
            int[] counts = quick ? new[] { 1, 4 } : new[] { 1, 2, 4, 8, 16, 32 };  // substeps of both, GS iterations
            foreach (int it in counts)
                foreach (int sub in counts)
                    list.Add(new SolverConfig { Method = SolverMethod.GaussSeidel, Iterations = it, Substeps = sub });
            int[] exactIterations = quick ? new[] { 1 } : new[] { 1, 2, 4 };
            foreach (int it in exactIterations)
                foreach (int sub in counts)
                    list.Add(new SolverConfig { Method = SolverMethod.ExactChain, Iterations = it, Substeps = sub });
            return list;
        }

        /// <summary>Runs the grid; <paramref name="progress"/> gets a label per finished cell.</summary>
        public static ReportResult Measure(bool quick, int repeats, Action<string> progress)
        {
            var result = new ReportResult { Machine = MachineInfo.Describe(), Repeats = Math.Max(1, repeats) };
            result.Scenarios.AddRange(ReferenceScenarios);
            foreach (var _ in ReferenceScenarios) result.Quantities.Add("?");
            result.Configs.AddRange(Grid(quick));
            if (!quick) ScenarioRunner.Run(BuiltInScenarios.Load(ReferenceScenarios[0]), RunOptions.Lean());  // JIT warm-up
            foreach (var config in result.Configs)
            {
                var cells = new ReportCell[ReferenceScenarios.Length];
                for (int k = 0; k < ReferenceScenarios.Length; k++)
                {
                    var times = new List<double>();
                    double error = double.NaN;
                    var verdict = Convergence.Converged;
                    for (int r = 0; r < result.Repeats; r++)
                    {
                        var s = BuiltInScenarios.Load(ReferenceScenarios[k]);
                        s.Solver.Method = config.Method;
                        s.Solver.Substeps = config.Substeps;
                        s.Solver.Iterations = config.Iterations;
                        var run = ScenarioRunner.Run(s, RunOptions.Lean());
                        times.Add(run.WallSeconds / s.Duration * 1000);
                        if (r == 0)
                        {
                            var checks = PhysicsChecks.Evaluate(run);
                            error = PrimaryError(run, checks);
                            verdict = ConvergenceVerdict.Judge(run).Kind;
                            if (checks.Count > 0) result.Quantities[k] = checks[0].Quantity;
                        }
                    }
                    cells[k] = new ReportCell { Error = error, MsPerSecond = Stats.Median(times), Verdict = verdict };
                    progress?.Invoke(config.Label + " · " + ReferenceScenarios[k]);
                }
                result.Cells.Add(cells);
            }
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

        /// <summary>The headline table (Markdown): the Pareto-optimal configurations, cheapest first.</summary>
        public static string HeadlineTable(ReportResult r)
        {
            var sb = new StringBuilder();
            sb.Append("| configuration (iterations × substeps) |");
            foreach (var s in r.Scenarios) sb.Append(' ').Append(s).Append(" error |");
            sb.Append(" mean ms per simulated s |\n|---|");
            foreach (var _ in r.Scenarios) sb.Append("---:|");
            sb.Append("---:|\n");
            int recommended = r.Recommended();
            foreach (int i in r.ParetoFront())
            {
                sb.Append("| ").Append(r.Configs[i].Label).Append(i == recommended ? " **(recommended)**" : "").Append(" |");
                foreach (var cell in r.Cells[i]) sb.Append(' ').Append(Pct(cell.Error)).Append(" |");
                sb.Append(' ').Append(Ms(r.MeanCost(i))).Append(" |\n");
            }
            return sb.ToString();
        }

        /// <summary>The full Markdown report.</summary>
        public static string Markdown(ReportResult r, string plotFile)
        {
            var sb = new StringBuilder();
            sb.Append("# HookeRope: error against run time\n\n");
            sb.Append("Machine: ").Append(r.Machine).Append("  \n");
            sb.Append("Date (UTC): ").Append(DateTime.UtcNow.ToString("yyyy-MM-dd HH:mm", CultureInfo.InvariantCulture)).Append("  \n");
            sb.Append("Timings: median of ").Append(r.Repeats).Append(" run(s) per cell, wall time of the stepping loop divided by the simulated time.\n\n");
            sb.Append("Reference scenarios (built-in, `run <name>` shows each):\n\n");
            for (int k = 0; k < r.Scenarios.Count; k++)
                sb.Append("- `").Append(r.Scenarios[k]).Append("`: relative error of the ").Append(r.Quantities[k]).Append(" against its analytic value.\n");
            sb.Append("\n## Headline: Pareto-optimal configurations\n\n");
            sb.Append(HeadlineTable(r)).Append('\n');
            sb.Append("![error against run time](").Append(plotFile).Append(")\n\n");
            sb.Append("## Recommended defaults\n\n");
            int rec = r.Recommended();
            int gs = r.Recommended(SolverMethod.GaussSeidel);
            sb.Append(rec >= 0
                ? $"- Cheapest configuration within {r.Target:P0} on every reference scenario: **{r.Configs[rec].Label}** ({Ms(r.MeanCost(rec))} ms per simulated second on average).\n"
                : $"- No configuration of the grid is within {r.Target:P0} on every reference scenario.\n");
            sb.Append(gs >= 0
                ? $"- Cheapest Gauss–Seidel configuration within {r.Target:P0}: {r.Configs[gs].Label} ({Ms(r.MeanCost(gs))} ms per simulated second).\n"
                : $"- No Gauss–Seidel configuration of the grid reaches {r.Target:P0} on every scenario (the heavy mass ratio defeats it): use the exact chain solve.\n");
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
