using System.Collections.Generic;
using System.IO;
using System.Linq;
using HookeRope.Lab.Output;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using NUnit.Framework;
using ScottPlot;
using ScottPlot.Plottables;

namespace HookeRope.Lab.Tests
{
    /// <summary>Plots chosen by the scenario (issue 16 item 2), checked by reading back the ScottPlot plot model.</summary>
    [TestFixture]
    public sealed class PlotTests : TempFolderTest
    {
        static readonly Dictionary<string, (RunResult run, ConvergenceVerdict verdict, List<CheckResult> checks)> Cache =
            new Dictionary<string, (RunResult, ConvergenceVerdict, List<CheckResult>)>();

        static (RunResult run, ConvergenceVerdict verdict, List<CheckResult> checks) Run(string name, string json = null)
        {
            if (!Cache.TryGetValue(name, out var entry))
            {
                var r = ScenarioRunner.Run(json == null ? BuiltInScenarios.Load(name) : ScenarioParser.Parse(json));
                entry = (r, ConvergenceVerdict.Judge(r), PhysicsChecks.Evaluate(r));
                Cache[name] = entry;
            }
            return entry;
        }

        static List<double> HorizontalLines(Plot plot) => plot.GetPlottables<HorizontalLine>().Select(l => l.Y).ToList();

        static List<string> Legends(Plot plot) => plot.GetPlottables().SelectMany(p => p.LegendItems).Select(i => i.LabelText).ToList();

        [Test]
        public void StaticHangForceIsAutoscaledInNewtonsWithTheAnalyticTensionAndNoFallArrestLimits()
        {
            var (r, v, checks) = Run("static-hang");
            var plot = Plots.Force(r, v, checks);
            Assert.That(plot.Axes.Left.Label.Text, Is.EqualTo("force (N)"));
            var lines = HorizontalLines(plot);
            Assert.That(lines.Count, Is.EqualTo(1), "one analytic line, no limits");
            Assert.That(lines[0], Is.EqualTo(99.08).Within(0.1), "(M + m)·g");
            var limits = plot.Axes.GetLimits();
            Assert.That(limits.Bottom, Is.EqualTo(0).Within(1e-9));
            Assert.That(limits.Top, Is.EqualTo(1.1 * System.Math.Max(r.PeakTopForce, 99.08)).Within(0.01), "autoscaled to the ~115 N peak, not to 8.5 kN");
            Assert.That(limits.Right, Is.EqualTo(r.Scenario.Duration).Within(r.HostStep));
            Assert.That(plot.GetPlottables<Scatter>().Count(), Is.EqualTo(2));
            Assert.That(string.Join(";", Legends(plot)), Does.Not.Contain("EN 355"));
        }

        [Test]
        public void ConvergedFallArrestForceCarriesTheLimitsAndTheAnalyticPeak()
        {
            var (r, v, checks) = Run("fall-arrest");
            var plot = Plots.Force(r, v, checks);
            Assert.That(plot.Axes.Left.Label.Text, Is.EqualTo("force (kN)"));
            var lines = HorizontalLines(plot);
            Assert.That(lines, Has.Some.EqualTo(6.0));
            Assert.That(lines, Has.Some.EqualTo(8.0));
            Assert.That(lines, Has.Some.EqualTo(5.518).Within(0.001));
            Assert.That(plot.Axes.GetLimits().Top, Is.EqualTo(8.8).Within(0.01));
            Assert.That(plot.Axes.Bottom.Label.Text, Is.EqualTo("time (s)"));
        }

        [Test]
        public void UnconvergedFallArrestForceHasNoLimitsAndSaysSo()
        {
            var (r, v, checks) = Run("gs-fall", VerdictTests.GaussSeidelFallArrest);
            var plot = Plots.Force(r, v, checks);
            Assert.That(HorizontalLines(plot), Has.None.EqualTo(6000.0).And.None.EqualTo(8000.0).And.None.EqualTo(6.0));
            Assert.That(plot.Axes.Title.Label.Text, Does.Contain("UNCONVERGED"));
        }

        [Test]
        public void FallArrestDisplacementShowsTautAndTheOshaDistance()
        {
            var (r, v, _) = Run("fall-arrest");
            var plot = Plots.Displacement(r, v);
            double tautDrop = r.TotalDrop - r.ArrestDistance;
            Assert.That(HorizontalLines(plot).Single(), Is.EqualTo(tautDrop + 1.07).Within(1e-9));
            Assert.That(plot.GetPlottables<VerticalLine>().Single().X, Is.EqualTo(r.TautTime).Within(1e-9));
            Assert.That(tautDrop, Is.EqualTo(4.078).Within(0.01), "free fall of the default scenario");
            Assert.That(plot.Axes.Left.Label.Text, Is.EqualTo("drop below release (m)"));
        }

        [Test]
        public void NeckingRadiusPlotsShowOnsetThinnestAndTheOnsetRadius()
        {
            var (r, _, _) = Run("necking");
            var time = Plots.DefectRadius(r);
            Assert.That(HorizontalLines(time), Has.Some.EqualTo(7.5).Within(1e-6), "r_min = 0.75 R = 7.5 mm");
            Assert.That(time.Axes.GetLimits().Top, Is.EqualTo(11).Within(1e-9));
            var profiles = Plots.RadiusProfiles(r);
            var legends = string.Join(";", Legends(profiles));
            Assert.That(legends, Does.Contain("(neck onset)"));
            Assert.That(legends, Does.Contain("(thinnest (intact))"));
            Assert.That(profiles.GetPlottables<Scatter>().Count(), Is.EqualTo(r.Profiles.Count + r.KeyProfiles.Count));
            var onset = r.KeyProfiles.Single(p => p.Label == "neck onset");
            Assert.That(onset.Radius.Min(), Is.LessThan(0.0075).And.GreaterThan(0.0070), "just past r_min at onset");
        }

        [TestCase("static-hang", new[] { "-force" })]
        [TestCase("fall-arrest", new[] { "-force", "-displacement", "-neck" })]
        [TestCase("necking", new[] { "-force", "-neck", "-radius" })]
        public void EachScenarioGetsThePlotsThatFitIt(string name, string[] suffixes)
        {
            var (r, v, checks) = Run(name);
            string stem = Path.Combine(dir, name);
            var files = Plots.WriteAll(r, v, checks, stem, false);
            Assert.That(files, Is.EqualTo(suffixes.Select(s => stem + s + ".png").ToList()));
            foreach (var f in files) Assert.That(new FileInfo(f).Length, Is.GreaterThan(1000));
        }

        [Test]
        public void ParetoPlotHasPercentLogAxisOnePercentLineFailedBandJoinedFamiliesAndTheRecommendation()
        {
            var exact = new Plots.Series { Label = "exact chain, 1 iteration" };
            exact.Cost.AddRange(new[] { 4.0, 1.0, 2.0 });
            exact.Error.AddRange(new[] { 0.005, 0.05, 0.02 });
            exact.Failed.AddRange(new[] { false, false, false });
            var gs = new Plots.Series { Label = "Gauss–Seidel, 1 iteration" };
            gs.Cost.AddRange(new[] { 0.5, 1.0 });
            gs.Error.AddRange(new[] { double.PositiveInfinity, 300.0 });
            gs.Failed.AddRange(new[] { true, false });
            var plot = Plots.Pareto("t", new[] { exact, gs }, 4.0, 0.005, "exact 1it × 4sub");

            Assert.That(HorizontalLines(plot), Is.EqualTo(new[] { 0.0 }), "the 1 % line at log10(1 %)");
            var joined = plot.GetPlottables<Scatter>().Where(s => s.LineWidth > 0 && s.LegendText == exact.Label).Single();
            var points = joined.Data.GetScatterPoints();
            Assert.That(points.Select(p => p.X).ToList(), Is.Ordered, "joined in order of cost");
            Assert.That(points.Select(p => p.Y).ToList(), Is.EqualTo(new[] { System.Math.Log10(5.0), System.Math.Log10(2.0), System.Math.Log10(0.5) }).Within(1e-9), "errors in %");
            var band = plot.GetPlottables<VerticalSpan>().Single();
            double worst = System.Math.Log10(300.0 * 100);
            Assert.That(band.Bottom, Is.GreaterThan(worst + 0.99), "failed runs sit a decade above the worst real error");
            var failed = plot.GetPlottables<Scatter>().Single(s => s.LegendText.EndsWith(": failed"));
            var fp = failed.Data.GetScatterPoints().Single();
            Assert.That(fp.Y, Is.InRange(band.Bottom, band.Top));
            var marker = plot.GetPlottables<Marker>().Single();
            Assert.That(marker.Location.X, Is.EqualTo(System.Math.Log10(4.0)).Within(1e-9));
            Assert.That(marker.Location.Y, Is.EqualTo(System.Math.Log10(0.5)).Within(1e-9));
            var limits = plot.Axes.GetLimits();
            Assert.That(limits.Top, Is.GreaterThanOrEqualTo(band.Top));
            Assert.That(limits.Bottom, Is.LessThanOrEqualTo(System.Math.Log10(0.5)));
            Assert.That(plot.Axes.Left.Label.Text, Does.Contain("%"));
        }
    }
}
