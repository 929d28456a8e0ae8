using System.IO;
using Spectre.Console;
using System.Collections.Generic;
using HookeRope.Lab.Output;
using HookeRope.Lab.Report;
using HookeRope.Lab.Scenarios;

namespace HookeRope.Lab.Commands
{
    /// <summary><c>report</c>: error against run time, Markdown + log–log Pareto plot + recommended defaults.</summary>
    public static class ReportCommand
    {
        /// <summary>Runs the grid and writes report.md and report-pareto.png to <paramref name="outDir"/>; <paramref name="progress"/> gets periodic lines with an ETA when the console is not interactive.</summary>
        public static int Execute(IAnsiConsole console, string outDir, bool quick, int repeats, TextWriter progress = null)
        {
            if (repeats < 1 || repeats > 50) throw new UsageException($"--repeats: {repeats} is out of range [1, 50]");
            OutputFolder.Ensure(outDir);
            console.MarkupLine("[bold]HookeRope lab · report[/]  " + Markup.Escape(MachineInfo.Describe()));
            ReportResult result = null;
            int total = ErrorReport.Grid(quick).Count * ErrorReport.ReferenceScenarios.Length;
            if (console.Profile.Capabilities.Interactive)
            {
                console.Progress().Start(ctx =>
                {
                    var task = ctx.AddTask("configurations × scenarios", maxValue: total);
                    result = ErrorReport.Measure(quick, quick ? 1 : repeats, _ => task.Increment(1));
                });
            }
            else
            {
                var lines = progress == null ? null : new ProgressLines("report (configurations × scenarios)", total, progress);
                int done = 0;
                result = ErrorReport.Measure(quick, quick ? 1 : repeats, lines == null ? null : _ => lines.Report(++done));
            }
            var series = new List<Plots.Series>();
            var byFamily = new Dictionary<string, Plots.Series>();
            for (int i = 0; i < result.Configs.Count; i++)
            {
                var c = result.Configs[i];
                string family = (c.Method == SolverMethod.GaussSeidel ? "Gauss–Seidel, " : "exact chain, ") + c.Iterations + (c.Iterations == 1 ? " iteration" : " iterations");
                if (!byFamily.TryGetValue(family, out var s))
                {
                    s = new Plots.Series { Label = family };
                    byFamily.Add(family, s);
                    series.Add(s);
                }
                s.Cost.Add(result.MeanCost(i));
                s.Error.Add(result.WorstError(i));
                s.Failed.Add(result.Failed(i));
            }
            int recommended = result.Recommended();
            string plot = Path.Combine(outDir, "report-pareto.png");
            Plots.Pareto("worst error over the reference scenarios against run time (substeps grow along each family)", series,
                recommended >= 0 ? result.MeanCost(recommended) : double.NaN, recommended >= 0 ? result.WorstError(recommended) : double.NaN,
                recommended >= 0 ? result.Configs[recommended].Label : "").SavePng(plot, 1200, 640);
            string md = Path.Combine(outDir, "report.md");
            File.WriteAllText(md, ErrorReport.Markdown(result, "report-pareto.png"));

            var table = new Table().Border(TableBorder.Rounded).Title("Pareto-optimal configurations");
            table.AddColumn("configuration");
            foreach (var s in result.Scenarios) table.AddColumn(new TableColumn(Markup.Escape(s)).RightAligned());
            table.AddColumn(new TableColumn("ms / sim s").RightAligned());
            int rec = result.Recommended();
            foreach (int i in result.ParetoFront())
            {
                var row = new List<string> { Markup.Escape(result.Configs[i].Label) + (i == rec ? " [green](recommended)[/]" : "") };
                foreach (var cell in result.Cells[i])
                    row.Add(double.IsFinite(cell.Error) ? (cell.Error * 100).ToString("G3", System.Globalization.CultureInfo.InvariantCulture) + " %" : "NaN");
                row.Add(result.MeanCost(i).ToString("F2", System.Globalization.CultureInfo.InvariantCulture));
                table.AddRow(row.ToArray());
            }
            console.Write(table);
            console.MarkupLine(rec >= 0
                ? "recommended default: [green]" + Markup.Escape(result.Configs[rec].Label) + "[/] (cheapest within 1 % on every reference scenario)"
                : "[yellow]no configuration within 1 % on every reference scenario[/]");
            console.MarkupLine("[grey]wrote[/] " + Markup.Escape(md));
            console.MarkupLine("[grey]wrote[/] " + Markup.Escape(plot));
            return 0;
        }
    }
}
