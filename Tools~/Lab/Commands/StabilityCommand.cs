using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using HookeRope.Lab.Report;
using HookeRope.Lab.Stability;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary><c>stability</c>: the extreme-case sweep as a table; exit code 1 if any case fails.</summary>
    public static class StabilityCommand
    {
        /// <summary>Runs the sweep, prints the table and writes stability.md to <paramref name="outDir"/>; <paramref name="progress"/> gets periodic lines with an ETA when the console is not interactive.</summary>
        public static int Execute(IAnsiConsole console, string outDir, bool quick, TextWriter progress = null)
        {
            OutputFolder.Ensure(outDir);
            var cases = StabilitySweep.Cases(quick);
            var outcomes = new List<StabilityOutcome>();
            if (console.Profile.Capabilities.Interactive)
            {
                console.Progress().Start(ctx =>
                {
                    var task = ctx.AddTask("stability cases", maxValue: cases.Count);
                    foreach (var c in cases)
                    {
                        outcomes.Add(StabilitySweep.Run(c));
                        task.Increment(1);
                    }
                });
            }
            else
            {
                var lines = progress == null ? null : new ProgressLines("stability cases", cases.Count, progress);
                foreach (var c in cases)
                {
                    outcomes.Add(StabilitySweep.Run(c));
                    lines?.Report(outcomes.Count);
                }
            }
            var table = new Table().Border(TableBorder.Rounded).Title("HookeRope stability sweep" + (quick ? " (quick)" : ""));
            table.AddColumn("case");
            table.AddColumn("NaN");
            table.AddColumn("energy blow-up");
            table.AddColumn(new TableColumn("motion energy rise (J)").RightAligned());
            table.AddColumn("settled");
            table.AddColumn(new TableColumn("max constraint error").RightAligned());
            table.AddColumn("result");
            var md = new StringBuilder();
            md.Append("# HookeRope stability sweep").Append(quick ? " (quick)" : "").Append("\n\n");
            md.Append("Machine: ").Append(MachineInfo.Describe()).Append("\n\n");
            md.Append("| case | NaN | energy blow-up | motion energy rise (J) | settled | max constraint error | result |\n|---|---|---|---:|---|---:|---|\n");
            int failed = 0;
            foreach (var o in outcomes)
            {
                if (o.Failed) failed++;
                string energy = o.Case.DrivenAnchor ? "n/a (driven anchor)" : o.EnergyBlowUp ? "YES" : "no";
                string error = o.MaxConstraintError.ToString("G3", CultureInfo.InvariantCulture);
                table.AddRow(Markup.Escape(o.Case.Name), o.NonFinite ? "[red]YES[/]" : "no",
                    o.EnergyBlowUp ? "[red]YES[/]" : Markup.Escape(energy), o.EnergyRise.ToString("G3", CultureInfo.InvariantCulture), o.Settled ? "yes" : "[yellow]no[/]", error,
                    o.Failed ? "[red]FAIL[/]" : "[green]ok[/]");
                md.Append("| ").Append(o.Case.Name).Append(" | ").Append(o.NonFinite ? "YES" : "no").Append(" | ").Append(energy)
                  .Append(" | ").Append(o.EnergyRise.ToString("G3", CultureInfo.InvariantCulture)).Append(" | ").Append(o.Settled ? "yes" : "no").Append(" | ").Append(error).Append(" | ")
                  .Append(o.Failed ? "FAIL" : "ok").Append(" |\n");
            }
            console.Write(table);
            string path = Path.Combine(outDir, quick ? "stability-quick.md" : "stability.md");
            File.WriteAllText(path, md.ToString());
            console.MarkupLine($"{outcomes.Count - failed} of {outcomes.Count} cases stable, " +
                (failed == 0 ? "[green]0 failed[/]" : $"[red]{failed} failed[/]") + "; [grey]wrote[/] " + Markup.Escape(path));
            return failed == 0 ? 0 : 1;
        }
    }
}
