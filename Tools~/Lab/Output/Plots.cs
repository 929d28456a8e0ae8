using System;
using System.Collections.Generic;
using HookeRope.Lab.Simulation;
using ScottPlot;

namespace HookeRope.Lab.Output
{
    /// <summary>PNG/SVG plots of a run (ScottPlot 5, headless SkiaSharp).</summary>
    public static class Plots
    {
        /// <summary>EN 355 energy-absorber limit, N.</summary>
        public const double En355Limit = 6000;
        /// <summary>ANSI Z359 / OSHA 1926.502 maximum arrest force, N.</summary>
        public const double OshaLimit = 8000;

        /// <summary>Anchor and load force against time with the 6 kN / 8 kN limits; writes PNG and, if asked, SVG.</summary>
        public static void Force(RunResult result, string pngPath, string svgPath = null)
        {
            int n = result.Samples.Count;
            var t = new double[n];
            var top = new double[n];
            var bottom = new double[n];
            for (int i = 0; i < n; i++)
            {
                t[i] = result.Samples[i].Time;
                top[i] = result.Samples[i].TopTension / 1000;
                bottom[i] = result.Samples[i].BottomTension / 1000;
            }
            var plot = new Plot();
            var a = plot.Add.ScatterLine(t, top);
            a.LegendText = "anchor force (first segment)";
            a.LineWidth = 2;
            var b = plot.Add.ScatterLine(t, bottom);
            b.LegendText = "force on the load (last segment)";
            b.LinePattern = LinePattern.Dotted;
            b.LineWidth = 2;
            var en = plot.Add.HorizontalLine(En355Limit / 1000, 1.5f, Colors.Orange, LinePattern.Dashed);
            en.LegendText = "6 kN: EN 355 energy absorber";
            var osha = plot.Add.HorizontalLine(OshaLimit / 1000, 1.5f, Colors.Red, LinePattern.Dashed);
            osha.LegendText = "8 kN: ANSI Z359 / OSHA 1926.502";
            plot.Title($"{result.Scenario.Name}: force against time (peak {result.PeakTopForce / 1000:F2} kN)");
            plot.XLabel("time (s)");
            plot.YLabel("force (kN)");
            double max = Math.Max(OshaLimit / 1000 * 1.1, result.PeakTopForce / 1000 * 1.1);
            plot.Axes.SetLimits(0, Math.Max(t.Length > 0 ? t[t.Length - 1] : 1, 1e-3), 0, max);
            plot.ShowLegend(Alignment.UpperRight);
            plot.SavePng(pngPath, 1000, 560);
            if (svgPath != null) plot.SaveSvg(svgPath, 1000, 560);
        }

        /// <summary>Radius along the rope at the scenario's profile instants.</summary>
        public static void RadiusProfiles(RunResult result, string pngPath, string svgPath = null)
        {
            var plot = new Plot();
            foreach (var profile in result.Profiles)
            {
                var mm = new double[profile.Radius.Length];
                for (int i = 0; i < mm.Length; i++) mm[i] = profile.Radius[i] * 1000;
                var line = plot.Add.ScatterLine(profile.Arc, mm);
                line.LegendText = $"t = {profile.Time:G4} s";
                line.LineWidth = 2;
            }
            plot.Title($"{result.Scenario.Name}: radius along the rope");
            plot.XLabel("rest arc length from the start (m)");
            plot.YLabel("radius (mm)");
            plot.Axes.SetLimitsY(0, result.Scenario.Rope.Radius * 1000 * 1.15);
            plot.ShowLegend(Alignment.LowerRight);
            plot.SavePng(pngPath, 1000, 500);
            if (svgPath != null) plot.SaveSvg(svgPath, 1000, 500);
        }

        /// <summary>One point set of the Pareto plot: a solver configuration family.</summary>
        public sealed class Series
        {
            /// <summary>Legend text.</summary>
            public string Label;
            /// <summary>Wall time per simulated second, ms.</summary>
            public List<double> Cost = new List<double>();
            /// <summary>Relative error (dimensionless).</summary>
            public List<double> Error = new List<double>();
        }

        /// <summary>Log–log scatter of error against run time (the report's Pareto plot).</summary>
        public static void Pareto(string title, IList<Series> series, string pngPath, string svgPath = null)
        {
            var plot = new Plot();
            foreach (var s in series)
            {
                var x = new double[s.Cost.Count];
                var y = new double[s.Error.Count];
                for (int i = 0; i < x.Length; i++)
                {
                    x[i] = Math.Log10(Math.Max(s.Cost[i], 1e-6));
                    y[i] = Math.Log10(Math.Max(s.Error[i], 1e-9));
                }
                var scatter = plot.Add.ScatterPoints(x, y);
                scatter.LegendText = s.Label;
                scatter.MarkerSize = 9;
            }
            plot.Axes.Bottom.TickGenerator = LogTicks();
            plot.Axes.Left.TickGenerator = LogTicks();
            plot.Title(title);
            plot.XLabel("wall time per simulated second (ms, log)");
            plot.YLabel("relative error (log)");
            plot.ShowLegend(Alignment.UpperRight);
            plot.SavePng(pngPath, 1000, 640);
            if (svgPath != null) plot.SaveSvg(svgPath, 1000, 640);
        }

        static ScottPlot.TickGenerators.NumericAutomatic LogTicks() => new ScottPlot.TickGenerators.NumericAutomatic
        {
            MinorTickGenerator = new ScottPlot.TickGenerators.LogMinorTickGenerator(),
            IntegerTicksOnly = true,
            LabelFormatter = v => Math.Pow(10, v).ToString("G3", System.Globalization.CultureInfo.InvariantCulture),
        };
    }
}
