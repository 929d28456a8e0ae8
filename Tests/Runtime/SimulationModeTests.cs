using System.Collections;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.Tests
{
    /// <summary>
    /// Play mode (in Unity and headless through the Unity stand-in's player loop): the rope respects
    /// Physics.simulationMode. In Script mode FixedUpdate does not step it (the user calls Simulate, as for
    /// Physics.Simulate); back in FixedUpdate mode it steps again. Update mode (steps in Update with Time.deltaTime)
    /// needs the real engine: the stand-in refuses that mode.
    /// </summary>
    public sealed class SimulationModeTests
    {
        GameObject _anchor, _rope;
        SimulationMode _mode;

        [SetUp] public void SetUp() => _mode = Physics.simulationMode;

        [TearDown]
        public void TearDown()
        {
            Physics.simulationMode = _mode;
            if (_rope != null) Object.Destroy(_rope);
            if (_anchor != null) Object.Destroy(_anchor);
        }

        [UnityTest]
        public IEnumerator InScriptModeFixedUpdateDoesNotStepTheRope()
        {
            _anchor = new GameObject("Anchor");
            _anchor.transform.position = new Vector3(0f, 5f, 0f);
            _rope = new GameObject("Rope", typeof(ElasticRope));
            _rope.transform.position = _anchor.transform.position;
            var rope = _rope.GetComponent<ElasticRope>();
            rope.StartAttachment.Point = _anchor.transform;
            rope.Rebuild();
            int last = rope.ParticleCount - 1;
            Vector3 built = rope.GetParticlePosition(last);

            Physics.simulationMode = SimulationMode.Script;
            for (int i = 0; i < 10; i++) yield return new WaitForFixedUpdate();
            Assert.That(rope.GetParticlePosition(last), Is.EqualTo(built), "FixedUpdate in Script mode leaves the rope alone");

            rope.Simulate(Time.fixedDeltaTime);
            Vector3 stepped = rope.GetParticlePosition(last);
            Assert.That(stepped, Is.Not.EqualTo(built), "Simulate steps it");

            Physics.simulationMode = SimulationMode.FixedUpdate;
            for (int i = 0; i < 3; i++) yield return new WaitForFixedUpdate();
            Assert.That(rope.GetParticlePosition(last), Is.Not.EqualTo(stepped), "FixedUpdate mode steps it again");
        }
    }
}
