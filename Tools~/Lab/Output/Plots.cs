using System;
using System.Collections.Generic;
using System.Globalization;
using HookeRope.Lab.Simulation;
using ScottPlot;

namespace HookeRope.Lab.Output
{
    /// <summary>
    /// PNG/SVG plots of a run (ScottPlot 5, headless SkiaSharp), chosen by the scenario: force against time
    /// (autoscaled, analytic references), for fall arrests the load displacement and the limits, for ropes whose
    /// radius changes the radius at the defect against time and the profiles at the moments that matter. Each
    /// builder returns the <see cref="Plot"/> so tests can read back its axes, labels and lines.
    /// </summary>
    public static class Plots
    {
        /// <summary>EN 355 energy-absorber limit, N.</summary>
        public const double En355Limit = 6000;
        /// <summary>ANSI Z359 / OSHA 1926.502 maximum arrest force, N.</summary>
        public const double OshaLimit = 8000;
        /// <summary>A radius plot is drawn only when the smallest radius falls below this fraction of R (else it is a flat line).</summary>
        public const double RadiusChangeFraction = 0.995;

        static readonly CultureInfo Invariant = CultureInfo.InvariantCulture;

        /// <summary>Writes the plots the scenario calls for under <paramref name="stem"/>; returns the files written.</summary>
        public static List<string> WriteAll(RunResult r, ConvergenceVerdict verdict, IList<CheckResult> checks, string stem, bool svg)
        {
            var files = new List<string>();
            void Save(Plot plot, string suffix, int width, int height)
            {
                plot.SavePng(stem + suffix + ".png", width, height);
                files.Add(stem + suffix + ".png");
                if (svg) plot.SaveSvg(stem + suffix + ".svg", width, height);
            }
            Save(Force(r, verdict, checks), "-force", 1000, 560);
            if (r.Scenario.IsFallArrest && !double.IsNaN(r.TautTime)) Save(Displacement(r, verdict), "-displacement", 1000, 560);
            if (HasMaterialLaw(r)) Save(ForceElongation(r), "-force-elongation", 1000, 560);
            if (RadiusChanges(r))
            {
                Save(DefectRadius(r), "-neck", 1000, 500);
                if (ProfilesVary(r)) Save(RadiusProfiles(r), "-radius", 1000, 500);
            }
            return files;
        }

        /// <summary>True when some radius profile varies along the rope by more than 0.5 % of R (a uniformly thinned rope gives flat profiles: the radius-against-time plot says it all).</summary>
        public static bool ProfilesVary(RunResult r)
        {
            var all = new List<RadiusProfile>(r.KeyProfiles);
            all.AddRange(r.Profiles);
            foreach (var p in all)
            {
                double min = double.PositiveInfinity, max = double.NegativeInfinity;
                foreach (var v in p.Radius) { min = Math.Min(min, v); max = Math.Max(max, v); }
                if (max - min > (1 - RadiusChangeFraction) * r.Scenario.Rope.Radius) return true;
            }
            return false;
        }

        /// <summary>True when the rope has a material law beyond Hooke's (issue 15): the elastic–plastic material or an energy absorber.</summary>
        public static bool HasMaterialLaw(RunResult r) => r.Scenario.Rope.IsPlastic || r.Scenario.Rope.EnergyAbsorber;

        /// <summary>
        /// Force against elongation (issue 15): the anchor force (first segment) against the rope's elongation at every sample,
        /// the material law's quasi-static curve (<see cref="HookeRope.Solver.ForceElongationCurve"/>) dashed, and for a plastic
        /// rope the neck onset and the break, for an absorber its plateau and EN 355's 6 kN. Samples after a break are left out
        /// (the pieces' elongation is not the rope's).
        /// </summary>
        public static Plot ForceElongation(RunResult r)
        {
            var rope = r.Scenario.Rope;
            var curve = HookeRope.Solver.ForceElongationCurve.Of(Simulation.ScenarioRunner.Settings(r.Scenario), rope.IsPlastic ? 1.0 : 0.5);
            int n = 0;   // the intact samples: after a break the elongation is that of the pieces
            while (n < r.Samples.Count && !r.Samples[n].Broken) n++;
            double peak = 0;
            for (int i = 0; i < n; i++) peak = Math.Max(peak, r.Samples[i].TopTension);
            bool kilo = Math.Max(peak, curve.PeakForce) >= 1000;
            double scale = kilo ? 1e-3 : 1;
            var e = new double[n];
            var f = new double[n];
            double longest = 0;
            for (int i = 0; i < n; i++)
            {
                e[i] = r.Samples[i].Elongation;
                f[i] = r.Samples[i].TopTension * scale;
                longest = Math.Max(longest, e[i]);
            }
            var plot = new Plot();
            var simulated = plot.Add.ScatterLine(e, f);
            simulated.LegendText = "simulated: anchor force against the rope's elongation";
            simulated.LineWidth = 2;
            var ce = new double[curve.Count];
            var cf = new double[curve.Count];
            for (int i = 0; i < curve.Count; i++)
            {
                ce[i] = curve.Elongation[i];
                cf[i] = curve.Force[i] * scale;
            }
            string unit = kilo ? "kN" : "N";
            var law = plot.Add.ScatterLine(ce, cf);
            law.LegendText = rope.IsPlastic
                ? $"material law, slow pull: yield {Num(curve.Force[1] * scale)} {unit}, neck onset {Num(curve.PeakForce * scale)} {unit}, zero force at {Num(curve.BreakElongation)} m"
                : $"material law, slow pull: plateau {Num(rope.AbsorberForce * scale)} {unit} over {Num(rope.AbsorberDeployment)} m";
            law.LinePattern = LinePattern.Dashed;
            law.LineWidth = 1.5f;
            law.Color = Colors.Green;
            double right = Math.Max(longest, double.IsNaN(curve.BreakElongation) ? longest : curve.BreakElongation);
            double high = peak;
            for (int i = 0; i < curve.Count; i++) if (curve.Elongation[i] <= right) high = Math.Max(high, curve.Force[i]);
            high *= scale;
            if (!double.IsNaN(r.BreakTime))
            {
                var at = plot.Add.VerticalLine(n > 0 ? e[n - 1] : 0, 1.5f, Colors.Red, LinePattern.Dotted);
                at.LegendText = $"break at {Num(r.BreakTime)} s (tension {SummaryView.Force(r.BreakTension)})";
            }
            if (rope.EnergyAbsorber)
            {
                var en = plot.Add.HorizontalLine(En355Limit * scale, 1.5f, Colors.Orange, LinePattern.Dashed);
                en.LegendText = "6 kN: EN 355 energy absorber";
                high = Math.Max(high, En355Limit * scale);
            }
            plot.Title($"{r.Scenario.Name}: force against elongation (peak {SummaryView.Force(peak)})");
            plot.XLabel("elongation of the rope (m)");
            plot.YLabel(kilo ? "force (kN)" : "force (N)");
            plot.Axes.SetLimits(0, Math.Max(right, 1e-3) * 1.05, 0, Math.Max(high, 1e-3) * 1.12);
            plot.ShowLegend(Alignment.UpperRight);
            return plot;
        }

        /// <summary>True when the smallest recorded radius fell below <see cref="RadiusChangeFraction"/>·R.</summary>
        public static bool RadiusChanges(RunResult r) => SummaryView.MinRadius(r) < RadiusChangeFraction * r.Scenario.Rope.Radius;

        /// <summary>
        /// Anchor force and force on the load against time, autoscaled (kN above 1 kN, else N), with the
        /// analytic force of each check in newtons as a dashed line; for a converged fall arrest the 6 kN / 8 kN limits.
        /// </summary>
        public static Plot Force(RunResult r, ConvergenceVerdict verdict, IList<CheckResult> checks)
        {
            double peak = Math.Max(r.PeakTopForce, r.PeakLoadForce);
            bool limits = r.Scenario.IsFallArrest && verdict.Converged;
            bool kilo = peak >= 1000 || limits;
            double scale = kilo ? 1e-3 : 1;
            int n = r.Samples.Count;
            var t = new double[n];
            var top = new double[n];
            var bottom = new double[n];
            for (int i = 0; i < n; i++)
            {
                t[i] = r.Samples[i].Time;
                top[i] = r.Samples[i].TopTension * scale;
                bottom[i] = r.Samples[i].BottomTension * scale;
            }
            var plot = new Plot();
            var a = plot.Add.ScatterLine(t, top);
            a.LegendText = "anchor force (first segment)";
            a.LineWidth = 2;
            var b = plot.Add.ScatterLine(t, bottom);
            b.LegendText = "force on the load (last segment)";
            b.LinePattern = LinePattern.Dotted;
            b.LineWidth = 2;
            double high = peak * scale, low = Math.Min(0, Min(top, bottom));
            foreach (var c in checks)
            {
                if (c.Unit != "N" || !double.IsFinite(c.Expected)) continue;
                var line = plot.Add.HorizontalLine(c.Expected * scale, 1.5f, Colors.Green, LinePattern.Dashed);
                line.LegendText = $"analytic {c.Quantity}: {Num(c.Expected * scale)} {(kilo ? "kN" : "N")} ({c.Formula})";
                high = Math.Max(high, c.Expected * scale);
            }
            if (limits)
            {
                var en = plot.Add.HorizontalLine(En355Limit * scale, 1.5f, Colors.Orange, LinePattern.Dashed);
                en.LegendText = "6 kN: EN 355 energy absorber";
                var osha = plot.Add.HorizontalLine(OshaLimit * scale, 1.5f, Colors.Red, LinePattern.Dashed);
                osha.LegendText = "8 kN: ANSI Z359 / OSHA 1926.502";
                high = Math.Max(high, OshaLimit * scale);
            }
            string note = verdict.Converged ? "" : $" — {verdict.Word.ToUpperInvariant()}: numbers not trustworthy";
            plot.Title($"{r.Scenario.Name}: force against time (peak {SummaryView.Force(peak)}){note}");
            plot.XLabel("time (s)");
            plot.YLabel(kilo ? "force (kN)" : "force (N)");
            if (high <= low) high = low + 1;
            plot.Axes.SetLimits(0, EndTime(r), low, high + 0.1 * (high - low));
            plot.ShowLegend(Alignment.UpperRight);
            return plot;
        }

        /// <summary>Fall arrest: drop of the load below its release point against time, with the taut instant and the 1.07 m OSHA deceleration distance past it (converged runs).</summary>
        public static Plot Displacement(RunResult r, ConvergenceVerdict verdict)
        {
            int n = r.LoadDrop.Length;
            var t = new double[n + 1];
            var drop = new double[n + 1];
            for (int k = 0; k < n; k++)
            {
                t[k + 1] = (k + 1) * r.HostStep;
                drop[k + 1] = r.LoadDrop[k];
            }
            var plot = new Plot();
            var line = plot.Add.ScatterLine(t, drop);
            line.LegendText = "load drop below the release point";
            line.LineWidth = 2;
            double tautDrop = r.TotalDrop - r.ArrestDistance;
            var taut = plot.Add.VerticalLine(r.TautTime, 1.5f, Colors.Gray, LinePattern.Dotted);
            taut.LegendText = $"rope taut at {Num(r.TautTime)} s (free fall {Num(tautDrop)} m)";
            double high = r.TotalDrop;
            if (verdict.Converged)
            {
                double limit = tautDrop + SummaryView.OshaDecelerationDistance;
                var osha = plot.Add.HorizontalLine(limit, 1.5f, Colors.Red, LinePattern.Dashed);
                osha.LegendText = $"taut + 1.07 m: OSHA deceleration distance (arrest distance {Num(r.ArrestDistance)} m)";
                high = Math.Max(high, limit);
            }
            plot.Title($"{r.Scenario.Name}: load displacement (lowest {Num(r.TotalDrop)} m below release)");
            plot.XLabel("time (s)");
            plot.YLabel("drop below release (m)");
            plot.Axes.SetLimits(0, EndTime(r), Math.Min(0, Min(drop, drop)), high * 1.1 + 1e-6);
            plot.Axes.InvertY();
            plot.ShowLegend(Alignment.LowerLeft);
            return plot;
        }

        /// <summary>Radius at the defect (neck included) and the smallest radius against time, with r_min, the break radius and the break instant where they apply.</summary>
        public static Plot DefectRadius(RunResult r)
        {
            var rope = r.Scenario.Rope;
            int n = r.Samples.Count;
            var t = new double[n];
            var neck = new double[n];
            var min = new double[n];
            for (int i = 0; i < n; i++)
            {
                t[i] = r.Samples[i].Time;
                neck[i] = r.Samples[i].NeckRadius * 1000;
                min[i] = r.Samples[i].MinRadius * 1000;
            }
            var plot = new Plot();
            var a = plot.Add.ScatterLine(t, neck);
            a.LegendText = $"radius at the defect ({Num(rope.DefectPosition)} of L)";
            a.LineWidth = 2;
            var b = plot.Add.ScatterLine(t, min);
            b.LegendText = "smallest radius";
            b.LinePattern = LinePattern.Dotted;
            var rest = plot.Add.HorizontalLine(rope.Radius * 1000, 1f, Colors.Gray, LinePattern.Dotted);
            rest.LegendText = $"rest radius R = {Num(rope.Radius * 1000)} mm";
            if (rope.Necking)
            {
                var onset = plot.Add.HorizontalLine(rope.NeckRadiusFraction * rope.Radius * 1000, 1.5f, Colors.Orange, LinePattern.Dashed);
                onset.LegendText = $"neck onset r_min = {Num(rope.NeckRadiusFraction)} R";
                if (rope.Fracture && rope.BreakRadiusFraction > 0)
                {
                    var brk = plot.Add.HorizontalLine(rope.BreakRadiusFraction * rope.Radius * 1000, 1.5f, Colors.Red, LinePattern.Dashed);
                    brk.LegendText = $"break radius {Num(rope.BreakRadiusFraction)} R";
                }
            }
            if (!double.IsNaN(r.BreakTime))
            {
                var at = plot.Add.VerticalLine(r.BreakTime, 1.5f, Colors.Red, LinePattern.Dotted);
                at.LegendText = $"break at {Num(r.BreakTime)} s";
            }
            plot.Title($"{r.Scenario.Name}: radius at the defect against time");
            plot.XLabel("time (s)");
            plot.YLabel("radius (mm)");
            plot.Axes.SetLimits(0, EndTime(r), 0, rope.Radius * 1000 * 1.1);
            plot.ShowLegend(Alignment.LowerLeft);
            return plot;
        }

        /// <summary>Radius along the rope at outputs.profileTimes and at the moments that matter (neck onset, thinnest intact state, break).</summary>
        public static Plot RadiusProfiles(RunResult r)
        {
            var plot = new Plot();
            var all = new List<RadiusProfile>(r.KeyProfiles);
            all.AddRange(r.Profiles);
            foreach (var profile in all)
            {
                var mm = new double[profile.Radius.Length];
                for (int i = 0; i < mm.Length; i++) mm[i] = profile.Radius[i] * 1000;
                var line = plot.Add.ScatterLine(profile.Arc, mm);
                line.LegendText = $"t = {Num(profile.Time)} s" + (profile.Label.Length > 0 ? " (" + profile.Label + ")" : "");
                line.LineWidth = 2;
                if (profile.Label.Length == 0) line.LinePattern = LinePattern.Dashed;
            }
            var rope = r.Scenario.Rope;
            if (rope.Necking)
            {
                var onset = plot.Add.HorizontalLine(rope.NeckRadiusFraction * rope.Radius * 1000, 1f, Colors.Orange, LinePattern.Dotted);
                onset.LegendText = $"r_min = {Num(rope.NeckRadiusFraction)} R";
            }
            plot.Title($"{r.Scenario.Name}: radius along the rope");
            plot.XLabel("rest arc length from the start (m)");
            plot.YLabel("radius (mm)");
            plot.Axes.SetLimits(0, rope.RestLength, 0, rope.Radius * 1000 * 1.15);
            plot.ShowLegend(Alignment.LowerRight);
            return plot;
        }

        /// <summary>One configuration family of the Pareto plot (one method and iteration count; substeps vary along it).</summary>
        public sealed class Series
        {
            /// <summary>Legend text.</summary>
            public string Label;
            /// <summary>Wall time per simulated second, ms.</summary>
            public List<double> Cost = new List<double>();
            /// <summary>Worst relative error (dimensionless); not finite when the run failed.</summary>
            public List<double> Error = new List<double>();
            /// <summary>True when the configuration failed (diverged, NaN or no result) on a reference scenario.</summary>
            public List<bool> Failed = new List<bool>();
            /// <summary>Draw the joining line dashed (the report's backward-Euler families, solid for BDF2).</summary>
            public bool Dashed;
            /// <summary>Palette index of the colour, or −1 for the next one in order (the report gives both integrators of one iteration count one colour).</summary>
            public int Colour = -1;
        }

        /// <summary>
        /// Log–log plot of the worst error in % against the run time: each family joined in order of cost,
        /// failed runs (diverged, NaN, no result) in a separate band a decade above the largest error, a 1 % line, the recommended configuration ringed,
        /// the legend outside the data.
        /// </summary>
        public static Plot Pareto(string title, IList<Series> series, double recommendedCost, double recommendedError, string recommendedLabel)
        {
            var plot = new Plot();
            var palette = new ScottPlot.Palettes.Category10();
            double top = 2;   // log10(100 %)
            foreach (var s in series)
                for (int i = 0; i < s.Error.Count; i++)
                    if (!s.Failed[i] && double.IsFinite(s.Error[i])) top = Math.Max(top, Math.Log10(Math.Max(s.Error[i] * 100, 1e-7)));
            double bandLow = Math.Ceiling(top) + 1, bandHigh = bandLow + 1;   // a decade of empty axis, then the band
            int colour = 0;
            foreach (var s in series)
            {
                var order = new List<int>();
                for (int i = 0; i < s.Cost.Count; i++) order.Add(i);
                order.Sort((a, b) => s.Cost[a].CompareTo(s.Cost[b]));
                var x = new List<double>();
                var y = new List<double>();
                var fx = new List<double>();
                var fy = new List<double>();
                foreach (int i in order)
                {
                    double lx = Math.Log10(Math.Max(s.Cost[i], 1e-6));
                    if (s.Failed[i] || !double.IsFinite(s.Error[i]))
                    {
                        fx.Add(lx);
                        fy.Add((bandLow + bandHigh) / 2);
                        continue;
                    }
                    x.Add(lx);
                    y.Add(Math.Log10(Math.Max(s.Error[i] * 100, 1e-7)));
                }
                var color = palette.GetColor(s.Colour >= 0 ? s.Colour : colour);
                colour++;
                if (x.Count > 0)
                {
                    var joined = plot.Add.Scatter(x.ToArray(), y.ToArray(), color);
                    joined.LegendText = s.Label;
                    joined.MarkerSize = 8;
                    joined.LineWidth = 1.5f;
                    if (s.Dashed) joined.LinePattern = LinePattern.Dashed;
                }
                if (fx.Count > 0)
                {
                    var failed = plot.Add.ScatterPoints(fx.ToArray(), fy.ToArray(), color);
                    failed.MarkerShape = MarkerShape.Eks;
                    failed.MarkerSize = 10;
                    failed.LegendText = s.Label + ": failed";
                }
            }
            var band = plot.Add.VerticalSpan(bandLow, bandHigh);
            band.LegendText = "diverged / NaN / no result (not an error value)";
            band.FillStyle.Color = Colors.Red.WithAlpha(0.08);
            var onePercent = plot.Add.HorizontalLine(0, 1.5f, Colors.Black, LinePattern.Dashed);
            onePercent.LegendText = "1 % error";
            if (double.IsFinite(recommendedCost) && double.IsFinite(recommendedError))
            {
                var ring = plot.Add.Marker(Math.Log10(recommendedCost), Math.Log10(Math.Max(recommendedError * 100, 1e-7)), MarkerShape.OpenCircle, 22, Colors.Black);
                ring.LegendText = "recommended: " + recommendedLabel;
            }
            plot.Axes.Bottom.TickGenerator = LogTicks("", double.PositiveInfinity);
            plot.Axes.Left.TickGenerator = LogTicks(" %", bandLow);
            plot.Title(title);
            plot.XLabel("wall time per simulated second (ms, log)");
            plot.YLabel("worst error over the reference scenarios (%, log)");
            plot.Axes.AutoScale();
            var limits = plot.Axes.GetLimits();
            plot.Axes.SetLimitsY(Math.Min(limits.Bottom, -1) - 0.2, bandHigh + 0.2);
            plot.ShowLegend(Edge.Right);
            return plot;
        }

        static ScottPlot.TickGenerators.NumericAutomatic LogTicks(string unit, double blankFrom) => new ScottPlot.TickGenerators.NumericAutomatic
        {
            MinorTickGenerator = new ScottPlot.TickGenerators.LogMinorTickGenerator(),
            IntegerTicksOnly = true,
            LabelFormatter = v => v >= blankFrom - 1.01 ? "" : Math.Pow(10, v).ToString(v >= 6 ? "0E0" : "G6", Invariant) + unit,
        };

        static double EndTime(RunResult r) => Math.Max(r.Steps * r.HostStep, 1e-3);

        static double Min(double[] a, double[] b)
        {
            double min = double.PositiveInfinity;
            foreach (var v in a) min = Math.Min(min, v);
            foreach (var v in b) min = Math.Min(min, v);
            return double.IsFinite(min) ? min : 0;
        }

        static string Num(double v) => v.ToString("G3", Invariant);
    }
}
