using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    public sealed class AttachmentTests
    {
        [Test]
        public void CompliantPinStretchesByForceTimesCompliance()
        {
            // a 5 kg load on a stiff rope hanging from a soft pin (compliance 1 mm/N)
            const float Compliance = 1e-3f, Load = 5f;
            var settings = RopeTestKit.Legacy(length: 1f, segments: 8);
            double weight = (Load + settings.LinearDensity * 1.0) * RopeTestKit.G;
            float sag = (float)(weight * Compliance);
            var rope = new Rope(settings, new Float3(0f, -sag, 0f), new Float3(0f, -1f - sag, 0f)); // start near equilibrium
            int pin = rope.AddPin(0, Float3.Zero, Compliance);
            rope.AddLoad(8, Load);
            double force = 0.0, position = 0.0;
            const int Steps = 90 * 4, Averaged = 90 * 2;
            for (int i = 0; i < Steps; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                if (i < Steps - Averaged) continue;
                force += rope.GetPinForce(pin).Y / Averaged;
                position += rope.GetPosition(0).Y / Averaged;
            }
            TestContext.WriteLine($"compliant pin: force {force:G6} N vs {-weight:G6} N, sag {-position:G6} m vs {weight * Compliance:G6} m");
            Assert.That(force, Is.EqualTo(-weight).Within(0.5).Percent, "the rope pulls the pin down with its whole weight");
            Assert.That(-position, Is.EqualTo(weight * Compliance).Within(1).Percent);
        }

        [Test]
        public void ReleasedLoadLeavesOnlyTheRopesShareAndItsTensionGoes()
        {
            // a 10 kg load on a 1 m rope: released, the end particle keeps its position and velocity and carries only μ·L/(2·8) again
            // damped (ζ ≈ 0.5 on the load's 88 rad/s mode) so that the load hangs still before it is released
            var settings = RopeTestKit.Legacy(length: 1f, segments: 8, damping: 0.01f);
            var rope = new Rope(settings, Float3.Zero, new Float3(0f, -1f, 0f));
            rope.AddPin(0, Float3.Zero);
            int load = rope.AddLoad(8, 10f);
            for (int i = 0; i < 90; i++) rope.Step(RopeTestKit.HostStep);
            float share = (float)(0.5 * settings.LinearDensity * 1.0 / 8);
            var position = rope.GetPosition(8);
            Assert.That(rope.GetParticleMass(8), Is.EqualTo(10f + share).Within(1e-5f));
            Assert.That(rope.Tensions[0], Is.GreaterThan(10f * RopeTestKit.G * 0.9f), "holds the load (N)");

            rope.ReleaseLoad(load);
            rope.ReleaseLoad(load); // a second release does nothing
            Assert.That(rope.IsLoadReleased(load), Is.True);
            Assert.That(rope.GetParticleMass(8), Is.EqualTo(share).Within(1e-6f), "kg");
            Assert.That(rope.GetPosition(8), Is.EqualTo(position), "released in place");
            // over 2 s the pin carries on average the rope's own weight μ·L·g (momentum balance), not the 98 N it held
            double meanPinForce = 0.0;
            const int Steps = 180;
            for (int i = 0; i < Steps; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                meanPinForce += rope.GetPinForce(0).Y / Steps;
            }
            Assert.That(rope.GetLoadForce(load), Is.EqualTo(Float3.Zero));
            Assert.That(rope.GetLoadHostForce(load), Is.EqualTo(Float3.Zero));
            TestContext.WriteLine($"released load: mean pin force {meanPinForce:G4} N, rope weight {settings.LinearDensity * RopeTestKit.G:G4} N");
            Assert.That(-meanPinForce, Is.EqualTo(settings.LinearDensity * 1.0 * RopeTestKit.G).Within(5).Percent, "N");
        }

        [Test]
        public void PinBreaksWhenItsForcePassesTheBreakForce()
        {
            var settings = RopeTestKit.Legacy(length: 1f, segments: 8);
            var rope = new Rope(settings, Float3.Zero, new Float3(0f, -1f, 0f));
            int pin = rope.AddPin(0, Float3.Zero, 0f, 200f);
            rope.AddLoad(8, 10f);
            for (int i = 0; i < 30; i++) rope.Step(RopeTestKit.HostStep);
            Assert.That(rope.IsPinBroken(pin), Is.False, "98 N < 200 N");
            rope.AddLoad(8, 20f); // 294 N > 200 N
            for (int i = 0; i < 30; i++) rope.Step(RopeTestKit.HostStep);
            Assert.That(rope.IsPinBroken(pin), Is.True);
            Assert.That(rope.GetPinForce(pin), Is.EqualTo(Float3.Zero));
            Assert.That(rope.GetPosition(0).Y, Is.LessThan(-0.1f), "the released end falls");
        }

        [Test]
        public void MovingPinIsFollowedAcrossSubstepsAndItsParticleReachesTheTarget()
        {
            var settings = RopeTestKit.Legacy(length: 1f, segments: 10);
            var rope = RopeTestKit.Hanging(settings, 0f, out _);
            int hand = rope.AddPinAtFraction(0.5f, new Float3(0f, -0.5f, 0f));
            Assert.That(rope.GetPinTarget(hand), Is.EqualTo(new Float3(0f, -0.5f, 0f)));
            rope.SetPinTarget(hand, new Float3(0.3f, -0.5f, 0f));
            rope.Step(RopeTestKit.HostStep);
            Assert.That(rope.GetPosition(5).X, Is.EqualTo(0.3f).Within(1e-6f));
            Assert.That(rope.GetVelocity(5).X, Is.EqualTo(0.3f / RopeTestKit.HostStep).Within(0.1).Percent,
                "it moved evenly across the substeps (0.3 m in one host step)");
        }

        [Test]
        public void LoadForceReadsTheRopePullInNewtons()
        {
            var settings = RopeTestKit.Settings(2f, 16, 1e5f, 0.1f);
            // damped (ζ ≈ 0.25 on the load's 25 rad/s mode) so that it comes to rest: the static pull does not depend on β
            settings.Damping = 0.02f;
            var rope = RopeTestKit.Hanging(settings, 80f, out int load);
            for (int i = 0; i < 90 * 30; i++) rope.Step(RopeTestKit.HostStep);
            Assert.That(rope.GetLoadForce(load).Y, Is.EqualTo(80.0 * RopeTestKit.G).Within(0.1).Percent, "static: the rope holds the load's weight");
            Assert.That(rope.GetLoadImpulse(load).Y, Is.EqualTo(80.0 * RopeTestKit.G * RopeTestKit.HostStep).Within(0.1).Percent);
            Assert.That(rope.GetParticleMass(16), Is.EqualTo(80f + 0.1f / 32f).Within(1e-4).Percent);
        }

        [Test]
        public void HostRigidBodyExchangesImpulsesWithTheRope()
        {
            // A host body (100 kg) integrated by the host with gravity + the rope impulse, written back each
            // step, must hang where the rope alone would put it: elongation (M + m/2) g L / E·A.
            const float Mass = 100f;
            var settings = RopeTestKit.Settings(2f, 16, 1e5f, 0.1f);
            settings.Damping = 0.005f;
            var rope = RopeTestKit.Hanging(settings, Mass, out int load);
            Float3 position = rope.GetLoadPosition(load), velocity = Float3.Zero;
            var gravity = new Float3(0f, -9.81f, 0f);
            float dt = RopeTestKit.HostStep;
            for (int i = 0; i < 90 * 20; i++)
            {
                rope.SetLoadState(load, position, velocity);  // 1. host → rope
                rope.Step(dt);                                // 2. rope step
                velocity += gravity * dt + rope.GetLoadImpulse(load) / Mass; // 3. host applies gravity + impulse
                position += velocity * dt;
            }
            double expected = (Mass + 0.05) * RopeTestKit.G * 2.0 / 1e5;
            TestContext.WriteLine($"host body elongation {-position.Y - 2.0:G6} m vs {expected:G6} m");
            Assert.That(-position.Y - 2.0, Is.EqualTo(expected).Within(1).Percent);
            Assert.That(rope.GetLoadForce(load).Y, Is.EqualTo(Mass * RopeTestKit.G).Within(1).Percent);
        }
    }
}
