using System;
using NUnit.Framework;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): parameter changes on a built rope apply at the next step without a new core rope;
    /// only a new segment count rebuilds it; bad values throw naming the parameter.
    /// </summary>
    [TestFixture]
    public sealed class ElasticRopeLiveSettingsTests
    {
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        ElasticRope HangingRope()
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 5f, 0f));
            var rope = _scene.Rope("Rope", anchor.position);
            rope.StartAttachment.Point = anchor;
            rope.SegmentCount = 12;
            rope.Rebuild();
            return rope;
        }

        [Test]
        public void MaterialChangeKeepsTheCoreRopeAndReachesItsSettings()
        {
            var rope = HangingRope();
            var core = rope.Simulation.Rope;
            rope.YoungsModulus = 2.5e8f;
            rope.Damping = 0.01f;
            rope.PoissonRatio = 0.45f;
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope, Is.SameAs(core));
            Assert.That(core.Settings.YoungsModulus, Is.EqualTo(2.5e8f).Within(1f));
            Assert.That(core.Settings.Damping, Is.EqualTo(0.01f).Within(1e-7f));
            Assert.That(rope.AxialStiffness, Is.EqualTo(2.5e8f * Mathf_Pi * rope.Radius * rope.Radius).Within(0.5f));
        }

        [Test]
        public void NewSegmentCountRebuildsAtTheNextStep()
        {
            var rope = HangingRope();
            var core = rope.Simulation.Rope;
            rope.SegmentCount = 30;
            rope.Simulate(0.02f);
            Assert.That(rope.Simulation.Rope, Is.Not.SameAs(core));
            Assert.That(rope.ParticleCount, Is.EqualTo(31));
        }

        [TestCase("RestLength")]
        [TestCase("Radius")]
        [TestCase("Density")]
        [TestCase("PoissonRatio")]
        [TestCase("Substeps")]
        public void OutOfRangeValueThrowsNamingTheParameter(string parameter)
        {
            var rope = HangingRope();
            TestDelegate set;
            switch (parameter)
            {
                case "RestLength": set = () => rope.RestLength = -1f; break;
                case "Radius": set = () => rope.Radius = 0f; break;
                case "Density": set = () => rope.Density = float.NaN; break;
                case "PoissonRatio": set = () => rope.PoissonRatio = 0.7f; break;
                default: set = () => rope.Substeps = 0; break;
            }
            var e = Assert.Throws<ArgumentOutOfRangeException>(set);
            Assert.That(e.ParamName, Is.EqualTo(parameter));
            Assert.That(e.Message, Does.Contain(parameter));
        }

        const float Mathf_Pi = (float)Math.PI;
    }
}
