using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools.Constraints;
using Is = UnityEngine.TestTools.Constraints.Is;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode, through the component: StartForce and EndForce are the core's pin force and the force applied to the
    /// Rigidbody (Rope.GetPinForce, Rope.GetLoadHostForce); in a static hang they balance the weights (the anchor holds
    /// rope plus load, the load end holds the load, two anchors share the rope's weight) within 0.5 %; OnStepped is
    /// raised once per step with the same values and a step with a listener moving a CharacterController allocates nothing.
    /// </summary>
    [TestFixture]
    public sealed class AttachmentForceReadoutTests
    {
        const float G = 9.81f, Mass = 100f, Dt = 1f / 90f;
        UnityRopeScene _scene;
        ElasticRope _rope;
        CharacterController _controller;
        int _raised;
        Vector3 _raisedStart, _raisedEnd;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); _raised = 0; }
        [TearDown] public void TearDown() => _scene.End();

        void Record(Vector3 startForce, Vector3 endForce)
        {
            _raised++;
            _raisedStart = startForce;
            _raisedEnd = endForce;
        }

        void MoveRig(Vector3 startForce, Vector3 endForce) => _controller.Move(_rope.EndRigDisplacement);

        /// <summary>A 2 m rope hung from an anchor at 10 m; damped (β = 20 ms) so it comes to rest within a few seconds.</summary>
        ElasticRope HangingRope(out float stretchedEnd)
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 10f, 0f));
            _rope = _scene.Rope("Rope", anchor.position);
            _rope.Damping = 0.02f;
            _rope.StartAttachment.Point = anchor;
            // start at the static stretch under the load so little is left to damp
            stretchedEnd = 10f - _rope.RestLength * (1f + Mass * G / _rope.AxialStiffness);
            return _rope;
        }

        /// <summary>A 100 kg CharacterController rig at height <paramref name="y"/> (m) on the rope's end, moved in OnStepped.</summary>
        GameObject AttachRig(ElasticRope rope, float y)
        {
            var go = _scene.Track(new GameObject("Rig", typeof(CharacterController)));
            go.transform.position = new Vector3(0f, y, 0f);
            _controller = go.GetComponent<CharacterController>();
            _controller.minMoveDistance = 0f;
            rope.EndAttachment.Point = go.transform;
            rope.EndAttachment.RigMass = Mass;
            rope.Rebuild();
            rope.OnStepped.AddListener(MoveRig);
            return go;
        }

        static Vector3 V(HookeRope.Mathematics.Float3 f) => new Vector3(f.X, f.Y, f.Z);

        float RopeWeight(ElasticRope rope) => rope.LinearDensity * rope.RestLength * G;

        [Test]
        public void AStaticHangWithARigidbodyBalancesAndTheReadoutsAreTheCoreForces()
        {
            var rope = HangingRope(out float y);
            var body = _scene.Body("Load", new Vector3(0f, y, 0f), Mass);
            rope.EndAttachment.Body = body;
            rope.Rebuild();
            UnityRopeScene.Run(rope, (int)(6f / Dt), Dt);

            var core = rope.Simulation.Rope;
            Assert.That(rope.StartForce, Is.EqualTo(V(core.GetPinForce(0))));
            Assert.That(rope.EndForce, Is.EqualTo(V(core.GetLoadHostForce(0))));
            float ropeWeight = RopeWeight(rope);
            TestContext.WriteLine("start " + rope.StartForce.y + " N, end " + rope.EndForce.y + " N, rope weight " + ropeWeight + " N");
            Assert.That(-rope.StartForce.y, Is.EqualTo(ropeWeight + Mass * G).Within(0.5).Percent);
            Assert.That(rope.EndForce.y, Is.EqualTo(Mass * G).Within(0.5).Percent);
            Assert.That(rope.StartForce.y + rope.EndForce.y, Is.EqualTo(-ropeWeight).Within(0.005f * (ropeWeight + Mass * G)));
        }

        [Test]
        public void AStaticHangWithARigWithoutARigidbodyBalances()
        {
            var rope = HangingRope(out float y);
            var go = AttachRig(rope, y);
            UnityRopeScene.Run(rope, (int)(6f / Dt), Dt);

            var core = rope.Simulation.Rope;
            Assert.That(rope.EndAttachment.Kind, Is.EqualTo(RopeEndKind.KinematicRig));
            Assert.That(rope.EndForce, Is.EqualTo(V(core.GetLoadForce(0))));
            float ropeWeight = RopeWeight(rope);
            TestContext.WriteLine("start " + rope.StartForce.y + " N, end " + rope.EndForce.y + " N, rope weight " + ropeWeight + " N, rig at " + go.transform.position.y + " m");
            Assert.That(-rope.StartForce.y, Is.EqualTo(ropeWeight + Mass * G).Within(0.5).Percent);
            Assert.That(rope.EndForce.y, Is.EqualTo(Mass * G).Within(0.5).Percent);
            Assert.That(go.transform.position.y, Is.EqualTo(y).Within(1e-3f), "hangs at the static stretch");
        }

        [Test]
        public void TwoAnchorsShareTheRopeWeight()
        {
            // a vertical rope stretched 5 % between two anchors: every motion is axial, so the damping stills it
            var a = _scene.Point("A", new Vector3(0f, 10f, 0f));
            var rope = _scene.Rope("Rope", a.position);
            var b = _scene.Point("B", new Vector3(0f, 10f - 1.05f * rope.RestLength, 0f));
            rope.Damping = 0.02f;
            rope.StartAttachment.Point = a;
            rope.EndAttachment.Point = b;
            rope.Rebuild();
            UnityRopeScene.Run(rope, (int)(3f / Dt), Dt);

            var core = rope.Simulation.Rope;
            Assert.That(rope.StartForce, Is.EqualTo(V(core.GetPinForce(0))));
            Assert.That(rope.EndForce, Is.EqualTo(V(core.GetPinForce(1))));
            float ropeWeight = RopeWeight(rope), pull = 0.05f * rope.AxialStiffness;
            Vector3 sum = rope.StartForce + rope.EndForce;
            TestContext.WriteLine("start " + rope.StartForce.y + " N, end " + rope.EndForce.y + " N, sum " + sum.y + " N, rope weight " + ropeWeight + " N");
            Assert.That(-rope.StartForce.y, Is.EqualTo(pull + 0.5f * ropeWeight).Within(0.5).Percent);
            Assert.That(-sum.y, Is.EqualTo(ropeWeight).Within(0.5).Percent);
            Assert.That(System.Math.Abs(sum.x) + System.Math.Abs(sum.z), Is.LessThan(0.005f * ropeWeight));
        }

        [Test]
        public void OnSteppedIsRaisedOncePerStepWithTheReadoutsAndAllocatesNothing()
        {
            var rope = HangingRope(out float y);
            AttachRig(rope, y + 1f);   // a 1 m fall first
            rope.OnStepped.AddListener(Record);

            for (int i = 1; i <= 120; i++)
            {
                rope.Simulate(Dt);
                Assert.That(_raised, Is.EqualTo(i));
                Assert.That(_raisedStart, Is.EqualTo(rope.StartForce));
                Assert.That(_raisedEnd, Is.EqualTo(rope.EndForce));
            }
            Assert.That(rope.PeakArrestForce, Is.GreaterThan(Mass * G), "the fall was arrested during the steps checked");
            Assert.That(() => { rope.Simulate(Dt); Physics.Simulate(Dt); }, Is.Not.AllocatingGCMemory());
            Assert.That(_raised, Is.EqualTo(121));
        }
    }
}
