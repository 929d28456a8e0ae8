using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools.Constraints;
using Is = UnityEngine.TestTools.Constraints.Is;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode, through the component and Unity physics: a 100 kg worker Rigidbody falls 4 m on the default
    /// ElasticRope lanyard (2 m, E 150 MPa, R 8 mm: E·A = 30.2 kN, 24 segments, 8 substeps), undamped so the energy
    /// balance of a light linear lanyard holds: F = M·g + sqrt((M·g)² + 2·M·g·k·h) with k = E·A/L. The peak arrest
    /// force the component reads must match it within 2 % (the default damping β = 2 ms, ζ = β·ω/2 ≈ 1.2 %, lowers
    /// the peak by a further 2 %); the worker is held (never farther from the anchor than the stretched lanyard);
    /// and a physics step (rope plus Rigidbody) allocates nothing once warm.
    /// </summary>
    [TestFixture]
    public sealed class WorkerFallArrestTests
    {
        const float G = 9.81f, Mass = 100f, FreeFall = 4f;
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        ElasticRope DefaultLanyard(out Transform anchor, out Rigidbody worker)
        {
            anchor = _scene.Point("Anchor", new Vector3(0f, 20f, 0f));
            var rope = _scene.Rope("Lanyard", anchor.position);
            // the D-ring starts FreeFall − L above the anchor, so the lanyard goes taut after a free fall of FreeFall
            worker = _scene.Body("Worker", new Vector3(0.01f, 20f + FreeFall - rope.RestLength, 0f), Mass);
            rope.Damping = 0f;
            rope.StartAttachment.Point = anchor;
            rope.EndAttachment.Body = worker;
            rope.Rebuild();
            return rope;
        }

        [TestCase(0.02f)]
        [TestCase(1f / 90f)]
        public void PeakArrestForceMatchesTheEnergyBalanceAndTheWorkerIsHeld(float dt)
        {
            var rope = DefaultLanyard(out var anchor, out var worker);
            float weight = Mass * G, k = rope.AxialStiffness / rope.RestLength;
            float expected = weight + Sqrt(weight * weight + 2f * weight * k * FreeFall);

            float lowest = float.PositiveInfinity, lowestAfterArrest = float.PositiveInfinity, farthest = 0f;
            int steps = (int)(6f / dt);
            for (int i = 0; i < steps; i++)
            {
                rope.Simulate(dt);
                Physics.Simulate(dt);
                float y = worker.position.y;
                if (i * dt < 1.5f) lowest = System.Math.Min(lowest, y);
                else lowestAfterArrest = System.Math.Min(lowestAfterArrest, y);
                farthest = System.Math.Max(farthest, (worker.position - anchor.position).magnitude);
            }

            TestContext.WriteLine("dt " + dt + " s: peak " + rope.PeakArrestForce + " N, expected " + expected + " N, lowest " + lowest + " m");
            Assert.That(rope.PeakArrestForce, Is.EqualTo(expected).Within(2).Percent);
            Assert.That(rope.IsBroken, Is.False);
            // the lowest point is where the lanyard stretches by F/k below its taut length
            float taut = anchor.position.y - rope.RestLength;
            Assert.That(lowest, Is.EqualTo(taut - expected / k).Within(0.02f * expected / k + 0.02f));
            // held: the undamped lanyard throws the worker back up, but later arrests never go lower than the first one
            // and the worker is never farther from the anchor than the lanyard stretched by the peak force
            Assert.That(lowestAfterArrest, Is.GreaterThanOrEqualTo(lowest - 1e-3f));
            Assert.That(farthest, Is.LessThan(rope.RestLength + 1.02f * expected / k));
        }

        [Test]
        public void APhysicsStepAllocatesNothingOnceWarm()
        {
            const float dt = 1f / 90f;
            var rope = DefaultLanyard(out _, out _);
            for (int i = 0; i < 120; i++) { rope.Simulate(dt); Physics.Simulate(dt); }
            Assert.That(() => { rope.Simulate(dt); Physics.Simulate(dt); }, Is.Not.AllocatingGCMemory());
        }

        static float Sqrt(float x) => (float)System.Math.Sqrt(x);
    }
}
