using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using HookeRope.Tests.Core.Geometry;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// The opt-in fused single-precision Gauss–Seidel kernel (<see cref="GaussSeidelKernel.FusedSingle"/>, issue 18 item 1)
    /// against numbers: a hanging loaded chain reads its weight, a soft rope stretches as Hooke's law says, a pendulum
    /// neither gains energy nor loses more than the precise kernel's backward Euler does, every rope it does not serve runs
    /// the precise kernel bit for bit, a step allocates nothing, and no steel rope or bad input turns it non-finite. Every
    /// case also runs the precise kernel (<see cref="GaussSeidelKernel.Precise"/>) and bounds the difference.
    /// </summary>
    public sealed class FusedGaussSeidelTests
    {
        static RopeSettings Settings(GaussSeidelKernel kernel, float youngsModulus, float damping, int substeps, int iterations, int segments = 16, float length = 1f)
        {
            var settings = RopeTestKit.Legacy(length: length, segments: segments, youngsModulus: youngsModulus, damping: damping, substeps: substeps,
                iterations: iterations, solver: ConstraintSolverKind.GaussSeidel);
            settings.Integrator = TimeIntegrator.BackwardEuler;
            settings.GaussSeidelKernel = kernel;
            return settings;
        }

        static void Run(Rope rope, int steps)
        {
            for (int i = 0; i < steps; i++) rope.Step(RopeTestKit.HostStep);
        }

        [Test]
        public void TheDefaultIsThePreciseKernelAndAnUnknownValueThrowsNamingTheSetting()
        {
            var settings = new RopeSettings();
            Assert.That(settings.GaussSeidelKernel, Is.EqualTo(GaussSeidelKernel.Precise));
            Assert.That(RopeParameters.GaussSeidelKernel.Default, Is.EqualTo(GaussSeidelKernel.Precise));
            int version = settings.Version;
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => settings.GaussSeidelKernel = (GaussSeidelKernel)7);
            Assert.That(e.ParamName, Is.EqualTo(nameof(RopeSettings.GaussSeidelKernel)));
            Assert.That(settings.GaussSeidelKernel, Is.EqualTo(GaussSeidelKernel.Precise));
            Assert.That(settings.Version, Is.EqualTo(version), "a rejected value changes nothing");
            settings.GaussSeidelKernel = GaussSeidelKernel.FusedSingle;
            Assert.That(settings.Version, Is.EqualTo(version + 1));
            Assert.That(settings.Clone().GaussSeidelKernel, Is.EqualTo(GaussSeidelKernel.FusedSingle));
        }

        // 1 m, 16 segments, E 1 GPa, R 5 mm (5.6 g per particle) with 0.5 kg at the end, damped to rest over 4 s. At 8 × 1
        // Gauss–Seidel itself is unconverged at this mass ratio (−1.3 % in either kernel), so the cases converge it by
        // substeps or iterations.
        [TestCase(64, 1)]
        [TestCase(8, 16)]
        [TestCase(64, 16)]
        public void AHangingLoadedChainsTopTensionAndPinForceAreItsWeight(int substeps, int iterations)
        {
            const float load = 0.5f;
            double[] top = new double[2], pin = new double[2];
            for (int kernel = 0; kernel < 2; kernel++)
            {
                var settings = Settings((GaussSeidelKernel)kernel, 1e9f, 0.01f, substeps, iterations);
                var rope = RopeTestKit.Hanging(settings, load, out _);
                double weight = (load + settings.LinearDensity * 1.0) * RopeTestKit.G;
                double carried = (load + settings.LinearDensity * (1.0 - 0.5 / 16)) * RopeTestKit.G;
                Run(rope, 315);
                double worst = 0.0;
                for (int i = 0; i < 45; i++)
                {
                    rope.Step(RopeTestKit.HostStep);
                    worst = Math.Max(worst, Math.Abs(rope.GetPinForce(0).Length / weight - 1.0));
                }
                top[kernel] = rope.Tensions[0] / carried - 1.0;
                pin[kernel] = worst;
                Assert.That(RopeTestKit.AllFinite(rope), Is.True);
            }
            TestContext.WriteLine($"{substeps} x {iterations}: top tension error precise {top[0] * 100:F4} %, fused {top[1] * 100:F4} %; worst pin force error over the last 0.5 s precise {pin[0] * 100:F4} %, fused {pin[1] * 100:F4} %");
            Assert.That(Math.Abs(top[1]), Is.LessThan(1e-3), "fused: top segment tension = the weight below it within 0.1 %");
            Assert.That(pin[1], Is.LessThan(1e-3), "fused: pin force = the total weight within 0.1 %");
            Assert.That(Math.Abs(top[1] - top[0]), Is.LessThan(5e-4), "fused against precise: within 0.05 % of the weight");
        }

        [Test]
        public void ASoftRopeStretchesUnderItsOwnWeightAsHookesLawSays()
        {
            // E 0.1 MPa: the self-weight stretch μ·g·L²/(2·E·A) = 5.6 cm is far above Gauss–Seidel's own error at 8 × 16
            double[] error = new double[2];
            for (int kernel = 0; kernel < 2; kernel++)
            {
                var settings = Settings((GaussSeidelKernel)kernel, 1e5f, 0.05f, 8, 16);
                var rope = RopeTestKit.Hanging(settings, 0f, out _);
                Run(rope, 720);
                double stretch = -1.0;
                foreach (float l in rope.SegmentLengths) stretch += l;
                double expected = settings.LinearDensity * RopeTestKit.G * 0.5 / settings.AxialStiffness;
                error[kernel] = stretch / expected - 1.0;
            }
            TestContext.WriteLine($"stretch against Hooke's law: precise {error[0] * 100:F4} %, fused {error[1] * 100:F4} %");
            Assert.That(Math.Abs(error[1]), Is.LessThan(1e-3), "fused: within 0.1 % of Hooke's law");
            Assert.That(Math.Abs(error[1] - error[0]), Is.LessThan(1e-4), "fused against precise");
        }

        [Test]
        public void APendulumNeverGainsEnergyAndLosesWhatBackwardEulerLoses()
        {
            // undamped (β 0), released at 30°, 64 substeps × 1 iteration (Gauss–Seidel converged enough that its elastic
            // energy is the rope's): backward Euler's own dissipation is the only loss
            double[] lost = new double[2], above = new double[2];
            for (int kernel = 0; kernel < 2; kernel++)
            {
                var rope = RopeTestKit.ReleasedAt30Degrees(Settings((GaussSeidelKernel)kernel, 1e9f, 0f, 64, 1));
                double start = rope.TotalEnergy(), most = double.MinValue;
                for (int i = 0; i < 450; i++)
                {
                    rope.Step(RopeTestKit.HostStep);
                    most = Math.Max(most, rope.TotalEnergy() - start);
                }
                lost[kernel] = start - rope.TotalEnergy();
                above[kernel] = most;
            }
            TestContext.WriteLine($"5 s: lost precise {lost[0]:G4} J, fused {lost[1]:G4} J; most above the start precise {above[0]:G3} J, fused {above[1]:G3} J");
            // the swing holds 0.059 J (a 30° release of 89.5 g, centre 0.5 m below the pin); 1e-4 J is the elastic energy's round-off band
            Assert.That(above[1], Is.LessThan(1e-4), "fused: never above the start energy");
            Assert.That(lost[1], Is.GreaterThan(0.0));
            Assert.That(lost[1], Is.EqualTo(lost[0]).Within(10).Percent, "fused: the loss of backward Euler, as the precise kernel");
        }

        /// <summary>A rope of each feature the fused kernel lacks (it falls back to the precise kernel).</summary>
        static Rope FeatureRope(string feature, GaussSeidelKernel kernel)
        {
            var settings = Settings(kernel, 1e9f, 0.002f, 8, 2);
            if (feature == "bdf2") settings.Integrator = TimeIntegrator.Bdf2;
            if (feature == "exact") settings.Solver = ConstraintSolverKind.ExactChain;
            if (feature == "drag") settings.DragCoefficient = 1.2f;
            if (feature == "absorber") settings.UseEnergyAbsorber(50f, 0.2f);
            if (feature == "plastic") settings.MaterialModel = MaterialModel.ElasticPlastic;
            var rope = new Rope(settings, Float3.Zero, new Float3(1f, 0f, 0f));
            rope.AddPin(0, Float3.Zero);
            rope.AddLoad(16, 0.3f);
            if (feature == "collider") rope.AddCollider(ColliderShape.Sphere(new Float3(0.5f, -0.6f, 0f), 0.2f, 0.3f));
            if (feature == "compliant-pin") rope.AddPin(16, new Float3(0.9f, -0.2f, 0f), 1e-4f);
            return rope;
        }

        [TestCase("bdf2")]
        [TestCase("exact")]
        [TestCase("drag")]
        [TestCase("absorber")]
        [TestCase("plastic")]
        [TestCase("collider")]
        [TestCase("compliant-pin")]
        public void ARopeWithAFeatureItLacksRunsThePreciseKernelBitForBit(string feature)
        {
            var precise = FeatureRope(feature, GaussSeidelKernel.Precise);
            var fused = FeatureRope(feature, GaussSeidelKernel.FusedSingle);
            for (int i = 0; i < 90; i++)
            {
                StepReport a = precise.Step(RopeTestKit.HostStep), b = fused.Step(RopeTestKit.HostStep);
                Assert.That(b.Residual, Is.EqualTo(a.Residual), feature);
            }
            for (int p = 0; p < precise.ParticleCount; p++)
            {
                Assert.That(fused.PositionX[p], Is.EqualTo(precise.PositionX[p]), feature + " x " + p);
                Assert.That(fused.PositionY[p], Is.EqualTo(precise.PositionY[p]), feature + " y " + p);
                Assert.That(fused.PositionZ[p], Is.EqualTo(precise.PositionZ[p]), feature + " z " + p);
                Assert.That(fused.GetVelocity(p), Is.EqualTo(precise.GetVelocity(p)), feature + " v " + p);
            }
            for (int j = 0; j < precise.SegmentCount; j++)
            {
                Assert.That(fused.Tensions[j], Is.EqualTo(precise.Tensions[j]), feature + " T " + j);
                Assert.That(fused.PeakTensions[j], Is.EqualTo(precise.PeakTensions[j]), feature + " peak " + j);
            }
        }

        [Test]
        public void TheFusedKernelRunsForAPlainChainAndDiffersFromThePreciseOne()
        {
            // the counterpart of the fallback cases: a plain chain does take the fused path (its float round-off differs)
            var precise = FeatureRope("plain", GaussSeidelKernel.Precise);
            var fused = FeatureRope("plain", GaussSeidelKernel.FusedSingle);
            Run(precise, 90);
            Run(fused, 90);
            double largest = 0.0;
            for (int p = 0; p < precise.ParticleCount; p++) largest = Math.Max(largest, (fused.GetPosition(p) - precise.GetPosition(p)).Length);
            TestContext.WriteLine($"swinging 1 m chain after 1 s: largest particle distance fused - precise {largest:G3} m");
            Assert.That(largest, Is.GreaterThan(0.0), "the fused kernel ran");
            Assert.That(largest, Is.LessThan(1e-3), "and swung the chain as the precise kernel did, within 1 mm");
        }

        [Test]
        public void TheSimulationFacadeReadsTheFusedRopeAsThePreciseOne()
        {
            // RopeSimulation (radius model, read-outs) on top of the fused step: the hanging rope of the load case at 64 × 1
            double[] top = new double[2], pin = new double[2];
            for (int kernel = 0; kernel < 2; kernel++)
            {
                var settings = Settings((GaussSeidelKernel)kernel, 1e9f, 0.01f, 64, 1);
                var simulation = new RopeSimulation(settings, Float3.Zero, new Float3(0f, -1f, 0f), new HookeRope.Radius.RadiusSettings());
                simulation.Rope.AddPin(0, Float3.Zero);
                simulation.Rope.AddLoad(16, 0.5f);
                for (int i = 0; i < 360; i++) simulation.Step(RopeTestKit.HostStep);
                top[kernel] = simulation.Rope.Tensions[0];
                pin[kernel] = simulation.Rope.GetPinForce(0).Length;
                Assert.That(RopeTestKit.AllFinite(simulation.Rope), Is.True);
            }
            Assert.That(top[1], Is.EqualTo(top[0]).Within(0.05).Percent);
            Assert.That(pin[1], Is.EqualTo(pin[0]).Within(0.05).Percent);
        }

        [Test]
        public void AStepAllocatesNothing()
        {
            var rope = RopeTestKit.Hanging(Settings(GaussSeidelKernel.FusedSingle, 1e9f, 0.002f, 8, 1), 0.5f, out _);
            rope.AddPin(8, new Float3(0f, -0.5f, 0f), 0f, 1e6f); // a breakable pin: the per-substep pin force path
            long bytes = SteadyStateAllocation.Bytes(() => rope.Step(RopeTestKit.HostStep), 50);
            Assert.That(bytes, Is.EqualTo(0));
            var several = RopeTestKit.Hanging(Settings(GaussSeidelKernel.FusedSingle, 1e9f, 0.002f, 8, 4), 0.5f, out _);
            Assert.That(SteadyStateAllocation.Bytes(() => several.Step(RopeTestKit.HostStep), 50), Is.EqualTo(0));
        }

        [TestCase(1, 1)]
        [TestCase(8, 1)]
        [TestCase(64, 4)]
        public void SteelNeverTurnsNonFinite(int substeps, int iterations)
        {
            // 200 GPa steel, 10 m, 64 segments, 500 kg dropped from 1 m of slack; then released horizontal and snatched
            var settings = Settings(GaussSeidelKernel.FusedSingle, 200e9f, 0.005f, substeps, iterations, 64, 10f);
            settings.Density = 7850f;
            var rope = new Rope(settings, Float3.Zero, new Float3(0f, -9f, 0f));
            rope.AddPin(0, Float3.Zero);
            rope.AddLoad(64, 500f);
            var swing = new Rope(settings, Float3.Zero, new Float3(10f, 0f, 0f));
            swing.AddPin(0, Float3.Zero);
            for (int i = 0; i < 180; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                swing.Step(RopeTestKit.HostStep);
                Assert.That(RopeTestKit.AllFinite(rope), Is.True, "dropped load, step " + i);
                Assert.That(RopeTestKit.AllFinite(swing), Is.True, "swing, step " + i);
            }
            Assert.That(rope.GetPinForce(0).IsFinite, Is.True);
        }

        [Test]
        public void BadInputNeverTurnsNonFinite()
        {
            var rope = RopeTestKit.Hanging(Settings(GaussSeidelKernel.FusedSingle, 1e9f, 0.002f, 8, 1), 0.5f, out _);
            Run(rope, 10);
            // a particle thrown at 1e30 m/s (finite, so accepted) overflows float within one substep
            rope.SetVelocity(8, new Float3(1e30f, 0f, 0f));
            rope.Step(RopeTestKit.HostStep);
            Assert.That(RopeTestKit.AllFinite(rope), Is.True, "after the throw");
            // the anchor teleported 1 km, and a particle placed 1e6 m away
            rope.SetPinTarget(0, new Float3(1000f, 0f, 0f));
            rope.SetPosition(4, new Float3(0f, 1e6f, 0f));
            for (int i = 0; i < 90; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                Assert.That(RopeTestKit.AllFinite(rope), Is.True, "step " + i);
            }
            Assert.That(rope.GetPosition(0).X, Is.EqualTo(1000f).Within(1e-3f), "the pin arrived");
        }

        [Test]
        public void ACutRopeFallsApartAndAPinBreaksAboveItsForce()
        {
            var rope = RopeTestKit.Hanging(Settings(GaussSeidelKernel.FusedSingle, 1e9f, 0.01f, 8, 4), 0.5f, out _);
            Run(rope, 90);
            float before = rope.Tensions[0];
            rope.BreakSegment(8);
            Run(rope, 45);
            Assert.That(rope.Tensions[8], Is.EqualTo(0f));
            Assert.That(rope.GetVelocity(16).Y, Is.LessThan(-3.0f), "the cut end falls (g·0.5 s = 4.9 m/s)");
            Assert.That(rope.Tensions[0], Is.LessThan(0.2f * before), "the top half carries only its own 45 g (0.4 N of the 5.3 N before)");

            var pinned = RopeTestKit.Hanging(Settings(GaussSeidelKernel.FusedSingle, 1e9f, 0.01f, 8, 4), 0.5f, out _);
            pinned.AddPin(16, new Float3(0f, -1f, 0f), 0f, 20f);
            Run(pinned, 30);
            Assert.That(pinned.IsPinBroken(1), Is.False);
            pinned.SetPinTarget(1, new Float3(0f, -1.5f, 0f)); // pulled 0.5 m down: the rope's pull far exceeds 20 N
            Run(pinned, 10);
            Assert.That(pinned.IsPinBroken(1), Is.True);
            Assert.That(RopeTestKit.AllFinite(pinned), Is.True);
        }
    }
}
