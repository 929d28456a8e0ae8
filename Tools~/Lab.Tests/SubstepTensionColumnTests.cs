using System;
using System.IO;
using HookeRope.Lab.Output;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>Issue 14 item 3: the CSV's substep maximum and mean tension columns.</summary>
    public sealed class SubstepTensionColumnTests
    {
        [Test]
        public void FallArrestRowsCarryTheSubstepMaximumAndMeanTension()
        {
            var result = ScenarioRunner.Run(BuiltInScenarios.Load("fall-arrest"));
            double topMax = 0, bottomMax = 0;
            foreach (var s in result.Samples)
            {
                Assert.That(s.TopTensionMax, Is.GreaterThanOrEqualTo(s.TopTensionMean));
                Assert.That(s.TopTensionMax, Is.GreaterThanOrEqualTo(s.TopTension));
                Assert.That(s.BottomTensionMax, Is.GreaterThanOrEqualTo(s.BottomTensionMean));
                Assert.That(s.BottomTensionMax, Is.GreaterThanOrEqualTo(s.BottomTension));
                topMax = Math.Max(topMax, s.TopTensionMax);
                bottomMax = Math.Max(bottomMax, s.BottomTensionMax);
            }
            TestContext.WriteLine($"largest top tension: substep {topMax:R} N, end of step {result.PeakTopForce:R} N; largest bottom tension over substeps {bottomMax:R} N");
            Assert.That(topMax, Is.GreaterThan(result.PeakTopForce), "the arrest peak falls between host steps");

            var text = new StringWriter();
            CsvWriter.Write(result, text);
            var lines = text.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries);
            Assert.That(lines[0], Does.EndWith("energy_J,top_tension_max_N,top_tension_mean_N,bottom_tension_max_N,bottom_tension_mean_N"));
            foreach (var line in lines)
            {
                var fields = line.TrimEnd('\r').Split(',');
                Assert.That(fields.Length, Is.EqualTo(19));
                foreach (var field in fields) Assert.That(field, Is.Not.EqualTo("-0"));
            }
        }
    }
}
