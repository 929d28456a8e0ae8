using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Simulation
{
    public sealed class RopeReadoutsTests
    {
        private const float Step = 1f / 90f;

        private static RopeSimulation Hanging(out int load)
        {
            var s = new RopeSettings { RestLength = 1f, SegmentCount = 10, Radius = 0.005f, YoungsModulus = 1e9f, Density = 1140f, Damping = 0.01f };
            s.AxialStiffness = 2000f;
            var sim = new RopeSimulation(s, Float3.Zero, new Float3(0f, -1f, 0f));
            sim.Rope.AddPin(0, Float3.Zero);
            load = sim.Rope.AddLoad(10, 5f);
            return sim;
        }

        [Test]
        public void ElongationAfterABreakCountsOnlyTheIntactSegments()
        {
            var sim = Hanging(out _);
            for (int i = 0; i < 90; i++) sim.Step(Step);
            Assert.That(sim.Readouts.Elongation, Is.GreaterThan(0.01), "5 kg on E·A 2000 N stretches about 2.5 cm");
            sim.Rope.BreakSegment(4);
            sim.Step(Step);
            var lengths = sim.Rope.SegmentLengths;
            var rest = sim.Rope.RestLengths;
            double intact = 0, all = 0, intactRest = 0;
            for (int j = 0; j < 10; j++)
            {
                all += lengths[j];
                if (j == 4) continue;
                intact += lengths[j] - rest[j];
                intactRest += rest[j];
            }
            Assert.That(sim.Readouts.Elongation, Is.EqualTo(intact).Within(1e-9));
            Assert.That(sim.Readouts.Strain, Is.EqualTo(intact / intactRest).Within(1e-9));
            Assert.That(Math.Abs(sim.Readouts.Elongation - (all - 1.0)), Is.GreaterThan(1e-4), "the 0.1 component formula counted the broken segment's length");
            Assert.That(sim.Readouts.IsBroken, Is.True);
            Assert.That(sim.Readouts.FirstBreak.HasValue, Is.True);
            Assert.That(sim.Readouts.FirstBreak.Value.Segment, Is.EqualTo(4));
        }

        [Test]
        public void TensionsPeaksAndTheirReset()
        {
            var sim = Hanging(out _);
            Assert.That(sim.Readouts.FirstBreak.HasValue, Is.False);
            for (int i = 0; i < 45; i++) sim.Step(Step);
            var tensions = sim.Rope.Tensions;
            Assert.That(sim.Readouts.TopTension, Is.EqualTo(tensions[0]));
            Assert.That(sim.Readouts.BottomTension, Is.EqualTo(tensions[9]));
            Assert.That(sim.Readouts.PeakTension, Is.GreaterThanOrEqualTo(sim.Readouts.TopTension));
            Assert.That(sim.Readouts.Residual, Is.GreaterThanOrEqualTo(0f));
            Assert.That(sim.Readouts.MinRadius, Is.EqualTo(0.005f));
            Assert.That(sim.Readouts.NeckRadius, Is.EqualTo(0.005f));
            sim.Readouts.ResetPeaks();
            Assert.That(sim.Readouts.PeakTension, Is.EqualTo(0f));
            Assert.That(sim.Readouts.PeakArrestForce, Is.EqualTo(0f));
            sim.Step(Step);
            Assert.That(sim.Readouts.PeakTension, Is.GreaterThan(0f));
            sim.Rope.BreakSegment(0);
            sim.Step(Step);
            Assert.That(sim.Readouts.TopTension, Is.EqualTo(0f), "0 once broken");
        }

        [Test]
        public void ArrestForceUsesTheLoadWhenOneIsSet()
        {
            var sim = Hanging(out int load);
            for (int i = 0; i < 30; i++) sim.Step(Step);
            Assert.That(sim.Readouts.ArrestLoad, Is.EqualTo(-1));
            Assert.That(sim.Readouts.ArrestForce, Is.EqualTo(sim.Readouts.BottomTension));
            sim.Readouts.ArrestLoad = load;
            sim.Step(Step);
            Assert.That(sim.Readouts.ArrestForce, Is.EqualTo(sim.Rope.GetLoadForce(load).Length));
            Assert.That(sim.Readouts.PeakArrestForce, Is.GreaterThanOrEqualTo(sim.Readouts.ArrestForce));
            Assert.Throws<ArgumentOutOfRangeException>(() => sim.Readouts.ArrestLoad = 7);
        }
    }
}
