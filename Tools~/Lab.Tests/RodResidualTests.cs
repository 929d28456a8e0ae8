using System.Collections.Generic;
using HookeRope.Lab.Stability;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>
    /// Two cases of the full stability grid that the documented limit "rod in compression" held until a bilateral segment
    /// with (almost) no geometric stiffness in the exact solve (pushing, or nearly slack) took its residual along the
    /// segment instead of along its force (solver.md, "Rods in compression", the axial residual): the force's direction
    /// lagged the segment by θ and the solve converged to the length L·cos θ, storing ½(L(1 − cos θ))²/α. Each case runs
    /// exactly as <c>stability --full</c> runs it (<see cref="GridSweep.Run"/>).
    /// </summary>
    [TestFixture]
    public sealed class RodResidualTests
    {
        private static IEnumerable<TestCaseData> FixedCases()
        {
            yield return new TestCaseData("E 2E+11 Pa, ratio 1E+06, dt 1/30 s, 2 seg, stretch 1, BackwardEuler, Bilateral, collider")
                .SetName("45 t load on a 2-segment steel rod hitting the sphere at 1/30 s, backward Euler (was +9.4 kJ)");
            yield return new TestCaseData("E 2E+11 Pa, ratio 1, dt 1/90 s, 256 seg, stretch 1, Bdf2, Bilateral, collider, damped (drag 3.13/s, β 0.05 s, 7.982 s)")
                .SetName("Damped 256-segment steel rod on the sphere, BDF2 (was +0.226 J)");
        }

        [TestCaseSource(nameof(FixedCases))]
        public void ARodThatPushesOnTheSphereGainsNoEnergyBeyondRoundOff(string description)
        {
            GridCase c = GridSweep.Cases(true).Find(x => x.ToString() == description);
            Assert.That(c, Is.Not.Null, "the case is in the full grid");
            GridOutcome o = GridSweep.Run(c);
            TestContext.WriteLine($"{description}: largest push {o.LargestPush:G4} N; largest gain {o.EnergyGain:G4} J " +
                $"({o.Excess:G4} J beyond the round-off allowance {o.Allowance:G3} J; motion alone {o.MotionGain:G4} J); " +
                $"{o.ViolentSubsteps} violent, {o.UnconvergedSubsteps} unconverged of {o.Substeps} substeps; {o.Reason}");
            Assert.That(o.Finite, Is.True);
            Assert.That(o.LargestPush, Is.GreaterThan(0.0), "the rod pushes");
            Assert.That(o.Excess, Is.LessThanOrEqualTo(0.0), "no energy gain beyond round-off");
            Assert.That(o.Failed, Is.False, o.Reason);
        }
    }
}
