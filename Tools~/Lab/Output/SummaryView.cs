using System;
using System.Collections.Generic;
using System.Globalization;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using Spectre.Console;

namespace HookeRope.Lab.Output
{
    /// <summary>The one-screen summary of a run (Spectre.Console table).</summary>
    public static class SummaryView
    {
        static readonly CultureInfo Invariant = CultureInfo.InvariantCulture;

        /// <summary>" · drag …" naming the drag terms that act and the wind, or "" without drag.</summary>
        static string DragText(DragSpec d)
        {
            if (!d.Acts) return "";
            var parts = new List<string>();
            if (d.ViscousDrag > 0) parts.Add(string.Format(Invariant, "c {0:G4} N·s/m²", d.ViscousDrag));
            if (d.AirDensity > 0 && d.DragCoefficient > 0) parts.Add(string.Format(Invariant, "C_d {0:G4}", d.DragCoefficient));
            if (d.AirDensity > 0 && d.SkinFriction > 0) parts.Add(string.Format(Invariant, "C_f {0:G4}", d.SkinFriction));
            if (d.AirDensity > 0 && (d.DragCoefficient > 0 || d.SkinFriction > 0)) parts.Add(string.Format(Invariant, "ρ {0:G4} kg/m³", d.AirDensity));
            if (d.Blows) parts.Add(string.Format(Invariant, "wind [{0:G4}, {1:G4}, {2:G4}] m/s", d.Wind.X, d.Wind.Y, d.Wind.Z));
            return " · drag " + string.Join(", ", parts);
        }

        /// <summary>Prints the summary of <paramref name="result"/> and the files written.</summary>
        public static void Print(IAnsiConsole console, RunResult result, ConvergenceVerdict verdict, IList<CheckResult> checks, IList<string> files)
        {
            var s = result.Scenario;
            console.Write(new Rule($"[bold]HookeRope lab · {Markup.Escape(s.Name)}[/]").LeftJustified());
            if (s.Description.Length > 0) console.MarkupLine("[grey]" + Markup.Escape(s.Description) + "[/]");
            console.MarkupLine(Markup.Escape(string.Format(Invariant,
                "{0} · {10} · {1} segments · E·A {2} · μ {3} kg/m · {4} substep{8} × {5} iteration{9} · host step {6:G4} ms · {7:G4} s simulated",
                s.Solver.Method == SolverMethod.ExactChain ? "exact chain" : "Gauss–Seidel", s.Rope.Segments,
                Force(s.Rope.ResolvedAxialStiffness), Num(s.Rope.ResolvedLinearDensity), s.Solver.Substeps, s.Solver.Iterations,
                s.HostStep * 1000, s.Duration, s.Solver.Substeps == 1 ? "" : "s", s.Solver.Iterations == 1 ? "" : "s",
                s.Solver.Integrator == HookeRope.Solver.TimeIntegrator.Bdf2 ? "BDF2" : "backward Euler") + DragText(s.Drag)));

            console.MarkupLine(VerdictLine(verdict));
            bool limits = verdict.Converged && s.IsFallArrest;
            string notAssessed = s.IsFallArrest ? "[yellow]limits not assessed: the run " + verdict.Word + "[/]" : "";

            var table = new Table().Border(TableBorder.Rounded);
            table.AddColumn("quantity");
            table.AddColumn(new TableColumn("value").RightAligned());
            table.AddColumn("reference");
            table.AddRow("peak anchor force", Force(result.PeakTopForce), limits ? Limits(result.PeakTopForce) : notAssessed);
            table.AddRow("peak force on the load", Force(result.PeakLoadForce), "");
            if (!double.IsNaN(result.TautTime))
            {
                table.AddRow("rope taut at", Num(result.TautTime) + " s", "");
                table.AddRow("free fall before taut", Num(result.TotalDrop - result.ArrestDistance) + " m", "");
                table.AddRow("arrest distance (taut → lowest)", Num(result.ArrestDistance) + " m",
                    !limits ? "" : result.ArrestDistance <= OshaDecelerationDistance
                        ? "[green]≤ 1.07 m OSHA deceleration distance[/]" : "[yellow]> 1.07 m OSHA deceleration distance[/]");
            }
            table.AddRow("max elongation", Num(result.MaxElongation) + " m",
                Markup.Escape("strain " + Percent(result.MaxElongation / s.Rope.RestLength))
                + (verdict.Kind == Convergence.Diverged ? " [red](diverged: not physical)[/]" : ""));
            if (result.Samples.Count > 0)
                table.AddRow("min radius", Num(MinRadius(result) * 1000) + " mm", Markup.Escape(string.Format(Invariant, "rest radius {0:G4} mm", s.Rope.Radius * 1000)));
            table.AddRow("broken", double.IsNaN(result.BreakTime) ? "no" : "[red]yes[/]",
                double.IsNaN(result.BreakTime) ? "" : result.BrokenAtConstruction
                    ? Markup.Escape("while the rope was built: its initial stretch is past the break criterion, tension " + Force(result.BreakTension))
                    : Markup.Escape(string.Format(Invariant, "at {0:G4} s, tension {1} before", result.BreakTime, Force(result.BreakTension))));
            foreach (var e in result.Events)
                table.AddRow("event at " + Num(e.Time) + " s", "", Markup.Escape(e.What));
            foreach (var check in checks)
            {
                string value = check.Unit.Length > 0 ? Num(check.Measured) + " " + check.Unit : Num(check.Measured);
                string reference = string.Format(Invariant, "{0} {1} {2} ({3})", check.Passed ? "[green]✓[/]" : "[red]✗[/]",
                    Markup.Escape(Num(check.Expected) + (check.Unit.Length > 0 ? " " + check.Unit : "")),
                    Markup.Escape(check.Absolute ? "" : "error " + (double.IsFinite(check.Error) ? (check.Error * 100).ToString("0.00", Invariant) + " %" : "n/a")),
                    Markup.Escape(check.Formula));
                table.AddRow("check: " + Markup.Escape(check.Quantity), value, reference);
            }
            table.AddRow("solver residual (max)", Num(result.MaxResidual), Markup.Escape(string.Format(Invariant,
                "strain error > {0} on {1} of the host steps", Percent(ConvergenceVerdict.UnconvergedStrainError), Percent(verdict.UnconvergedFraction))));
            table.AddRow("wall time", Num(result.WallSeconds * 1000) + " ms",
                Markup.Escape(string.Format(Invariant, "{0} host steps, {1:G3}× real time", result.Steps,
                    result.Steps * s.HostStep / Math.Max(result.WallSeconds, 1e-9))));
            console.Write(table);
            if (!verdict.Converged) console.MarkupLine("[bold]what to change:[/] " + Markup.Escape(verdict.Advice));
            foreach (var file in files) console.MarkupLine("[grey]wrote[/] " + Markup.Escape(file));
        }

        /// <summary>Smallest radius over the recorded samples in m (NaN without samples).</summary>
        public static double MinRadius(RunResult result)
        {
            double min = double.NaN;
            foreach (var sample in result.Samples) if (!(sample.MinRadius >= min)) min = sample.MinRadius;
            return min;
        }

        /// <summary>OSHA 1926.502(d)(16)(iv): the deceleration distance of a personal fall arrest system is at most 1.07 m.</summary>
        public const double OshaDecelerationDistance = 1.07;

        /// <summary>The verdict in one line: word, colour and reason.</summary>
        public static string VerdictLine(ConvergenceVerdict verdict)
        {
            string colour = verdict.Kind == Convergence.Converged ? "green" : verdict.Kind == Convergence.Unconverged ? "yellow" : "red";
            return $"[bold {colour}]verdict: {verdict.Word}[/] — " + Markup.Escape(verdict.Reason);
        }

        static string Limits(double force)
        {
            string en = force <= Plots.En355Limit ? "[green]≤ 6 kN EN 355[/]" : "[red]> 6 kN EN 355[/]";
            string osha = force <= Plots.OshaLimit ? "[green]≤ 8 kN ANSI/OSHA[/]" : "[red]> 8 kN ANSI/OSHA[/]";
            return en + " · " + osha;
        }

        /// <summary>A force in N or kN with 3–4 significant digits.</summary>
        public static string Force(double newtons) => Math.Abs(newtons) >= 1000
            ? (newtons / 1000).ToString("G4", Invariant) + " kN"
            : newtons.ToString("G4", Invariant) + " N";

        /// <summary>A fraction as a percentage with one decimal and no digit grouping ("109.7 %").</summary>
        public static string Percent(double fraction) => (fraction * 100).ToString("0.0", Invariant) + " %";

        /// <summary>A number with 4 significant digits, invariant culture.</summary>
        public static string Num(double value) => value.ToString("G4", Invariant);
    }
}
