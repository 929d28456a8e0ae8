using System.IO;
using HookeRope.Lab.Commands;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>Convergence verdicts (issue 16 item 1): thresholds, limit ticks only for converged fall arrests, exit codes.</summary>
    [TestFixture]
    public sealed class VerdictTests : TempFolderTest
    {
        /// <summary>The default fall arrest on Gauss–Seidel with 1 iteration: finite but the rope is far longer than its tension implies.</summary>
        public const string GaussSeidelFallArrest = @"{ ""name"": ""gs-fall"", ""duration"": 3, ""solver"": { ""method"": ""gauss-seidel"" },
  ""rope"": { ""restLength"": 2, ""segments"": 20, ""axialStiffness"": 5000, ""linearDensity"": 0.05 },
  ""end"": { ""type"": ""body"", ""mass"": 100 }, ""initial"": { ""fallHeight"": 4 }, ""expect"": { ""check"": ""fall-arrest"" } }";

        /// <summary>A 1 t load on a rope released at 10× its length, Gauss–Seidel with one projection per step: stable, but its segments are many times longer than their tension implies.</summary>
        public const string FarOffRun = @"{ ""name"": ""far"", ""duration"": 1, ""solver"": { ""method"": ""gauss-seidel"", ""substeps"": 1, ""iterations"": 1 },
  ""rope"": { ""restLength"": 1, ""segments"": 16, ""radius"": 0.005, ""youngsModulus"": 1e9, ""fracture"": false, ""necking"": false },
  ""end"": { ""type"": ""body"", ""mass"": 1000 }, ""initial"": { ""stretch"": 9 }, ""outputs"": { ""sampleRate"": 10 } }";

        /// <summary>A 1 t load on a 1 m rope of E = 1 kPa: the load falls through it, strain past 100 (10 000 %).</summary>
        public const string DivergingRun = @"{ ""name"": ""div"", ""duration"": 5, ""rope"": { ""restLength"": 1, ""segments"": 8, ""youngsModulus"": 1e3, ""fracture"": false, ""necking"": false },
  ""end"": { ""type"": ""body"", ""mass"": 1000 }, ""outputs"": { ""sampleRate"": 10 } }";

        int Invoke(out string output, params string[] args)
        {
            var o = new StringWriter();
            int code = LabCli.Invoke(args, LabConsole.Plain(o), o, o);
            output = o.ToString();
            return code;
        }

        string Write(string json)
        {
            string file = Path.Combine(dir, "scenario.json");
            File.WriteAllText(file, json);
            return file;
        }

        [Test]
        public void DefaultFallArrestConvergesAndShowsTheLimits()
        {
            var r = ScenarioRunner.Run(BuiltInScenarios.Load("fall-arrest"));
            var v = ConvergenceVerdict.Judge(r);
            Assert.That(v.Kind, Is.EqualTo(Convergence.Converged), v.Reason);
            Assert.That(v.UnconvergedFraction, Is.EqualTo(0));
            Assert.That(Invoke(out string output, "run", "--out", dir), Is.EqualTo(0));
            Assert.That(output, Does.Contain("verdict: converged"));
            Assert.That(output, Does.Contain("≤ 6 kN EN 355"));
            Assert.That(output, Does.Contain("OSHA deceleration distance"));
        }

        [Test]
        public void GaussSeidelFallArrestIsUnconvergedWithoutTicksAndSaysWhatToChange()
        {
            var r = ScenarioRunner.Run(ScenarioParser.Parse(GaussSeidelFallArrest));
            var v = ConvergenceVerdict.Judge(r);
            Assert.That(v.Kind, Is.EqualTo(Convergence.Unconverged), v.Reason);
            Assert.That(v.UnconvergedFraction, Is.GreaterThan(ConvergenceVerdict.AllowedFraction));
            Assert.That(r.PeakTopForce, Is.LessThan(0.05 * 5518), "the peak force is wrong by over 95 %: why the verdict matters");
            string file = Write(GaussSeidelFallArrest);
            Assert.That(Invoke(out string output, "run", file, "--out", dir), Is.EqualTo(0), "unconverged without --check still exits 0");
            Assert.That(output, Does.Contain("verdict: unconverged"));
            Assert.That(output, Does.Not.Contain("✓"), "no tick of any kind on an unconverged fall arrest");
            Assert.That(output, Does.Not.Contain("≤ 6 kN"));
            Assert.That(output, Does.Contain("limits not assessed"));
            Assert.That(output, Does.Contain("use the exact solver"));
            Assert.That(Invoke(out _, "run", file, "--check", "--out", dir), Is.EqualTo(RunCommand.CheckFailed));
        }

        [Test]
        public void ExtremeRunIsDivergedAndExitsThree()
        {
            var r = ScenarioRunner.Run(ScenarioParser.Parse(DivergingRun));
            var v = ConvergenceVerdict.Judge(r);
            Assert.That(v.Kind, Is.EqualTo(Convergence.Diverged), v.Reason);
            Assert.That(r.MaxElongation / r.Scenario.Rope.RestLength, Is.GreaterThan(ConvergenceVerdict.MaxCredibleStrain));
            Assert.That(Invoke(out string output, "run", Write(DivergingRun), "--out", dir), Is.EqualTo(RunCommand.Diverged));
            Assert.That(output, Does.Contain("verdict: diverged"));
            Assert.That(output, Does.Contain("not physical"));
            Assert.That(output, Does.Contain("what to change:"));
        }

        [Test]
        public void FarOffGaussSeidelRunIsUnconvergedAndSaysSo()
        {
            var r = ScenarioRunner.Run(ScenarioParser.Parse(FarOffRun));
            var v = ConvergenceVerdict.Judge(r);
            Assert.That(v.Kind, Is.EqualTo(Convergence.Unconverged), v.Reason);
            Assert.That(v.DivergedFraction, Is.GreaterThan(0.5), "strain errors above 100 % on most steps");
            Assert.That(v.Reason, Does.Contain("far longer than their tension implies"));
            Assert.That(v.Advice, Does.StartWith("use the exact solver"));
        }

        [Test]
        public void NonFallArrestScenarioNeverShowsFallArrestLimits()
        {
            Assert.That(Invoke(out string output, "run", "static-hang", "--out", dir), Is.EqualTo(0));
            Assert.That(output, Does.Contain("verdict: converged"));
            Assert.That(output, Does.Not.Contain("EN 355"));
            Assert.That(output, Does.Not.Contain("OSHA"));
        }

        [TestCase(0.0f, 0.0f, Convergence.Converged)]
        [TestCase(0.019f, 0.0f, Convergence.Converged)]
        [TestCase(0.05f, 0.0f, Convergence.Unconverged)]
        [TestCase(2.0f, 0.0f, Convergence.Unconverged)]
        [TestCase(0.0f, 101.0f, Convergence.Diverged)]
        public void ThresholdsOnASyntheticRun(float residual, float strain, Convergence expected)
        {
            var s = BuiltInScenarios.Load("static-hang");
            var r = new RunResult { Scenario = s, ResidualSeries = new float[100], MaxElongation = strain * s.Rope.RestLength };
            for (int i = 0; i < 20; i++) r.ResidualSeries[i] = residual;   // 20 % of the steps
            Assert.That(ConvergenceVerdict.Judge(r).Kind, Is.EqualTo(expected));
            for (int i = 0; i < 11; i++) r.ResidualSeries[i] = 0;          // 9 % left: a transient
            Assert.That(ConvergenceVerdict.Judge(r).Kind, Is.EqualTo(strain > 100 ? Convergence.Diverged : Convergence.Converged));
        }

        [Test]
        public void NonFiniteRunIsDiverged()
        {
            var r = new RunResult { Scenario = BuiltInScenarios.Load("static-hang"), NonFinite = true, ResidualSeries = new float[0] };
            Assert.That(ConvergenceVerdict.Judge(r).Kind, Is.EqualTo(Convergence.Diverged));
        }
    }
}
