using NUnit.Framework;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode: pulled past its break strain the rope breaks once, at its mid-rope defect, raising OnBreak with the
    /// tension E·A·strain of the breaking segment; afterwards the read-outs describe the intact segments only.
    /// </summary>
    [TestFixture]
    public sealed class RopeFractureTests
    {
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        /// <summary>A 1 m rope of 20 segments, break strain 0.2, from a top anchor at 3 m to a grip at 2 m.</summary>
        (ElasticRope Rope, Transform Top, Transform Grip) RopeToBreak()
        {
            var top = _scene.Point("Top", new Vector3(0f, 3f, 0f));
            var grip = _scene.Point("Grip", new Vector3(0f, 2f, 0f));
            var rope = _scene.Rope("Rope", top.position);
            rope.RestLength = 1f;
            rope.SegmentCount = 20;
            rope.Fracture = true;
            rope.BreakStrain = 0.2f;
            rope.StartAttachment.Point = top;
            rope.EndAttachment.Point = grip;
            rope.Rebuild();
            return (rope, top, grip);
        }

        [Test]
        public void PulledPastBreakStrainBreaksOnce()
        {
            var (rope, top, grip) = RopeToBreak();

            int breaks = 0;
            float tension = 0f;
            Vector3 where = Vector3.zero;
            float gripAtBreak = 0f;
            rope.OnBreak.AddListener((position, peak) => { breaks++; tension = peak; where = position; gripAtBreak = grip.position.y; });
            for (int step = 0; step < 200; step++)
            {
                grip.position = new Vector3(0f, 2f - 0.005f * step, 0f);
                rope.Simulate(0.01f);
            }

            Assert.That(rope.IsBroken, Is.True);
            Assert.That(breaks, Is.EqualTo(1));
            TestContext.WriteLine("break at " + where + ", tension " + tension + " N");
            // the defect segment breaks at strain 0.2: tension E·A·0.2 (the pull at 0.5 m/s adds a few % of wave load)
            Assert.That(tension, Is.EqualTo(rope.AxialStiffness * 0.2f).Within(5).Percent);
            // the default defect sits mid-rope: the break is halfway between the top and the grip
            Assert.That(where.y, Is.EqualTo(0.5f * (top.position.y + gripAtBreak)).Within(0.05f));
        }

        [Test]
        public void ReadoutsAfterABreakCountTheIntactSegmentsOnly()
        {
            var (rope, _, grip) = RopeToBreak();
            for (int step = 0; step < 200 && !rope.IsBroken; step++)
            {
                grip.position = new Vector3(0f, 2f - 0.005f * step, 0f);
                rope.Simulate(0.01f);
            }
            Assert.That(rope.IsBroken, Is.True);
            for (int step = 0; step < 5; step++) rope.Simulate(0.01f);

            var core = rope.Simulation.Rope;
            double elongation = 0.0, intactRest = 0.0, allLengths = 0.0;
            int broken = -1;
            for (int j = 0; j < core.SegmentCount; j++)
            {
                allLengths += core.SegmentLengths[j];
                if (core.IsSegmentBroken(j)) { broken = j; continue; }
                elongation += core.SegmentLengths[j] - core.RestLengths[j];
                intactRest += core.RestLengths[j];
            }
            Assert.That(broken, Is.EqualTo(10), "the mid-rope defect segment broke");
            Assert.That(rope.Elongation, Is.EqualTo((float)elongation).Within(1e-6f), "Σ over the intact segments of (l − L_j)");
            Assert.That(rope.Elongation, Is.Not.EqualTo((float)(allLengths - rope.RestLength)).Within(1e-4f), "not Σ l − L over the whole rope");
            Assert.That(rope.Strain, Is.EqualTo((float)(elongation / intactRest)).Within(1e-6f));
            Assert.That(rope.Elongation, Is.EqualTo((float)rope.Simulation.Readouts.Elongation));
            Assert.That(rope.TopTension, Is.EqualTo(rope.Simulation.Readouts.TopTension));
            Assert.That(rope.BottomTension, Is.EqualTo(rope.Simulation.Readouts.BottomTension));
            Assert.That(rope.PeakTension, Is.GreaterThanOrEqualTo(rope.AxialStiffness * 0.2f * 0.95f), "the peak before the break is kept");
            Assert.That(rope.Simulation.Readouts.FirstBreak.HasValue, Is.True);
            Assert.That(rope.Simulation.Readouts.FirstBreak.Value.Segment, Is.EqualTo(10));
        }
    }
}
