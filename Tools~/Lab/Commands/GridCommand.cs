using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Text;
using HookeRope.Lab.Report;
using HookeRope.Lab.Stability;
using HookeRope.Solver;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary><c>stability --full</c>: the integrator grid (<see cref="GridSweep"/>), a summary per integrator and a table of every failure; exit code 1 if any case fails.</summary>
    public static class GridCommand
    {
        /// <summary>Runs the grid (whole, or the CI subset), prints and writes stability-grid.md (or stability-grid-ci.md) to <paramref name="outDir"/>.</summary>
        public static int Execute(IAnsiConsole console, string outDir, bool full)
        {
            OutputFolder.Ensure(outDir);
            var cases = GridSweep.Cases(full);
            var clock = Stopwatch.StartNew();
            var outcomes = GridSweep.RunAll(cases);
            double seconds = clock.Elapsed.TotalSeconds;
            var md = new StringBuilder();
            md.Append("# HookeRope integrator stability grid").Append(full ? "" : " (CI subset)").Append("\n\n");
            md.Append("Machine: ").Append(MachineInfo.Describe()).Append("\n\n");
            md.Append(string.Format(CultureInfo.InvariantCulture, "{0} cases in {1:F1} s.\n\n", cases.Count, seconds));
            md.Append("| integrator | cases | failed | largest energy gain (J) |\n|---|---:|---:|---:|\n");
            var summary = new Table().Border(TableBorder.Rounded).Title("HookeRope integrator grid" + (full ? "" : " (CI subset)"));
            summary.AddColumn("integrator");
            summary.AddColumn(new TableColumn("cases").RightAligned());
            summary.AddColumn(new TableColumn("failed").RightAligned());
            summary.AddColumn(new TableColumn("largest energy gain (J)").RightAligned());
            int failedAll = 0;
            foreach (var integrator in new[] { TimeIntegrator.BackwardEuler, TimeIntegrator.Bdf2 })
            {
                int count = 0, failed = 0;
                double gain = 0.0;
                foreach (var o in outcomes)
                {
                    if (o.Case.Integrator != integrator) continue;
                    count++;
                    if (o.Failed) failed++;
                    if (o.EnergyGain > gain) gain = o.EnergyGain;
                }
                failedAll += failed;
                string g = gain.ToString("G3", CultureInfo.InvariantCulture);
                summary.AddRow(integrator.ToString(), count.ToString(CultureInfo.InvariantCulture), failed == 0 ? "[green]0[/]" : $"[red]{failed}[/]", g);
                md.Append(string.Format(CultureInfo.InvariantCulture, "| {0} | {1} | {2} | {3} |\n", integrator, count, failed, g));
            }
            console.Write(summary);
            md.Append("\n## Failures\n\n");
            if (failedAll == 0) md.Append("None.\n");
            else
            {
                var failures = new Table().Border(TableBorder.Rounded).Title("failures");
                failures.AddColumn("case");
                failures.AddColumn("why");
                md.Append("| case | why |\n|---|---|\n");
                foreach (var o in outcomes)
                {
                    if (!o.Failed) continue;
                    failures.AddRow(Markup.Escape(o.Case.ToString()), Markup.Escape(o.Reason));
                    md.Append("| ").Append(o.Case).Append(" | ").Append(o.Reason).Append(" |\n");
                }
                console.Write(failures);
            }
            string path = Path.Combine(outDir, full ? "stability-grid.md" : "stability-grid-ci.md");
            File.WriteAllText(path, md.ToString());
            console.MarkupLine($"{cases.Count - failedAll} of {cases.Count} cases stable in {seconds:F1} s, " +
                (failedAll == 0 ? "[green]0 failed[/]" : $"[red]{failedAll} failed[/]") + "; [grey]wrote[/] " + Markup.Escape(path));
            return failedAll == 0 ? 0 : 1;
        }
    }
}
