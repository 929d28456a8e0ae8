using System.IO;
using Spectre.Console;
using System.Collections.Generic;
using HookeRope.Lab.Output;
using HookeRope.Lab.Report;
using HookeRope.Lab.Scenarios;
using HookeRope.Solver;

namespace HookeRope.Lab.Commands
{
    /// <summary><c>report</c>: error against run time, Markdown + log–log Pareto plot + recommended defaults.</summary>
    public static class ReportCommand
    {
        /// <summary>
        /// The lines of the Pareto plot: one per solver × integrator × iteration count (<see cref="SolverConfig.Family"/>),
        /// its configurations' mean cost and worst error, substeps growing along it; BDF2 first and solid, backward Euler
        /// dashed in the same colour for the same iteration count, then Gauss–Seidel.
        /// </summary>
        public static List<Plots.Series> Families(ReportResult result)
        {
            var order = new List<int>();
            for (int i = 0; i < result.Configs.Count; i++) order.Add(i);
            order.Sort((a, b) =>
            {
                int byGroup = GroupRank(result.Configs[a]).CompareTo(GroupRank(result.Configs[b]));
                return byGroup != 0 ? byGroup : a.CompareTo(b);
            });
            var colours = new List<string>();   // method + iteration count, exact first
            foreach (int i in order)
            {
                string key = ColourKey(result.Configs[i]);
                if (result.Configs[i].Method == SolverMethod.ExactChain && !colours.Contains(key)) colours.Add(key);
            }
            foreach (int i in order)
            {
                string key = ColourKey(result.Configs[i]);
                if (!colours.Contains(key)) colours.Add(key);
            }
            var series = new List<Plots.Series>();
            var byFamily = new Dictionary<string, Plots.Series>();
            foreach (int i in order)
            {
                var c = result.Configs[i];
                if (!byFamily.TryGetValue(c.Family, out var s))
                {
                    s = new Plots.Series { Label = c.Family, Dashed = c.Integrator == TimeIntegrator.BackwardEuler, Colour = colours.IndexOf(ColourKey(c)) };
                    byFamily.Add(c.Family, s);
                    series.Add(s);
                }
                s.Cost.Add(result.MeanCost(i));
                s.Error.Add(result.WorstError(i));
                s.Failed.Add(result.Failed(i));
            }
            return series;
        }

        static int GroupRank(SolverConfig c) => c.Method == SolverMethod.GaussSeidel ? 2 : c.Integrator == TimeIntegrator.Bdf2 ? 0 : 1;

        static string ColourKey(SolverConfig c) => c.Method + "/" + c.Iterations;

        /// <summary>
        /// Runs the grid and writes report.md and report-pareto.png to <paramref name="outDir"/>, and the headline into each
        /// of <paramref name="headlines"/> (<see cref="HeadlineBlock"/>; their markers are checked before the grid runs);
        /// <paramref name="progress"/> gets periodic lines with an ETA when the console is not interactive.
        /// </summary>
        public static int Execute(IAnsiConsole console, string outDir, bool quick, int repeats, TextWriter progress = null, IReadOnlyList<string> headlines = null)
        {
            if (repeats < 1 || repeats > 50) throw new UsageException($"--repeats: {repeats} is out of range [1, 50]");
            OutputFolder.Ensure(outDir);
            if (headlines != null) foreach (var file in headlines) HeadlineBlock.Check(file);
            console.MarkupLine("[bold]HookeRope lab · report[/]  " + Markup.Escape(MachineInfo.Describe()));
            ReportResult result = null;
            int total = ErrorReport.Grid(quick).Count * ErrorReport.ReferenceScenarios.Length * (quick ? 1 : repeats);
            if (console.Profile.Capabilities.Interactive)
            {
                console.Progress().Start(ctx =>
                {
                    var task = ctx.AddTask("rounds × configurations × scenarios", maxValue: total);
                    result = ErrorReport.Measure(quick, quick ? 1 : repeats, _ => task.Increment(1));
                });
            }
            else
            {
                var lines = progress == null ? null : new ProgressLines("report (rounds × configurations × scenarios)", total, progress);
                int done = 0;
                result = ErrorReport.Measure(quick, quick ? 1 : repeats, lines == null ? null : _ => lines.Report(++done));
            }
            var series = Families(result);
            int recommended = result.Recommended();
            string plot = Path.Combine(outDir, "report-pareto.png");
            Plots.Pareto($"worst error over {result.Scenarios.Count} reference scenarios against run time (substeps grow along each line)", series,
                recommended >= 0 ? result.MeanCost(recommended) : double.NaN, recommended >= 0 ? result.WorstError(recommended) : double.NaN,
                recommended >= 0 ? result.Configs[recommended].Label : "").SavePng(plot, 1400, 720);
            string md = Path.Combine(outDir, "report.md");
            File.WriteAllText(md, ErrorReport.Markdown(result, "report-pareto.png"));

            var table = new Table().Border(TableBorder.Rounded).Title("Pareto-optimal configurations of each solver and integrator");
            table.AddColumn("configuration");
            foreach (var s in result.Scenarios) table.AddColumn(new TableColumn(Markup.Escape(s)).RightAligned());
            table.AddColumn(new TableColumn("ms / sim s").RightAligned());
            foreach (int i in ErrorReport.HeadlineRows(result))
            {
                var row = new List<string> { Markup.Escape(result.Configs[i].Label) + (i == recommended ? " [green](recommended)[/]" : "") };
                foreach (var cell in result.Cells[i])
                    row.Add(double.IsFinite(cell.Error) ? (cell.Error * 100).ToString("G3", System.Globalization.CultureInfo.InvariantCulture) + " %" : "NaN");
                row.Add(result.MeanCost(i).ToString("F2", System.Globalization.CultureInfo.InvariantCulture));
                table.AddRow(row.ToArray());
            }
            console.Write(table);
            console.MarkupLine(recommended >= 0
                ? "recommended default: [green]" + Markup.Escape(result.Configs[recommended].Label) + "[/] (cheapest converged configuration within 1 % on every reference scenario, the dissipation scenarios included)"
                : "[yellow]no configuration within 1 % on every reference scenario[/]");
            console.MarkupLine("[grey]load average (1, 5, 15 min):[/] " + Markup.Escape(result.LoadBefore) + " at the start, " + Markup.Escape(result.LoadAfter) + " at the end");
            if (headlines != null)
                foreach (var file in headlines)
                {
                    HeadlineBlock.Write(file, ErrorReport.Headline(result));
                    console.MarkupLine("[grey]wrote the headline into[/] " + Markup.Escape(file));
                }
            console.MarkupLine("[grey]wrote[/] " + Markup.Escape(md));
            console.MarkupLine("[grey]wrote[/] " + Markup.Escape(plot));
            return 0;
        }
    }
}
