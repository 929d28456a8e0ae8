using NUnit.Framework;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode, through the component: a 100 kg worker rig without a Rigidbody (a CharacterController, the rope's end
    /// a <see cref="RopeEndKind.KinematicRig"/> of 100 kg moved by EndRigDisplacement in OnStepped) falls 4 m on the
    /// default lanyard (2 m, E·A = 30.2 kN), undamped. Its peak arrest force must match the same fall of a 100 kg
    /// Rigidbody worker within 2 % and the light-lanyard energy balance F = M·g·(1 + sqrt(1 + 2·k·h/(M·g))),
    /// k = E·A/L, within 2 % (measured: the two workers agree within 0.001 %; −1.1 % at 50 Hz, −1.6 % at 90 Hz from the balance). A steel-stiff lanyard (E·A 10 MN: ω·Δt = 4.5 at 50 Hz, where an explicit force fed to the
    /// controller diverges) stays finite, arrests and gains no energy.
    /// </summary>
    [TestFixture]
    public sealed class KinematicRigFallArrestTests
    {
        const float G = 9.81f, Mass = 100f, FreeFall = 4f;
        UnityRopeScene _scene;
        CharacterController _controller;
        ElasticRope _rope;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        /// <summary>The rig script's whole job: move the controller where the rope carried its mass.</summary>
        void MoveRig(Vector3 startForce, Vector3 endForce) => _controller.Move(_rope.EndRigDisplacement);

        /// <summary>An anchor at 20 m and a lanyard whose end (the rig's D-ring) starts FreeFall − L above it, 1 cm aside.</summary>
        ElasticRope Lanyard(out Transform anchor, out Vector3 dRing)
        {
            anchor = _scene.Point("Anchor", new Vector3(0f, 20f, 0f));
            var rope = _scene.Rope("Lanyard", anchor.position);
            dRing = new Vector3(0.01f, 20f + FreeFall - rope.RestLength, 0f);
            rope.Damping = 0f;
            rope.StartAttachment.Point = anchor;
            return rope;
        }

        ElasticRope CharacterControllerWorker(out Transform anchor, out Transform worker)
        {
            _rope = Lanyard(out anchor, out var dRing);
            var go = _scene.Track(new GameObject("Worker", typeof(CharacterController)));
            go.transform.position = dRing;   // the controller's pivot is the D-ring
            _controller = go.GetComponent<CharacterController>();
            _controller.minMoveDistance = 0f;
            worker = go.transform;
            _rope.EndAttachment.Point = worker;
            _rope.EndAttachment.RigMass = Mass;
            _rope.Rebuild();
            _rope.OnStepped.AddListener(MoveRig);
            return _rope;
        }

        ElasticRope RigidbodyWorker(out Rigidbody worker)
        {
            var rope = Lanyard(out _, out var dRing);
            worker = _scene.Body("Worker", dRing, Mass);
            rope.EndAttachment.Body = worker;
            rope.Rebuild();
            return rope;
        }

        static float EnergyBalance(float axialStiffness, float length)
        {
            float weight = Mass * G, k = axialStiffness / length;
            return weight * (1f + (float)System.Math.Sqrt(1f + 2f * k * FreeFall / weight));
        }

        [TestCase(0.02f)]
        [TestCase(1f / 90f)]
        public void PeakArrestForceMatchesTheRigidbodyWorkerAndTheEnergyBalance(float dt)
        {
            var rigid = RigidbodyWorker(out _);
            UnityRopeScene.Run(rigid, (int)(2f / dt), dt);
            float rigidPeak = rigid.PeakArrestForce;

            var rope = CharacterControllerWorker(out var anchor, out var worker);
            float lowest = float.PositiveInfinity;
            for (int i = 0; i < (int)(2f / dt); i++)
            {
                rope.Simulate(dt);
                lowest = System.Math.Min(lowest, worker.position.y);
            }

            float expected = EnergyBalance(rope.AxialStiffness, rope.RestLength), k = rope.AxialStiffness / rope.RestLength;
            TestContext.WriteLine("dt " + dt + " s: CharacterController peak " + rope.PeakArrestForce + " N, Rigidbody peak " + rigidPeak +
                                  " N, energy balance " + expected + " N, lowest " + lowest + " m");
            Assert.That(rope.PeakArrestForce, Is.EqualTo(rigidPeak).Within(2).Percent);
            Assert.That(rope.PeakArrestForce, Is.EqualTo(expected).Within(2).Percent);
            // the controller went where the rope carried it: the lowest point is the taut length plus F/k below the anchor
            Assert.That(lowest, Is.EqualTo(anchor.position.y - rope.RestLength - expected / k).Within(0.02f * expected / k + 0.02f));
            // the rope's end particle and the controller agree after the last step
            Assert.That((rope.GetParticlePosition(rope.ParticleCount - 1) - worker.position).magnitude, Is.LessThan(1e-4f));
        }

        [TestCase(0.02f)]
        [TestCase(1f / 90f)]
        public void AStiffSteelLanyardStaysFiniteArrestsAndGainsNoEnergy(float dt)
        {
            var rigid = RigidbodyWorker(out var body);
            MakeSteelStiff(rigid);
            float rigidLowest = float.PositiveInfinity;
            for (int i = 0; i < (int)(4f / dt); i++)
            {
                rigid.Simulate(dt);
                Physics.Simulate(dt);
                rigidLowest = System.Math.Min(rigidLowest, body.position.y);
            }

            var rope = CharacterControllerWorker(out var anchor, out var worker);
            MakeSteelStiff(rope);
            float k = rope.AxialStiffness / rope.RestLength, start = worker.position.y;
            float omegaDt = (float)System.Math.Sqrt(k / Mass) * dt;
            float highestAfterArrest = float.NegativeInfinity, lowest = float.PositiveInfinity;
            bool finite = true;
            for (int i = 0; i < (int)(4f / dt); i++)
            {
                rope.Simulate(dt);
                var p = worker.position;
                finite &= float.IsFinite(p.x) && float.IsFinite(p.y) && float.IsFinite(p.z) && float.IsFinite(rope.EndForce.y);
                lowest = System.Math.Min(lowest, p.y);
                if (i * dt > 1.5f) highestAfterArrest = System.Math.Max(highestAfterArrest, p.y);
            }

            float expected = EnergyBalance(rope.AxialStiffness, rope.RestLength);
            float taut = anchor.position.y - rope.RestLength;
            TestContext.WriteLine("dt " + dt + " s, ω·Δt " + omegaDt + ": peak " + rope.PeakArrestForce + " N (Rigidbody worker " + rigid.PeakArrestForce +
                                  " N, energy balance " + expected + " N), lowest " + lowest + " m (Rigidbody worker " + rigidLowest + " m, taut " + taut +
                                  " m), highest after the first arrest " + highestAfterArrest + " m (start " + start + " m), final " + worker.position.y + " m");
            Assert.That(omegaDt, Is.GreaterThan(2f), "beyond the stability limit of an explicit force (dt " + dt + ")");
            Assert.That(finite, Is.True);
            // arrested at the lanyard's length, as the Rigidbody worker: the stretch at the peak is centimetres at most
            // (the undamped energy balance allows F/k = 4 cm)
            Assert.That(lowest, Is.EqualTo(rigidLowest).Within(0.005f));
            Assert.That(lowest, Is.GreaterThan(taut - 1.02f * expected / k - 0.005f));
            Assert.That(rope.PeakArrestForce, Is.EqualTo(rigid.PeakArrestForce).Within(2).Percent);
            // no energy gained: the peak force stays under the undamped balance, the rig never climbs back to its start
            // and never drops below the taut length again
            Assert.That(rope.PeakArrestForce, Is.GreaterThan(0.2f * expected).And.LessThanOrEqualTo(1.02f * expected));
            Assert.That(highestAfterArrest, Is.LessThan(start));
            Assert.That(worker.position.y, Is.GreaterThan(taut - 0.01f).And.LessThan(start));
        }

        /// <summary>Steel-like E·A 10 MN, elastic (no radius model: a neck would soften it at 1 GPa), 10 iterations (one is not enough at this stiffness).</summary>
        static void MakeSteelStiff(ElasticRope rope)
        {
            rope.AxialStiffness = 10e6f;
            rope.Fracture = false;
            rope.Necking = false;
            rope.PoissonThinning = false;
            rope.Damping = 0.002f;
            rope.Iterations = 10;
            rope.Rebuild();
        }
    }
}
