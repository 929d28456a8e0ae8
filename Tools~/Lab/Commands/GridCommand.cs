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
    /// <summary>
    /// <c>stability --full</c>: the integrator grid (<see cref="GridSweep"/>), a summary per family and integrator, the
    /// documented domain limits (<see cref="GridLimits"/>) and a table of every failing case with the limit it falls under;
    /// exit code 1 if any case fails: since every case of the full grid passes (issue 14 item 4), a documented limit names a
    /// failure's known cause, it no longer excuses it.
    /// </summary>
    public static class GridCommand
    {
        /// <summary>"n (p %)": a count and its share of the substeps.</summary>
        private static string Share(long n, long substeps) =>
            string.Format(CultureInfo.InvariantCulture, "{0} ({1:G2} %)", n, 100.0 * n / System.Math.Max(substeps, 1));

        /// <summary>
        /// True when the case's description contains one of the '|'-separated alternatives of <paramref name="match"/> (an
        /// alternative ending in '$' must be the whole description).
        /// </summary>
        private static bool Matches(string description, string match)
        {
            foreach (string alternative in match.Split('|'))
            {
                if (alternative.Length == 0) continue;
                if (alternative[alternative.Length - 1] == '$' ? description == alternative.Substring(0, alternative.Length - 1)
                    : description.Contains(alternative, System.StringComparison.Ordinal)) return true;
            }
            return false;
        }

        /// <summary>
        /// Runs the grid (whole, or the CI subset; only the cases whose description contains <paramref name="match"/> when
        /// given), prints and writes stability-grid.md (or stability-grid-ci.md) to <paramref name="outDir"/>.
        /// </summary>
        public static int Execute(IAnsiConsole console, string outDir, bool full, string match = null)
        {
            OutputFolder.Ensure(outDir);
            var cases = GridSweep.Cases(full);
            if (!string.IsNullOrEmpty(match)) cases.RemoveAll(c => !Matches(c.ToString(), match));
            var clock = Stopwatch.StartNew();
            var outcomes = GridSweep.RunAll(cases);
            double seconds = clock.Elapsed.TotalSeconds;
            var md = new StringBuilder();
            md.Append("# HookeRope integrator stability grid").Append(full ? "" : " (CI subset)").Append("\n\n");
            md.Append("Machine: ").Append(MachineInfo.Describe()).Append("\n\n");
            md.Append(string.Format(CultureInfo.InvariantCulture, "{0} cases in {1:F1} s.\n\n", cases.Count, seconds));
            md.Append("| family | integrator | cases | failed | documented limit | largest energy gain (J) | largest gain / round-off bound | iterations / substep | violent substeps | shortened steps | unconverged substeps |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
            var summary = new Table().Border(TableBorder.Rounded).Title("HookeRope integrator grid" + (full ? "" : " (CI subset)"));
            summary.AddColumn("family");
            summary.AddColumn("integrator");
            summary.AddColumn(new TableColumn("cases").RightAligned());
            summary.AddColumn(new TableColumn("failed").RightAligned());
            summary.AddColumn(new TableColumn("documented limit").RightAligned());
            summary.AddColumn(new TableColumn("largest energy gain (J)").RightAligned());
            summary.AddColumn(new TableColumn("largest gain / round-off bound").RightAligned());
            summary.AddColumn(new TableColumn("iterations / substep").RightAligned());
            summary.AddColumn(new TableColumn("violent substeps").RightAligned());
            summary.AddColumn(new TableColumn("shortened steps").RightAligned());
            summary.AddColumn(new TableColumn("unconverged substeps").RightAligned());
            int failedAll = 0, limitedAll = 0;
            foreach (var family in new[] { GridFamily.Undamped, GridFamily.Friction, GridFamily.Settle, GridFamily.Teleport })
                foreach (var integrator in new[] { TimeIntegrator.BackwardEuler, TimeIntegrator.Bdf2 })
                {
                    int count = 0, failed = 0, limited = 0;
                    double gain = 0.0, relative = 0.0;
                    long substeps = 0, iterations = 0, violent = 0, shortened = 0, unconverged = 0;
                    foreach (var o in outcomes)
                    {
                        if (o.Case.Integrator != integrator || o.Case.Family != family) continue;
                        count++;
                        if (o.Undocumented) failed++;
                        else if (o.Failed) limited++;
                        if (o.EnergyGain > gain) gain = o.EnergyGain;
                        double r = o.EnergyGain / System.Math.Max(o.RoundOff, 1e-300);
                        if (r > relative) relative = r;
                        substeps += o.Substeps; iterations += o.SolveIterations; violent += o.ViolentSubsteps;
                        shortened += o.ShortenedSteps; unconverged += o.UnconvergedSubsteps;
                    }
                    if (count == 0) continue;
                    failedAll += failed;
                    limitedAll += limited;
                    string g = gain.ToString("G3", CultureInfo.InvariantCulture), rel = relative.ToString("G3", CultureInfo.InvariantCulture);
                    string its = ((double)iterations / System.Math.Max(substeps, 1)).ToString("F3", CultureInfo.InvariantCulture);
                    string v = Share(violent, substeps), sh = shortened.ToString(CultureInfo.InvariantCulture), u = Share(unconverged, substeps);
                    summary.AddRow(family.ToString(), integrator.ToString(), count.ToString(CultureInfo.InvariantCulture), failed == 0 ? "[green]0[/]" : $"[red]{failed}[/]",
                        limited.ToString(CultureInfo.InvariantCulture), g, rel, its, v, sh, u);
                    md.Append(string.Format(CultureInfo.InvariantCulture, "| {0} | {1} | {2} | {3} | {4} | {5} | {6} | {7} | {8} | {9} | {10} |\n", family, integrator, count, failed, limited, g, rel, its, v, sh, u));
                }
            console.Write(summary);
            md.Append("\n## Documented domain limits\n\n");
            foreach (string limit in GridLimits.All)
            {
                int n = 0;
                foreach (var o in outcomes) if (o.Limit == limit) n++;
                md.Append(GridLimits.ReportLine(limit, n)).Append('\n');
            }
            md.Append("\n## Failures (every failing case; the limit column names the documented limit it falls under)\n\n");
            if (failedAll + limitedAll == 0) md.Append("None.\n");
            else
            {
                var failures = new Table().Border(TableBorder.Rounded).Title("failures");
                failures.AddColumn("case");
                failures.AddColumn("why");
                failures.AddColumn("documented limit");
                md.Append("| case | why | documented limit |\n|---|---|---|\n");
                foreach (var o in outcomes)
                {
                    if (!o.Failed) continue;
                    string limit = o.Limit == null ? "none: undocumented failure" : GridLimits.Name(o.Limit);
                    failures.AddRow(Markup.Escape(o.Case.ToString()), Markup.Escape(o.Reason), Markup.Escape(limit));
                    md.Append("| ").Append(o.Case).Append(" | ").Append(o.Reason).Append(" | ").Append(limit).Append(" |\n");
                }
                console.Write(failures);
            }
            string path = Path.Combine(outDir, full ? "stability-grid.md" : "stability-grid-ci.md");
            File.WriteAllText(path, md.ToString());
            console.MarkupLine($"{cases.Count - failedAll - limitedAll} of {cases.Count} cases stable in {seconds:F1} s, {limitedAll} within documented domain limits, " +
                (failedAll == 0 ? "[green]0 undocumented failures[/]" : $"[red]{failedAll} undocumented failures[/]") + "; [grey]wrote[/] " + Markup.Escape(path));
            return failedAll + limitedAll == 0 ? 0 : 1;
        }
    }
}
