using System.IO;
using HookeRope.Lab.Commands;
using HookeRope.Lab.Stability;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>
    /// The CI subset of the integrator grid (issue 14 item 4; <c>stability --full</c> runs all of it): 2 values per axis,
    /// 0.5 s, the settle, friction and teleport families. CI holds what <c>--full</c> holds: every case finite and stable (no
    /// energy gain beyond round-off, settled when damped, recovered after the teleport); no failure, not even one under a
    /// documented domain limit (<see cref="GridLimits"/>).
    /// </summary>
    [TestFixture]
    public sealed class GridSweepTests : TempFolderTest
    {
        [Test]
        public void CiSubsetStaysFiniteAndStable()
        {
            var cases = GridSweep.Cases(false);
            Assert.That(cases.Count, Is.EqualTo(114));
            var outcomes = GridSweep.RunAll(cases);
            foreach (var o in outcomes)
            {
                Assert.That(o.Finite, Is.True, o.Case.ToString());
                // a failure fails the test, under a documented limit (its known cause, named in the message) or not
                Assert.That(o.Failed, Is.False, o.Case + ": " + o.Reason + " [" + (o.Limit ?? "undocumented") + "]");
            }
        }

        [Test]
        public void RoundOffAllowanceIsTheDocumentedBound()
        {
            // 2⁻²² of K + |G| + U per substep: four half-ulps of float32
            Assert.That(GridOutcome.RoundOffPerSubstep, Is.EqualTo(System.Math.Pow(2.0, -22)));
            var o = new GridOutcome { Case = new GridCase(), Finite = true, Excess = 1e-9, ReachBound = 1.0 };
            Assert.That(o.GainedEnergy, Is.True, "any excess over the accumulated bound is a gain");
            o.Excess = 0.0;
            Assert.That(o.GainedEnergy, Is.False);
        }

        [Test]
        public void GridCommandWritesItsTableAndItsLimits()
        {
            var output = new StringWriter();
            int code = GridCommand.Execute(LabConsole.Plain(output), dir, full: false);
            string md = File.ReadAllText(Path.Combine(dir, "stability-grid-ci.md"));
            Assert.That(md, Does.Contain("| Undamped | Bdf2 |"));
            Assert.That(md, Does.Contain("| Teleport | BackwardEuler |"));
            Assert.That(md, Does.Contain("## Documented domain limits"));
            Assert.That(md, Does.Contain("## Failures"));
            Assert.That(md, Does.Not.Contain("none: undocumented failure"));
            Assert.That(code, Is.EqualTo(0));
            Assert.That(output.ToString(), Does.Contain("0 undocumented failures"));
        }
    }
}
