using System.Collections.Generic;
using HookeRope.Lab.Report;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>
    /// The accuracy of the package defaults at Unity's default Fixed Timestep (0.02 s) and at the step they were validated
    /// at (1/90 s), against analytic answers (Documentation~/index.md, "Fixed step: validated at 1/90 s"). The bounds are
    /// the measured errors (lab <c>accuracy</c>) with margin: about 1.4× the 0.02 s error, rounded up, and never tighter
    /// than 0.1 %; a change of solver, defaults or scenarios that loses accuracy at 0.02 s fails here.
    /// </summary>
    [TestFixture]
    public sealed class FixedStepAccuracyTests
    {
        static readonly Dictionary<double, List<StepAccuracyRow>> Measured = new Dictionary<double, List<StepAccuracyRow>>();

        static StepAccuracyRow Row(string name, double step)
        {
            if (!Measured.TryGetValue(step, out var rows)) Measured[step] = rows = FixedStepAccuracy.Measure(step);
            return rows.Find(r => r.Case == name);
        }

        // measured with BDF2 and the vector chain solve, at 0.02 s: −0.02 %, +0.01 %, +0.08 %, +0.03 %, +0.21 %;
        // at 1/90 s: −0.23 %, −0.01 %, +0.05 %, +0.02 %, +0.06 % (with backward Euler and the lumped transverse
        // stabilisation before: −2.49 %, −1.00 %, +0.01 %, +0.10 %, +0.27 % and −1.41 %, −0.56 %, +0.02 %, +0.05 %, +0.07 %)
        [TestCase("default lanyard: fall arrest", FixedStepAccuracy.UnityDefaultStep, 0.001)]
        [TestCase("lab fall-arrest scenario", FixedStepAccuracy.UnityDefaultStep, 0.001)]
        [TestCase("default lanyard: static hang", FixedStepAccuracy.UnityDefaultStep, 0.0012)]
        [TestCase("default lanyard: period", FixedStepAccuracy.UnityDefaultStep, 0.001)]
        [TestCase("spring–mass reference", FixedStepAccuracy.UnityDefaultStep, 0.003)]
        [TestCase("default lanyard: fall arrest", FixedStepAccuracy.ValidatedStep, 0.004)]
        [TestCase("lab fall-arrest scenario", FixedStepAccuracy.ValidatedStep, 0.001)]
        [TestCase("default lanyard: static hang", FixedStepAccuracy.ValidatedStep, 0.001)]
        [TestCase("default lanyard: period", FixedStepAccuracy.ValidatedStep, 0.001)]
        [TestCase("spring–mass reference", FixedStepAccuracy.ValidatedStep, 0.001)]
        public void TheErrorStaysWithinTheDocumentedBound(string name, double step, double bound)
        {
            var row = Row(name, step);
            Assert.That(row.Error, Is.LessThanOrEqualTo(bound), $"{name} at {step} s: {row.Quantity} {row.Measured:G6} {row.Unit} against {row.Expected:G6} ({row.Formula})");
        }

        // with BDF2 the arrests are within 0.25 % at both steps (default lanyard −0.23 % and −0.02 %, lab scenario −0.01 %
        // and +0.01 %), so their errors are no longer ordered by the step; the spring–mass period still is
        [TestCase("spring–mass reference")]
        public void TheDynamicErrorsGrowFromTheValidatedStepToUnitysDefault(string name)
        {
            // the peak force and the period are time-integration errors: the longer step is the less accurate one
            Assert.That(Row(name, FixedStepAccuracy.UnityDefaultStep).Error, Is.GreaterThan(Row(name, FixedStepAccuracy.ValidatedStep).Error));
        }

        [Test]
        public void StepLabelsReadAsTheDocumentationWritesThem()
        {
            Assert.That(FixedStepAccuracy.StepLabel(1.0 / 90.0), Is.EqualTo("1/90 s"));
            Assert.That(FixedStepAccuracy.StepLabel(0.02), Is.EqualTo("0.02 s"));
        }
    }
}
