using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>Determinism and allocation-free stepping.</summary>
    public sealed class InvariantTests
    {
        private static Rope Scene(ConstraintSolverKind solver, TimeIntegrator integrator, out int hand)
        {
            var settings = RopeTestKit.Legacy(length: 3f, segments: 48, solver: solver, damping: 0.001f);
            settings.Integrator = integrator;
            var rope = new Rope(settings, new Float3(100f, 2f, -50f), new Float3(103f, 2f, -50f));
            hand = rope.AddPin(0, new Float3(100f, 2f, -50f));
            rope.AddPinAtFraction(1f, new Float3(103f, 2f, -50f), 1e-4f, 5000f);
            rope.AddLoad(24, 20f);
            rope.AddCollider(ColliderShape.Sphere(new Float3(101.5f, 1f, -50f), 0.4f, 0.3f));
            rope.AddCollider(ColliderShape.Box(new Float3(101.5f, -1f, -50f), Quat.FromAxisAngle(new Float3(0f, 1f, 0f), 0.3f), new Float3(1f, 0.5f, 1f), 0.5f));
            rope.AddCollider(ColliderShape.Capsule(new Float3(102.5f, 0.5f, -50f), Quat.Identity, 0.1f, 0.3f));
            rope.AddCollider(ColliderShape.Plane(new Float3(0f, -2f, 0f), new Float3(0f, 1f, 0f), 0.4f));
            return rope;
        }

        private static void Drive(Rope rope, int hand, int from, int to)
        {
            for (int i = from; i < to; i++)
            {
                rope.SetPinTarget(hand, new Float3(100f + 0.3f * MathF.Sin(i * 0.05f), 2f, -50f + 0.2f * MathF.Cos(i * 0.07f)));
                rope.Step(RopeTestKit.HostStep);
            }
        }

        [TestCase(ConstraintSolverKind.ExactChain, TimeIntegrator.BackwardEuler)]
        [TestCase(ConstraintSolverKind.GaussSeidel, TimeIntegrator.BackwardEuler)]
        [TestCase(ConstraintSolverKind.ExactChain, TimeIntegrator.Bdf2)]
        public void SameInputsGiveBitwiseIdenticalResults(ConstraintSolverKind solver, TimeIntegrator integrator)
        {
            var a = Scene(solver, integrator, out int handA);
            var b = Scene(solver, integrator, out int handB);
            Drive(a, handA, 0, 200);
            Drive(b, handB, 0, 200);
            for (int i = 0; i < a.ParticleCount; i++)
            {
                Assert.That(BitConverter.SingleToInt32Bits(a.PositionX[i]), Is.EqualTo(BitConverter.SingleToInt32Bits(b.PositionX[i])));
                Assert.That(BitConverter.SingleToInt32Bits(a.PositionY[i]), Is.EqualTo(BitConverter.SingleToInt32Bits(b.PositionY[i])));
                Assert.That(BitConverter.SingleToInt32Bits(a.PositionZ[i]), Is.EqualTo(BitConverter.SingleToInt32Bits(b.PositionZ[i])));
            }
            for (int j = 0; j < a.SegmentCount; j++)
                Assert.That(BitConverter.SingleToInt32Bits(a.Tensions[j]), Is.EqualTo(BitConverter.SingleToInt32Bits(b.Tensions[j])));
            Assert.That(RopeTestKit.AllFinite(a), Is.True);
            Assert.That(a.Tensions[10], Is.GreaterThan(0f), "the scene really loads the rope");
        }

        [TestCase(ConstraintSolverKind.ExactChain, TimeIntegrator.BackwardEuler)]
        [TestCase(ConstraintSolverKind.GaussSeidel, TimeIntegrator.BackwardEuler)]
        [TestCase(ConstraintSolverKind.ExactChain, TimeIntegrator.Bdf2)]
        public void StepAllocatesNothingAfterWarmUp(ConstraintSolverKind solver, TimeIntegrator integrator)
        {
            var rope = Scene(solver, integrator, out int hand);
            int events = 0;
            rope.Broken += e => events++;
            Drive(rope, hand, 0, 20);
            rope.BreakSegment(40); // warm up the event path too
            Drive(rope, hand, 20, 40);
            // Three windows of 100 steps (each with a break event): a real per-step allocation shows in
            // every window, while a one-off runtime allocation (tiered JIT) can only show in one.
            long fewest = long.MaxValue;
            for (int window = 0; window < 3; window++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                Drive(rope, hand, 40 + 100 * window, 90 + 100 * window);
                rope.BreakSegment(30 + window);
                Drive(rope, hand, 90 + 100 * window, 140 + 100 * window);
                fewest = Math.Min(fewest, GC.GetAllocatedBytesForCurrentThread() - before);
            }
            Assert.That(fewest, Is.EqualTo(0));
            Assert.That(events, Is.EqualTo(4));
        }

        [Test]
        public void RopeLocalFrameKeepsPrecisionFarFromTheWorldOrigin()
        {
            // the same hanging rope at the origin and 10 km away stretches by the same amount
            var near = RopeTestKit.Legacy(length: 2f, segments: 16);
            var far = near.Clone();
            var a = new Rope(near, Float3.Zero, new Float3(0f, -2f, 0f));
            var b = new Rope(far, new Float3(10000f, 0f, 10000f), new Float3(10000f, -2f, 10000f));
            a.AddPin(0, Float3.Zero); a.AddLoad(16, 50f);
            b.AddPin(0, new Float3(10000f, 0f, 10000f)); b.AddLoad(16, 50f);
            for (int i = 0; i < 450; i++) { a.Step(RopeTestKit.HostStep); b.Step(RopeTestKit.HostStep); }
            Assert.That(b.PositionY[16], Is.EqualTo(a.PositionY[16]));
            Assert.That(b.GetPosition(16).X, Is.EqualTo(10000f));
        }
    }
}
