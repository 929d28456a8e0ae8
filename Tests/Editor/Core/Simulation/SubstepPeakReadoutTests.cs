using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using HookeRope.Tests.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Simulation
{
    /// <summary>
    /// Issue 14 item 3: the peak read-outs take the maximum over the substeps. A 200 kg load snatches a 5 m steel wire
    /// rope (E 100 GPa, R 4 mm, 24 segments) after 0.2 m of slack at the defaults (8 substeps, 1/90 s, backward Euler):
    /// the arrest lasts about four host steps, so its peak falls between two of them.
    /// </summary>
    public sealed class SubstepPeakReadoutTests
    {
        private const float HostStep = 1f / 90f, Length = 5f, Slack = 0.2f, Mass = 200f;

        [TestCase(TimeIntegrator.BackwardEuler)]
        [TestCase(TimeIntegrator.Bdf2)]
        public void SnatchPeakReadsTheSubstepMaximumAboveTheEndOfStepValue(TimeIntegrator integrator)
        {
            var s = RopeTestKit.Legacy(Length, 24, radius: 0.004f, youngsModulus: 1e11f, density: 7850f);
            s.Integrator = integrator;
            var sim = new RopeSimulation(s, Float3.Zero, new Float3(0f, -(Length - Slack), 0f));
            sim.Rope.AddPin(0, Float3.Zero);
            int load = sim.Rope.AddLoad(sim.Rope.ParticleCount - 1, Mass);
            sim.Readouts.ArrestLoad = load;
            float substepPeak = 0f, endOfStepPeak = 0f, loadSubstepPeak = 0f, loadMeanPeak = 0f;
            for (int k = 0; k < 32; k++)
            {
                sim.Step(HostStep);
                var peaks = sim.Rope.PeakTensions;
                var tensions = sim.Rope.Tensions;
                for (int j = 0; j < peaks.Length; j++)
                {
                    substepPeak = Math.Max(substepPeak, peaks[j]);
                    endOfStepPeak = Math.Max(endOfStepPeak, tensions[j]);
                }
                loadSubstepPeak = Math.Max(loadSubstepPeak, sim.Rope.GetLoadPeakForce(load));
                loadMeanPeak = Math.Max(loadMeanPeak, sim.Rope.GetLoadForce(load).Length);
            }
            double mg = Mass * RopeTestKit.G, k0 = 1e11 * Math.PI * 0.004 * 0.004 / Length;
            double expected = mg + Math.Sqrt(mg * mg + 2.0 * mg * k0 * Slack);
            TestContext.WriteLine($"{integrator}: PeakTension {sim.Readouts.PeakTension:R} N (end-of-step largest {endOfStepPeak:R} N, +{(sim.Readouts.PeakTension / endOfStepPeak - 1) * 100:F2} %), " +
                $"PeakArrestForce {sim.Readouts.PeakArrestForce:R} N (host-step mean largest {loadMeanPeak:R} N, +{(sim.Readouts.PeakArrestForce / loadMeanPeak - 1) * 100:F2} %), " +
                $"massless formula {expected:F1} N: tension {(sim.Readouts.PeakTension / expected - 1) * 100:F2} %, arrest {(sim.Readouts.PeakArrestForce / expected - 1) * 100:F2} %");
            Assert.That(sim.Readouts.PeakTension, Is.EqualTo(substepPeak), "the read-out is the substep maximum");
            Assert.That(sim.Readouts.PeakArrestForce, Is.EqualTo(loadSubstepPeak), "the arrest read-out is the load's substep maximum");
            // measured: tension +0.57 % (backward Euler) / +2.05 % (BDF2) above the largest end-of-step value; arrest
            // +7.63 % / +3.97 % above the largest host-step mean load force
            Assert.That(sim.Readouts.PeakTension, Is.GreaterThan(1.005f * endOfStepPeak));
            Assert.That(sim.Readouts.PeakArrestForce, Is.GreaterThan(1.03f * loadMeanPeak));
            if (integrator == TimeIntegrator.BackwardEuler) return;   // its numerical damping reads 7.4 % low (solver.md)
            // BDF2 measured −0.30 % (tension) and −1.21 % (arrest) against the massless formula
            Assert.That(sim.Readouts.PeakTension, Is.EqualTo(expected).Within(2).Percent);
            Assert.That(sim.Readouts.PeakArrestForce, Is.EqualTo(expected).Within(2).Percent);
        }
    }
}
