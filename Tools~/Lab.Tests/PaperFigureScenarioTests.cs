using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>Issue 17 item 5: the built-in fracture scenario shows Fig. 8's sequence — uniform, a neck in the middle, the break there.</summary>
    public sealed class PaperFigureScenarioTests
    {
        [Test]
        public void FractureScenarioNecksAndBreaksInTheMiddle()
        {
            var s = BuiltInScenarios.Load("fracture");
            var setup = ScenarioRunner.Build(s, true);
            var model = setup.Simulation.RadiusModel;
            // 21 segments: the defect (0.5) is in segment 10, whose middle is the rope's middle.
            Assert.That(model.DefectSegment, Is.EqualTo(10));
            Assert.That(model.DefectRestArc / model.RestLength, Is.EqualTo(0.5).Within(1e-6));

            var r = ScenarioRunner.Run(s, new RunOptions { TrackEnergy = false });
            double radius = s.Rope.Radius, uniform = double.NaN, necked = double.NaN;
            foreach (var sample in r.Samples)
            {
                if (sample.Time < 0.5) uniform = sample.NeckRadius;          // strain 25 %: Poisson only
                if (sample.Time < r.BreakTime) necked = sample.NeckRadius;    // just before the break
            }
            double poissonAtBreak = radius / System.Math.Sqrt(1.5);            // ν = 0.5 at 50 % strain
            TestContext.WriteLine("neck radius at t < 0.5 s: " + uniform / radius + " R; just before the break: " + necked / radius + " R");
            Assert.That(uniform, Is.EqualTo(radius / System.Math.Sqrt(1.25)).Within(0.02 * radius), "uniform thinning first");
            Assert.That(necked, Is.LessThan(0.7 * poissonAtBreak), "a neck deeper than the Poisson radius before the break");
            Assert.That(r.BreakTime, Is.EqualTo(1.0).Within(0.05));
        }
    }
}
