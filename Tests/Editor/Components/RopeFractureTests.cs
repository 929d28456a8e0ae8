using NUnit.Framework;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>Unity only (edit mode): pulled past its break strain the rope breaks once, raising OnBreak with a positive tension.</summary>
    [TestFixture]
    public sealed class RopeFractureTests
    {
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        [Test]
        public void PulledPastBreakStrainBreaksOnce()
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

            int breaks = 0;
            float tension = 0f;
            rope.OnBreak.AddListener((position, peak) => { breaks++; tension = peak; });
            for (int step = 0; step < 200; step++)
            {
                grip.position = new Vector3(0f, 2f - 0.005f * step, 0f);
                rope.Simulate(0.01f);
            }

            Assert.That(rope.IsBroken, Is.True);
            Assert.That(breaks, Is.EqualTo(1));
            Assert.That(tension, Is.GreaterThan(0f));
        }
    }
}
