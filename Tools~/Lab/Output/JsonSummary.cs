using System.Collections.Generic;
using System.IO;
using System.Text;
using System.Text.Encodings.Web;
using System.Text.Json;
using HookeRope.Lab.Simulation;

namespace HookeRope.Lab.Output
{
    /// <summary>
    /// The machine-readable summary of a run (NAME-summary.json and <c>run --json</c>): every quantity the
    /// one-screen summary reports, at full double precision, SI units in the key names; null when not measured.
    /// </summary>
    public static class JsonSummary
    {
        /// <summary>The summary as indented JSON text.</summary>
        public static string Text(RunResult result, ConvergenceVerdict verdict, IList<CheckResult> checks, IList<string> files)
        {
            using (var stream = new MemoryStream())
            {
                using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true, Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping }))
                    Write(w, result, verdict, checks, files);
                return Encoding.UTF8.GetString(stream.ToArray());
            }
        }

        static void Write(Utf8JsonWriter w, RunResult r, ConvergenceVerdict v, IList<CheckResult> checks, IList<string> files)
        {
            var s = r.Scenario;
            w.WriteStartObject();
            w.WriteString("scenario", s.Name);
            w.WriteString("solver", s.Solver.Method == Scenarios.SolverMethod.ExactChain ? "exact-chain" : "gauss-seidel");
            w.WriteString("integrator", Scenarios.SolverSpec.IntegratorJson(s.Solver.Integrator));
            w.WriteNumber("substeps", s.Solver.Substeps);
            w.WriteNumber("iterations", s.Solver.Iterations);
            Number(w, "hostStep_s", s.HostStep);
            Number(w, "duration_s", s.Duration);
            w.WriteStartObject("verdict");
            w.WriteString("kind", v.Word);
            w.WriteString("reason", v.Reason);
            w.WriteString("advice", v.Advice);
            Number(w, "unconvergedStepFraction", v.UnconvergedFraction);
            Number(w, "divergedStepFraction", v.DivergedFraction);
            w.WriteEndObject();
            Number(w, "peakAnchorForce_N", r.PeakTopForce);
            Number(w, "peakLoadForce_N", r.PeakLoadForce);
            Number(w, "tautTime_s", r.TautTime);
            Number(w, "freeFallBeforeTaut_m", double.IsNaN(r.TautTime) ? double.NaN : r.TotalDrop - r.ArrestDistance);
            Number(w, "arrestDistance_m", double.IsNaN(r.TautTime) ? double.NaN : r.ArrestDistance);
            Number(w, "maxElongation_m", r.MaxElongation);
            Number(w, "maxStrain", r.MaxElongation / s.Rope.RestLength);
            Number(w, "minRadius_m", SummaryView.MinRadius(r));
            Number(w, "restRadius_m", s.Rope.Radius);
            w.WriteBoolean("broken", !double.IsNaN(r.BreakTime));
            Number(w, "breakTime_s", r.BreakTime);
            Number(w, "breakTension_N", r.BreakTension);
            w.WriteBoolean("brokenDuringConstruction", r.BrokenAtConstruction);
            Number(w, "maxResidual", r.MaxResidual);
            w.WriteBoolean("nonFinite", r.NonFinite);
            Number(w, "wallTime_s", r.WallSeconds);
            w.WriteNumber("hostSteps", r.Steps);
            if (v.Converged && s.IsFallArrest)
            {
                w.WriteStartObject("limits");
                w.WriteBoolean("en355_6kN", r.PeakTopForce <= Plots.En355Limit);
                w.WriteBoolean("ansiOsha_8kN", r.PeakTopForce <= Plots.OshaLimit);
                w.WriteBoolean("oshaDecelerationDistance_1_07m", r.ArrestDistance <= SummaryView.OshaDecelerationDistance);
                w.WriteEndObject();
            }
            else w.WriteNull("limits");
            w.WriteStartArray("events");
            foreach (var e in r.Events)
            {
                w.WriteStartObject();
                Number(w, "time_s", e.Time);
                w.WriteString("what", e.What);
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteStartArray("checks");
            foreach (var c in checks)
            {
                w.WriteStartObject();
                w.WriteString("quantity", c.Quantity);
                w.WriteString("unit", c.Unit);
                Number(w, "measured", c.Measured);
                Number(w, "expected", c.Expected);
                Number(w, "relativeError", c.Absolute ? double.NaN : c.Error);
                Number(w, "tolerance", c.Tolerance);
                w.WriteBoolean("passed", c.Passed);
                w.WriteString("formula", c.Formula);
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteStartArray("files");
            foreach (var f in files) w.WriteStringValue(f);
            w.WriteEndArray();
            w.WriteEndObject();
        }

        /// <summary>A number at full precision (shortest round-trip form), null when not finite; −0 is written as 0.</summary>
        static void Number(Utf8JsonWriter w, string name, double value)
        {
            if (!double.IsFinite(value)) w.WriteNull(name);
            else w.WriteNumber(name, value == 0 ? 0.0 : value);
        }
    }
}
