using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.MaterialLaw
{
    /// <summary>
    /// Issue 15 item 2: a 100 kg mass after a 4 m free fall on a 2 m stiff webbing lanyard (E·A 100 kN, k = E·A/L = 50 kN/m)
    /// with a 4 kN absorber. The arrest force is read inside the step (the load's substep peak, the read-out's
    /// <see cref="RopeReadouts.PeakArrestForce"/>); the deployment x_d against the energy balance
    /// M·g·(h + x_e + x_d) = F_p·x_d + F_p²/(2k), x_e = F_p/k (massless lanyard: x_d = 1.2728 m).
    /// </summary>
    public sealed class EnergyAbsorberTests
    {
        const double Mass = 100, H = 4, Plateau = 4000, K = 1e5 / 2;

        static double Weight => Mass * MaterialTestKit.G;

        /// <summary>x_d from M·g·(h + x_e + x_d) = F_p·x_d + F_p²/(2k).</summary>
        static double Deployment => (Weight * (H + Plateau / K) - Plateau * Plateau / (2 * K)) / (Plateau - Weight);

        static RopeSimulation Arrest(RopeSettings settings, out Rope rope, double seconds = 3.0)
        {
            rope = MaterialTestKit.Lanyard(settings, out int load);
            var sim = new RopeSimulation(rope);
            sim.Readouts.ArrestLoad = load;
            for (int k = 0; k < (int)(seconds * 90); k++) sim.Step(MaterialTestKit.HostStep);
            return sim;
        }

        [Test]
        public void AbsorberHoldsTheArrestForceAtItsPlateauAndDeploysByTheEnergyBalance()
        {
            var sim = Arrest(MaterialTestKit.LanyardSettings(absorber: true), out Rope rope);
            var r = sim.Readouts;
            TestContext.WriteLine($"peak arrest force {r.PeakArrestForce:F1} N (plateau {Plateau} N), deployment {r.AbsorberDeployment:F4} m (energy balance {Deployment:F4} m, {(r.AbsorberDeployment / Deployment - 1) * 100:F2} %)");
            Assert.That(r.PeakArrestForce, Is.EqualTo(Plateau).Within(2).Percent);
            Assert.That(r.AbsorberDeployment, Is.EqualTo(Deployment).Within(2).Percent);
            Assert.That(Deployment, Is.EqualTo(1.27).Within(0.01), "the issue's ≈ 1.27 m");
            Assert.That(r.MeetsEn355, Is.True, "EN 355: ≤ 6 kN");
            Assert.That(rope.AbsorberSegment, Is.EqualTo(rope.SegmentCount - 1));
            Assert.That(r.PlasticElongation, Is.EqualTo(r.AbsorberDeployment).Within(1e-9), "all the set is the absorber's");
        }

        [Test]
        public void WithoutTheAbsorberTheSameLanyardPeaksAtTheLinearFormula()
        {
            var sim = Arrest(MaterialTestKit.LanyardSettings(absorber: false), out _, 1.5);
            double linear = Weight + Math.Sqrt(Weight * Weight + 2 * Weight * K * H);
            TestContext.WriteLine($"peak arrest force {sim.Readouts.PeakArrestForce:F1} N, linear formula {linear:F1} N");
            Assert.That(sim.Readouts.PeakArrestForce, Is.EqualTo(linear).Within(2).Percent, "Mg + sqrt((Mg)² + 2Mgkh) = 20.8 kN");
            Assert.That(sim.Readouts.MeetsEn355, Is.False, "EN 355 fails");
            Assert.That(sim.Readouts.AbsorberDeployment, Is.EqualTo(0.0));
        }

        [Test]
        public void UsedUpAbsorberHandsTheArrestToTheWebbing()
        {
            // 0.5 m of deployment is not enough: once it is used up, the webbing stretches on from F_p:
            // M·g·(h + x_d + x) = F_p·x_d + ½k·x² − … with x the webbing's total stretch; F = k·x
            const double Short = 0.5;
            var sim = Arrest(MaterialTestKit.LanyardSettings(absorber: true, deployment: (float)Short), out _, 1.5);
            // M g (h + x_d + x) = F_p x_d + ½ k x²  →  ½k x² − M g x − (M g (h + x_d) − F_p x_d) = 0
            double c = Weight * (H + Short) - Plateau * Short;
            double x = (Weight + Math.Sqrt(Weight * Weight + 2 * K * c)) / K;
            TestContext.WriteLine($"peak {sim.Readouts.PeakArrestForce:F1} N, energy balance {K * x:F1} N, deployment {sim.Readouts.AbsorberDeployment:F4} m");
            Assert.That(sim.Readouts.AbsorberDeployment, Is.EqualTo(Short).Within(1e-6), "fully deployed");
            Assert.That(sim.Readouts.PeakArrestForce, Is.EqualTo(K * x).Within(2).Percent);
        }

        [TestCase(ConstraintSolverKind.ExactChain)]
        [TestCase(ConstraintSolverKind.GaussSeidel)]
        public void BothSolversCapTheForceOnAOneSegmentLanyard(ConstraintSolverKind solver)
        {
            // one segment: Gauss–Seidel's projection is exact as well (a heavy load on many segments is its known weakness)
            var sim = Arrest(MaterialTestKit.LanyardSettings(absorber: true, segments: 1, solver: solver), out _, 2.0);
            TestContext.WriteLine($"{solver}: peak {sim.Readouts.PeakArrestForce:F1} N, deployment {sim.Readouts.AbsorberDeployment:F4} m");
            Assert.That(sim.Readouts.PeakArrestForce, Is.EqualTo(Plateau).Within(2).Percent);
            Assert.That(sim.Readouts.AbsorberDeployment, Is.EqualTo(Deployment).Within(2).Percent);
        }

        [Test]
        public void PresetStepsWithoutAllocating()
        {
            var rope = MaterialTestKit.Lanyard(MaterialTestKit.LanyardSettings(absorber: true), out int load);
            var sim = new RopeSimulation(rope);
            for (int k = 0; k < 5; k++) sim.Step(MaterialTestKit.HostStep);   // taut from step 1, deploying for ≈ 0.3 s
            long bytes = HookeRope.Tests.Core.Geometry.SteadyStateAllocation.Bytes(() => sim.Step(MaterialTestKit.HostStep), 2);
            Assert.That(bytes, Is.EqualTo(0), "0 B per step while it deploys");
            Assert.That(rope.AbsorberDeployment, Is.GreaterThan(0.1));
        }
    }
}
