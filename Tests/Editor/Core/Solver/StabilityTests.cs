using System;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>The stability matrix: stiff and extreme cases stay finite, never gain energy, and recover.</summary>
    public sealed class StabilityTests
    {
        //        E (Pa)   mass ratio   host step      segments  stretch
        [TestCase(1e6f,    1.0,         1f / 30f,      2,        1f)]
        [TestCase(1e6f,    1e6,         1f / 30f,      16,       1f)]
        [TestCase(2e11f,   1.0,         1f / 30f,      64,       1f)]
        [TestCase(2e11f,   1e6,         1f / 90f,      64,       1f)]
        [TestCase(2e11f,   1e6,         1f / 1000f,    16,       1f)]
        [TestCase(1e6f,    1.0,         1f / 1000f,    16,       10f)]
        [TestCase(2e11f,   1e3,         1f / 30f,      16,       10f)]
        [TestCase(1e9f,    1e6,         1f / 90f,      2,        10f)]
        [TestCase(1e9f,    1e4,         1f / 90f,      256,      1f)]
        [TestCase(1e9f,    1e4,         1f / 90f,      64,       3f)]
        public void ExtremeCaseStaysFiniteAndGainsNoEnergy(float youngsModulus, double massRatio, float hostStep, int segments, float stretch)
        {
            var test = new StabilityCase { YoungsModulus = youngsModulus, MassRatio = massRatio, HostDeltaTime = hostStep, SegmentCount = segments, Stretch = stretch };
            StabilityResult result = test.Run(stretch > 1f ? 8.0 : 2.0);
            TestContext.WriteLine($"E={youngsModulus:G3} ratio={massRatio:G3} dt={hostStep:G3} n={segments} stretch={stretch}: E0 {result.InitialEnergy:G4} J, gain {result.LargestEnergyGain:G3} J, final KE {result.FinalKineticEnergy:G3} J, reach {result.FarthestFromAnchor:G4} m, residual {result.FinalResidual:G3}");
            Assert.That(result.Finite, Is.True);
            Assert.That(result.LargestEnergyGain, Is.LessThanOrEqualTo(1e-4 * Math.Abs(result.InitialEnergy) + 1e-6));
            Assert.That(result.FarthestFromAnchor, Is.LessThan(test.ReachBound(result)), "it ends hanging from its anchor");
        }

        //        E (Pa)  mass ratio  integrator
        [TestCase(1e9f,   1.0,        TimeIntegrator.BackwardEuler)]
        [TestCase(1e9f,   1.0,        TimeIntegrator.Bdf2)]
        [TestCase(2e11f,  1e6,        TimeIntegrator.BackwardEuler)]
        [TestCase(2e11f,  1e6,        TimeIntegrator.Bdf2)]
        public void RopeReleasedTenTimesStretchedConvergesWithoutGainingEnergy(float youngsModulus, double massRatio, TimeIntegrator integrator)
        {
            // 256 segments released at 10× their length (a nylon rope: 3.2 MJ of elastic energy in 1 m): the first substeps
            // move the segments across themselves, one Newton iteration is far off, and before the line search and the
            // violent-substep iterations the state stored up to 10× the energy put in (its segments left stretched with
            // no tension). Now the solve converges and the total energy only falls. (Since the position remainders the
            // steel rope with 10⁶ under BDF2 needs no violent substep at all: 0 counted.)
            var test = new StabilityCase
            {
                YoungsModulus = youngsModulus, MassRatio = massRatio, SegmentCount = 256, Stretch = 10f, Integrator = integrator,
            };
            StabilityResult result = test.Run(1.0);
            TestContext.WriteLine($"E0 {result.InitialEnergy:G4} J, gain {result.LargestEnergyGain:G3} J, violent substeps {result.ViolentSubsteps}, unconverged {result.UnconvergedSubsteps}, reach {result.FarthestFromAnchor:G4} m");
            Assert.That(result.Finite, Is.True);
            Assert.That(result.LargestEnergyGain, Is.LessThanOrEqualTo(1e-4 * Math.Abs(result.InitialEnergy) + 1e-6));
            Assert.That(result.FarthestFromAnchor, Is.LessThan(test.ReachBound(result)));
        }

        [Test]
        public void TenThousandSegmentsStayFinite()
        {
            var test = new StabilityCase { YoungsModulus = 2e11f, MassRatio = 1e3, SegmentCount = 10000, RestLength = 100f };
            StabilityResult result = test.Run(0.1);
            Assert.That(result.Finite, Is.True);
            Assert.That(result.LargestEnergyGain, Is.LessThanOrEqualTo(1e-4 * Math.Abs(result.InitialEnergy) + 1e-6));
        }

        [Test]
        public void AnchorTeleportedOneKilometreRecovers()
        {
            // the anchor jumps 1 km in one step (90 km/s): the rope is yanked along, never gains energy, and
            // within 20 s hangs from the new anchor again (numerical damping only, Damping = 0)
            var test = new StabilityCase { YoungsModulus = 1e9f, MassRatio = 100.0, TeleportDistance = 1000f };
            StabilityResult result = test.Run(20.0);
            TestContext.WriteLine($"after teleport: ceiling {result.EnergyCeiling:G4} J, gain {result.LargestEnergyGain:G3} J, final KE {result.FinalKineticEnergy:G3} J, reach {result.FarthestFromAnchor:G4} m");
            Assert.That(result.Finite, Is.True);
            Assert.That(result.LargestEnergyGain, Is.LessThanOrEqualTo(1e-4 * result.EnergyCeiling + 1e-6));
            Assert.That(result.FarthestFromAnchor, Is.LessThan(test.ReachBound(result)), "the rope hangs from the new anchor again");
        }

        [Test]
        public void CoincidentParticlesUnfoldIntoAHangingRope()
        {
            var test = new StabilityCase { Coincident = true, MassRatio = 10.0 };
            StabilityResult result = test.Run(4.0);
            TestContext.WriteLine($"coincident: reach {result.FarthestFromAnchor:G6} m, final KE {result.FinalKineticEnergy:G3} J");
            Assert.That(result.Finite, Is.True);
            Assert.That(result.FarthestFromAnchor, Is.EqualTo(test.RestLength).Within(2).Percent, "the load ends one rope length below the anchor");
        }
    }
}
