using System.Collections.Generic;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>Every built-in scenario, run on the real solver, against its analytic formula.</summary>
    [TestFixture]
    public sealed class ScenarioPhysicsTests
    {
        static RunResult Run(Scenario s) => ScenarioRunner.Run(s, new RunOptions { TrackEnergy = false });

        static RunResult Run(string builtIn) => Run(BuiltInScenarios.Load(builtIn));

        static void AssertChecks(RunResult r, int count)
        {
            Assert.That(r.NonFinite, Is.False, r.Scenario.Name + ": NaN or ∞ in positions");
            List<CheckResult> checks = PhysicsChecks.Evaluate(r);
            Assert.That(checks.Count, Is.GreaterThanOrEqualTo(count), r.Scenario.Name + ": checks");
            for (int i = 0; i < count; i++)
            {
                var c = checks[i];
                Assert.That(c.Passed, Is.True,
                    $"{r.Scenario.Name}: {c.Quantity} = {c.Measured:G6} {c.Unit}, expected {c.Expected:G6} ({c.Formula}), error {c.Error:G3} > {c.Tolerance:G3}");
            }
        }

        [Test]
        public void FallArrestPeakForceMatchesTheEnergyBalance()
        {
            var r = Run("fall-arrest");
            // F = Mg + sqrt((Mg)² + 2Mgkh) = 5518 N for 100 kg, k = 2500 N/m, h = 4 m: within 5 %.
            Assert.That(r.PeakTopForce, Is.EqualTo(PhysicsChecks.FallArrestForce(100, 9.81, 2500, 4)).Within(5).Percent);
            Assert.That(r.TautTime, Is.EqualTo(System.Math.Sqrt(2 * 4 / 9.81)).Within(0.05));
            AssertChecks(r, 1);
        }

        [Test]
        public void StaticHangElongationAndTopTension() => AssertChecks(Run("static-hang"), 2);

        [Test]
        public void SpringOscillatorPeriod() => AssertChecks(Run("spring-oscillator"), 2);

        [Test]
        public void HeavyMassRatioHangsAtTheStaticElongation() => AssertChecks(Run("heavy-mass-ratio"), 2);

        [Test]
        public void SteelCableFundamentalAndMeanElongation() => AssertChecks(Run("steel-cable"), 2);

        [TestCase(0.0)]
        [TestCase(0.25)]
        [TestCase(0.5)]
        public void PoissonSweepRadiusFollowsTheVolumeLaw(double nu)
        {
            var s = BuiltInScenarios.Load("poisson-sweep");
            s.Rope.PoissonRatio = nu;
            var r = Run(s);
            AssertChecks(r, 1);
            double strain = PhysicsChecks.FinalElongation(r) / s.Rope.RestLength;
            Assert.That(strain, Is.EqualTo(1.0).Within(0.02), "the end keyframe doubles the length");
        }

        [Test]
        public void NeckingFormsAtTheDefectBelowTheOnsetRadius() => AssertChecks(Run("necking"), 3);

        [Test]
        public void FractureBreaksAtTheBreakStrainTension()
        {
            var r = Run("fracture");
            Assert.That(double.IsNaN(r.BreakTime), Is.False, "the cord must break");
            // The end moves at 0.5 m/s from 1 m: 50 % strain is reached at t ≈ 1 s.
            Assert.That(r.BreakTime, Is.EqualTo(1.0).Within(0.05));
            AssertChecks(r, 1);
        }

        [Test]
        public void CollisionBendWrapsTheBarWithoutPenetrating()
        {
            // No penetration (1 % of the collision radius), length = tangent + arc + tangent,
            // reported tension and both anchor forces = E·A·strain.
            AssertChecks(Run("collision-bend"), 4);
        }

        [Test]
        public void CatenarySagAndHorizontalTension() => AssertChecks(Run("catenary"), 2);

        [Test]
        public void SwingSettleDecaysAtTheDragRateAndSettlesWhenTheFormulaSays()
        {
            // c = 0.5 N·s/m² on μ = 0.229 kg/m: decay rate c/(2μ) = 1.091 1/s (2 %), within 1 cm at (2μ/c)·ln(1 m/1 cm) = 4.22 s (5 %)
            var r = Run("swing-settle");
            foreach (var c in PhysicsChecks.Evaluate(r)) TestContext.WriteLine($"{c.Quantity}: {c.Measured:G5} {c.Unit} vs {c.Expected:G5} {c.Unit} ({c.Error * 100:G3} %)");
            AssertChecks(r, 2);
        }

        [Test]
        public void EveryBuiltInScenarioHasAPhysicsTest()
        {
            var covered = new[] { "fall-arrest", "static-hang", "spring-oscillator", "heavy-mass-ratio", "steel-cable",
                "poisson-sweep", "necking", "fracture", "collision-bend", "catenary",
                "spring-amplitude", "slack-bounce", "steel-snatch",   // these three: DissipationScenarioTests
                "plastic-necking", "absorber-arrest",               // these two: MaterialLawScenarioTests
                "swing-settle" };
            Assert.That(BuiltInScenarios.Names, Is.EquivalentTo(covered));
        }
    }
}
