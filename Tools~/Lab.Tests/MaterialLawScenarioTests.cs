using System.Linq;
using HookeRope.Lab.Output;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using NUnit.Framework;
using ScottPlot;

namespace HookeRope.Lab.Tests
{
    /// <summary>
    /// Issue 15 in the lab: the scenario format takes the material law and the energy absorber (with the order of the
    /// plastic strains checked), the two built-in scenarios pass their analytic checks, and the force–elongation plot
    /// draws the run against the law's quasi-static curve.
    /// </summary>
    [TestFixture]
    public sealed class MaterialLawScenarioTests
    {
        static void AssertRejectedAt(string json, string path, string words)
        {
            var e = Assert.Throws<ScenarioException>(() => ScenarioParser.Parse(json));
            Assert.That(e.Path, Is.EqualTo(path));
            Assert.That(e.Message, Does.Contain(words));
        }

        [Test]
        public void TheRopeBlockTakesTheMaterialLawAndTheAbsorber()
        {
            var s = ScenarioParser.Parse("{\"rope\":{\"materialModel\":\"elastic-plastic\",\"yieldStrain\":0.05,\"hardeningModulus\":0,\"neckingStrain\":0.2,\"ultimateStrain\":0.4," +
                                         "\"energyAbsorber\":true,\"absorberForce\":3500,\"absorberDeployment\":1.2}}");
            Assert.That(s.Rope.IsPlastic, Is.True);
            var settings = ScenarioRunner.Settings(s);
            Assert.That(settings.MaterialModel, Is.EqualTo(HookeRope.Solver.MaterialModel.ElasticPlastic));
            Assert.That(new[] { settings.YieldStrain, settings.HardeningModulus, settings.NeckingStrain, settings.UltimateStrain }, Is.EqualTo(new[] { 0.05f, 0f, 0.2f, 0.4f }));
            Assert.That(settings.EnergyAbsorber, Is.True);
            Assert.That(settings.AbsorberForce, Is.EqualTo(3500f));
            Assert.That(settings.AbsorberDeployment, Is.EqualTo(1.2f));
            Assert.That(ScenarioRunner.Settings(new Scenario()).MaterialModel, Is.EqualTo(HookeRope.Solver.MaterialModel.Elastic), "elastic by default");
        }

        [TestCase("{\"rope\":{\"materialModel\":\"elastic-plastic\",\"yieldStrain\":0.7,\"ultimateStrain\":0.6}}", "$.rope.yieldStrain", "must be below ultimateStrain (0.6)")]
        [TestCase("{\"rope\":{\"materialModel\":\"elastic-plastic\",\"yieldStrain\":0.1,\"neckingStrain\":0.05}}", "$.rope.neckingStrain", "[yieldStrain, ultimateStrain) = [0.1, 0.6)")]
        [TestCase("{\"rope\":{\"hardeningModulus\":-1}}", "$.rope.hardeningModulus", "out of range [0, 1E+12]")]
        [TestCase("{\"rope\":{\"absorberForce\":0}}", "$.rope.absorberForce", "out of range (0, 1E+07]")]
        [TestCase("{\"rope\":{\"materialModel\":\"plastic\"}}", "$.rope.materialModel", "elastic-plastic")]
        public void BadMaterialInputIsRejectedNamingThePath(string json, string path, string words) => AssertRejectedAt(json, path, words);

        [Test]
        public void PlasticNeckingPeaksAtTheNeckOnsetFollowsTheCurveAndBreaksWithItsForceGone()
        {
            var r = ScenarioRunner.Run(BuiltInScenarios.Load("plastic-necking"), new RunOptions { TrackEnergy = false });
            var checks = PhysicsChecks.Evaluate(r);
            Assert.That(checks.Count, Is.EqualTo(4));
            foreach (var c in checks)
                Assert.That(c.Passed, Is.True, $"{c.Quantity} = {c.Measured:G6} {c.Unit}, expected {c.Expected:G6} ({c.Formula}), error {c.Error:G3} > {c.Tolerance:G3}");
            Assert.That(double.IsNaN(r.BreakTime), Is.False, "it breaks");
            Assert.That(r.PlasticWork, Is.GreaterThan(0));
        }

        [Test]
        public void AbsorberArrestHoldsThePlateauDeploysByTheEnergyBalanceAndPassesEn355()
        {
            var r = ScenarioRunner.Run(BuiltInScenarios.Load("absorber-arrest"), new RunOptions { TrackEnergy = true });
            var checks = PhysicsChecks.Evaluate(r);
            Assert.That(checks.Count, Is.EqualTo(4));
            foreach (var c in checks)
                Assert.That(c.Passed, Is.True, $"{c.Quantity} = {c.Measured:G6} {c.Unit}, expected {c.Expected:G6} ({c.Formula}), error {c.Error:G3} > {c.Tolerance:G3}");
            Assert.That(PhysicsChecks.AbsorberDeployment(100, 9.81, 5e4, 4, 4000), Is.EqualTo(1.2728).Within(1e-4));
            var verdict = ConvergenceVerdict.Judge(r);
            Assert.That(verdict.Converged, Is.True, verdict.Reason);
            Assert.That(r.MaxEnergy, Is.LessThanOrEqualTo(r.InitialEnergy + 1e-6 * System.Math.Abs(r.InitialEnergy)), "no energy created");
        }

        [Test]
        public void ForceElongationPlotDrawsTheRunAgainstTheMaterialLaw()
        {
            var r = ScenarioRunner.Run(BuiltInScenarios.Load("plastic-necking"), new RunOptions { TrackEnergy = false });
            Assert.That(Plots.HasMaterialLaw(r), Is.True);
            var plot = Plots.ForceElongation(r);
            Assert.That(plot.Axes.Bottom.Label.Text, Is.EqualTo("elongation of the rope (m)"));
            Assert.That(plot.Axes.Left.Label.Text, Is.EqualTo("force (kN)"));
            var legends = plot.GetPlottables().SelectMany(p => p.LegendItems).Select(i => i.LabelText).ToList();
            Assert.That(legends, Has.Some.StartsWith("material law, slow pull: yield 20 kN, neck onset 34.7 kN"));
            Assert.That(legends, Has.Some.StartsWith("break at"));
            var limits = plot.Axes.GetLimits();
            Assert.That(limits.Top, Is.EqualTo(34.65 * 1.12).Within(0.05), "the neck onset with headroom");
            Assert.That(Plots.HasMaterialLaw(ScenarioRunner.Run(BuiltInScenarios.Load("static-hang"), RunOptions.Lean())), Is.False, "an elastic rope has no such plot");
        }
    }
}
