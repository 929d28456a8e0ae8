using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Two-way coupling with a host rigid body integrated by semi-implicit Euler (PhysX's order: v += (F/M + g)·Δt, then
    /// x += v·Δt). A 100 kg body falls 4 m on a 2 m, 0.46 kg lanyard (E·A 30 kN, 24 segments, undamped), the way a
    /// worker Rigidbody hangs on the component. Driven by <see cref="Rope.GetLoadHostForce"/> and
    /// <see cref="Rope.GetLoadHostVelocityCorrection"/>, the body follows the load particle exactly and the arrest peak
    /// meets the energy balance F = M·g + sqrt((M·g)² + 2·M·g·k·h); driven by the mean force alone, the body falls short
    /// of the particle every step, resetting the particle to the body discards stretch energy, and the arrest reads low
    /// (measured: −9.0 % at 50 Hz, −5.9 % at 90 Hz, against −1.1 % and −1.6 % with the host force).
    /// </summary>
    public sealed class HostCouplingTests
    {
        const float Mass = 100f, Length = 2f, FreeFall = 4f, AxialStiffness = 30000f;

        /// <summary>A host body: position and velocity of the attachment point, integrated the way PhysX does.</summary>
        struct HostBody
        {
            public Float3 Position, Velocity;

            public void Step(Float3 force, Float3 gravity, float dt)
            {
                Velocity = Velocity + (force * (1f / Mass) + gravity) * dt;
                Position = Position + Velocity * dt;
            }
        }

        static Rope Lanyard(out int load, out HostBody body, TimeIntegrator integrator = TimeIntegrator.BackwardEuler)
        {
            var settings = RopeTestKit.Legacy(length: Length, segments: 24, radius: 0.008f, density: 1140f, damping: 0f);
            settings.Integrator = integrator;
            settings.AxialStiffness = AxialStiffness;
            // the body starts FreeFall − L above the anchor with the lanyard laid straight up to it
            var top = new Float3(0.01f, FreeFall - Length, 0f);
            var rope = new Rope(settings, Float3.Zero, top);
            rope.AddPin(0, Float3.Zero);
            load = rope.AddLoad(rope.ParticleCount - 1, Mass);
            body = new HostBody { Position = top, Velocity = Float3.Zero };
            return rope;
        }

        static double Expected()
        {
            double mg = Mass * RopeTestKit.G, k = AxialStiffness / Length;
            return mg + Math.Sqrt(mg * mg + 2.0 * mg * k * FreeFall);
        }

        // Backward Euler's numerical damping reads the 50 Hz arrest 3.0 % low (h = 2.5 ms); the solver before the vector
        // chain solve read −1.1 % only because the folding lanyard gained 292 J in its fold, which made up for the damping.
        [TestCase(0.02f, TimeIntegrator.BackwardEuler, 3.5)]
        [TestCase(1f / 90f, TimeIntegrator.BackwardEuler, 2.0)]
        [TestCase(1f / 90f, TimeIntegrator.Bdf2, 2.0)]
        [TestCase(0.02f, TimeIntegrator.Bdf2, 2.0)]
        public void BodyFollowsTheLoadParticleAndTheArrestMeetsTheEnergyBalance(float dt, TimeIntegrator integrator, double tolerancePercent)
        {
            var rope = Lanyard(out int load, out var body, integrator);
            var gravity = rope.Settings.Gravity;
            var correction = Float3.Zero;
            double peak = 0.0, worstGap = 0.0, worstImpulse = 0.0;
            for (int i = 0; i < (int)(3f / dt); i++)
            {
                body.Velocity = body.Velocity + correction;
                rope.SetLoadState(load, body.Position, body.Velocity);
                rope.Step(dt);
                var force = rope.GetLoadHostForce(load);
                correction = rope.GetLoadHostVelocityCorrection(load);
                body.Step(force, gravity, dt);

                peak = Math.Max(peak, rope.GetLoadForce(load).Length);
                worstGap = Math.Max(worstGap, (body.Position - rope.GetLoadPosition(load)).Length);
                // host force over the step plus the next step's velocity change carry exactly the rope's impulse
                var delivered = force * dt + correction * Mass;
                worstImpulse = Math.Max(worstImpulse, (delivered - rope.GetLoadImpulse(load)).Length);
            }
            double expected = Expected();
            TestContext.WriteLine($"{integrator}, dt {dt}: peak {peak:F0} N vs {expected:F0} N ({(peak / expected - 1) * 100:F2} %), gap {worstGap:G3} m, impulse error {worstImpulse:G3} N·s");
            Assert.That(peak, Is.EqualTo(expected).Within(tolerancePercent).Percent);
            Assert.That(worstGap, Is.LessThan(1e-4), "the body ends each step where the load particle ended");
            Assert.That(worstImpulse, Is.LessThan(1e-3 * Mass), "no impulse lost or made");
        }

        [TestCase(0.02f)]
        [TestCase(1f / 90f)]
        public void MeanForceCouplingLosesTheArrestEnergy(float dt)
        {
            // the coupling the component used before: the mean force, no correction
            var rope = Lanyard(out int load, out var body);
            double peak = 0.0;
            for (int i = 0; i < (int)(3f / dt); i++)
            {
                rope.SetLoadState(load, body.Position, body.Velocity);
                rope.Step(dt);
                body.Step(rope.GetLoadForce(load), rope.Settings.Gravity, dt);
                peak = Math.Max(peak, rope.GetLoadForce(load).Length);
            }
            double expected = Expected();
            TestContext.WriteLine($"mean-force coupling, dt {dt}: peak {peak:F0} N vs {expected:F0} N ({(peak / expected - 1) * 100:F1} %)");
            Assert.That(peak, Is.LessThan(0.96 * expected), "why the host force exists");
        }

        [Test]
        public void LightLanyardCarriesTheArrestWithoutTensionSaturation()
        {
            // the same arrest without a host: the 19 g particles of a straight, taut lanyard need a transverse inertia
            // ratio above 16 (about 33 at the peak); capped at 16 the tension saturated near 6.5 kN
            const float dt = 1f / 90f;
            var rope = Lanyard(out int load, out var body);
            rope.SetLoadState(load, body.Position, body.Velocity);
            double peak = 0.0;
            for (int i = 0; i < (int)(2f / dt); i++)
            {
                rope.Step(dt);
                peak = Math.Max(peak, rope.GetLoadForce(load).Length);
            }
            Assert.That(peak, Is.EqualTo(Expected()).Within(2).Percent);
        }
    }
}
