using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;

namespace HookeRope.Lab.Report
{
    /// <summary>One reference case measured at one fixed step.</summary>
    public sealed class StepAccuracyRow
    {
        /// <summary>Case name.</summary>
        public string Case;
        /// <summary>Quantity compared (the check's).</summary>
        public string Quantity;
        /// <summary>Unit of <see cref="Measured"/> and <see cref="Expected"/>.</summary>
        public string Unit;
        /// <summary>Host (fixed) step, s.</summary>
        public double Step;
        /// <summary>Simulated value.</summary>
        public double Measured;
        /// <summary>Analytic value.</summary>
        public double Expected;
        /// <summary>Formula of the analytic value.</summary>
        public string Formula;

        /// <summary>Signed relative error (measured − expected)/expected.</summary>
        public double SignedError => (Measured - Expected) / Expected;

        /// <summary>|<see cref="SignedError"/>|, ∞ for a non-finite measurement.</summary>
        public double Error => double.IsFinite(Measured) ? Math.Abs(SignedError) : double.PositiveInfinity;
    }

    /// <summary>
    /// Accuracy of the package defaults against analytic answers at a given fixed step: the step the defaults were
    /// validated at (1/90 s) against Unity's default Fixed Timestep (0.02 s). Cases: the fall arrest of a 100 kg worker
    /// after a 4 m free fall on the package-default lanyard (peak arrest force; damping 0 so the massless energy balance
    /// is the exact answer) and on the lab's default fall-arrest scenario; a 100 kg load hanging on the default lanyard
    /// with the default damping (static stretch, and its period from the release); the spring–mass reference (10 kg on a light 10 kN spring, period).
    /// Every case uses the default solver: exact chain, 8 substeps × 1 iteration.
    /// </summary>
    public static class FixedStepAccuracy
    {
        /// <summary>The step the defaults were validated at (s): the lab report's recommendation is made at 90 Hz.</summary>
        public const double ValidatedStep = 1.0 / 90.0;
        /// <summary>Unity's default Fixed Timestep (s).</summary>
        public const double UnityDefaultStep = 0.02;

        /// <summary>Case names, in table order.</summary>
        public static readonly string[] CaseNames =
        {
            "default lanyard: fall arrest", "lab fall-arrest scenario", "default lanyard: static hang", "default lanyard: period", "spring–mass reference",
        };

        /// <summary>The scenario of case <paramref name="name"/> at fixed step <paramref name="step"/> (s).</summary>
        public static Scenario Case(string name, double step)
        {
            Scenario s;
            switch (name)
            {
                case "default lanyard: fall arrest":
                    s = DefaultLanyard(duration: 3.0);
                    s.Solver.Damping = 0;
                    s.Initial = new InitialSpec { Shape = InitialShape.Slack, FallHeight = 4.0 };
                    s.Expect.Check = "fall-arrest";
                    break;
                case "lab fall-arrest scenario":
                    s = BuiltInScenarios.Load("fall-arrest");
                    break;
                case "default lanyard: static hang":
                    s = DefaultLanyard(duration: 20.0);
                    s.Expect.Check = "static-hang";
                    break;
                case "default lanyard: period":
                    s = DefaultLanyard(duration: 6.0);
                    s.Expect.Check = "period";
                    break;
                case "spring–mass reference":
                    s = BuiltInScenarios.Load("spring-oscillator");
                    break;
                default:
                    throw new ArgumentException("unknown case " + name, nameof(name));
            }
            s.HostStep = step;
            s.Outputs = new OutputSpec();
            return s;
        }

        /// <summary>The package-default rope (RopeParameters defaults, default solver) with a 100 kg body at its end.</summary>
        static Scenario DefaultLanyard(double duration)
        {
            var s = new Scenario { Name = "default-lanyard", Duration = duration };
            s.Rope.PoissonThinning = false;
            s.Rope.Necking = false;
            s.Rope.Fracture = false;
            s.End = new AttachmentSpec { Kind = AttachmentKind.Body, Mass = 100 };
            return s;
        }

        /// <summary>Runs every case at <paramref name="step"/> (s) and returns its primary check.</summary>
        public static List<StepAccuracyRow> Measure(double step)
        {
            var rows = new List<StepAccuracyRow>();
            foreach (var name in CaseNames)
            {
                var run = ScenarioRunner.Run(Case(name, step), RunOptions.Lean());
                var check = PhysicsChecks.Evaluate(run)[0];
                rows.Add(new StepAccuracyRow
                {
                    Case = name, Quantity = check.Quantity, Unit = check.Unit, Step = step,
                    Measured = run.NonFinite ? double.NaN : check.Measured, Expected = check.Expected, Formula = check.Formula,
                });
            }
            return rows;
        }

        /// <summary>A Markdown table of <paramref name="steps"/> side by side (one column pair per step).</summary>
        public static string Markdown(IList<double> steps)
        {
            var columns = new List<List<StepAccuracyRow>>();
            foreach (var step in steps) columns.Add(Measure(step));
            var md = new StringBuilder();
            md.Append("| case | quantity | analytic |");
            foreach (var step in steps) md.Append(" at ").Append(StepLabel(step)).Append(" | error |");
            md.AppendLine();
            md.Append("|---|---|---:|");
            foreach (var _ in steps) md.Append("---:|---:|");
            md.AppendLine();
            for (int i = 0; i < CaseNames.Length; i++)
            {
                var first = columns[0][i];
                md.Append("| ").Append(first.Case).Append(" | ").Append(first.Quantity).Append(" | ").Append(Value(first.Expected, first.Unit)).Append(" |");
                foreach (var column in columns)
                {
                    var row = column[i];
                    md.Append(' ').Append(Value(row.Measured, row.Unit)).Append(" | ")
                      .Append((row.SignedError * 100).ToString("+0.00;−0.00", CultureInfo.InvariantCulture)).Append(" % |");
                }
                md.AppendLine();
            }
            return md.ToString();
        }

        /// <summary>"1/90 s" for 1/90, else "0.02 s".</summary>
        public static string StepLabel(double step)
        {
            double hz = 1.0 / step;
            return Math.Abs(hz - Math.Round(hz)) < 1e-6 && Math.Abs(step * 100 - Math.Round(step * 100)) > 1e-9
                ? "1/" + Math.Round(hz).ToString(CultureInfo.InvariantCulture) + " s"
                : step.ToString("0.###", CultureInfo.InvariantCulture) + " s";
        }

        static string Value(double v, string unit) => unit == "m"
            ? (v * 1000).ToString("0.000", CultureInfo.InvariantCulture) + " mm"
            : v.ToString("G5", CultureInfo.InvariantCulture) + " " + unit;
    }
}
