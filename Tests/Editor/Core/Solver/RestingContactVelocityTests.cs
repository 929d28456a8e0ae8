using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Issue 14 item 4 (the settle cases of "push after the solve"): a particle resting on a collider under BDF2. The push-out
    /// enters BDF2's velocity as a backward-Euler kick c/h, and with BDF2's history v = (4v_n − v_{n−1})/3 + … the velocity of a
    /// particle held still on a surface converged to h·g_n/2 into it (g_n: its acceleration onto the surface) while its position
    /// stood still: a velocity with no motion, which never decays. The velocity pass now takes the part into the surface from a
    /// particle the passes pushed out in two substeps running, with its history (Rope.RemoveVelocityIntoSurface).
    /// </summary>
    public sealed class RestingContactVelocityTests
    {
        /// <summary>h·g/2 at 8 substeps of 1/90 s (m/s): the velocity a rope resting on a plane read under BDF2 before.</summary>
        const double PhantomSpeed = 0.5 * 9.81 / 720.0;

        [TestCase(TimeIntegrator.BackwardEuler)]
        [TestCase(TimeIntegrator.Bdf2)]
        public void RopeLandingOnAPlaneComesToRestWithoutBouncing(TimeIntegrator integrator)
        {
            // a horizontal 1 m rope 5 cm above a frictionless plane (its radius 5 mm): lands after 0.1 s at 1 m/s
            var settings = RopeTestKit.Legacy(length: 1f, segments: 4);
            settings.Integrator = integrator;
            var rope = new Rope(settings, new Float3(0f, 0.055f, 0f), new Float3(1f, 0.055f, 0f));
            rope.AddCollider(ColliderShape.Plane(Float3.Zero, new Float3(0f, 1f, 0f), 0f));
            double upward = 0.0, fastest = 0.0;
            bool landed = false;
            for (int k = 0; k < 90; k++)
            {
                rope.Step(1f / 90f);
                for (int i = 0; i < rope.ParticleCount; i++)
                {
                    landed |= rope.GetPosition(i).Y < 0.0051f;
                    if (landed) upward = Math.Max(upward, rope.GetVelocity(i).Y);
                    if (k == 89) fastest = Math.Max(fastest, rope.GetVelocity(i).Length);
                }
            }
            TestContext.WriteLine($"{integrator}: largest upward velocity after landing {upward:G3} m/s, fastest particle after 1 s {fastest:G3} m/s (h·g/2 = {PhantomSpeed:G4} m/s)");
            Assert.That(landed, Is.True);
            Assert.That(RopeTestKit.AllFinite(rope), Is.True);
            // measured: backward Euler 1.9e-6 m/s up, 1.6e-6 m/s at the end; BDF2 0 and 0 (before: 0 up, 6.81e-3 m/s = h·g/2 at the end)
            Assert.That(upward, Is.LessThan(1e-5));
            Assert.That(fastest, Is.LessThan(1e-5));
        }

        [TestCase(1e6f)]
        [TestCase(1e9f)]
        [TestCase(2e11f)]
        public void TwoSegmentRopeOnASphereComesToRest(float youngsModulus)
        {
            // the stability grid's settle case: 1 m, 2 segments, a load of one particle's mass, laid 30° off the vertical,
            // swinging onto a frictionless sphere (R 0.1 m, 0.6 m below the pin) that its middle particle comes to rest on;
            // β 0.05 s and the grid's drag (every velocity × exp(−k·Δt) after each step, k = √(g/ℓ)) for 25/k s
            var settings = RopeTestKit.Legacy(length: 1f, segments: 2, youngsModulus: youngsModulus, damping: 0.05f);
            settings.Integrator = TimeIntegrator.Bdf2;
            Rope rope = RopeTestKit.ReleasedAt30Degrees(settings);
            rope.AddLoad(2, settings.LinearDensity * 0.5f);
            RopeTestKit.AddGridSphere(rope, 0f);
            double area = Math.PI * 0.005 * 0.005, mass = 1140.0 * area, load = mass / 2.0;
            double hanging = 1.0 + (load + mass / 2.0) * 9.81 / (youngsModulus * area);
            double k = Math.Min(Math.Sqrt(9.81 / hanging), Math.Sqrt(youngsModulus * area / (load + mass / 3.0)));
            float decay = (float)Math.Exp(-k / 90.0);
            double start = rope.KineticEnergy() + rope.GravitationalEnergy();
            int steps = (int)Math.Ceiling(25.0 / k * 90.0);
            for (int s = 0; s < steps; s++)
            {
                rope.Step(1f / 90f);
                for (int i = 1; i < rope.ParticleCount; i++) rope.SetVelocity(i, rope.GetVelocity(i) * decay);
            }
            double kinetic = rope.KineticEnergy(), dissipated = start - rope.GravitationalEnergy() - kinetic;
            double middle = rope.GetVelocity(1).Length;
            double gap = (rope.GetPosition(1) - new Float3(0f, -0.6f, 0f)).Length - 0.105;
            TestContext.WriteLine($"E {youngsModulus:G3} Pa: kinetic after {steps} steps {kinetic:G3} J of {dissipated:G3} J dissipated, middle particle {middle:G3} m/s, {gap:G3} m off the sphere");
            Assert.That(RopeTestKit.AllFinite(rope), Is.True);
            // resting on the sphere
            Assert.That(Math.Abs(gap), Is.LessThan(1e-5));
            // measured: 3.2e-10 J (1 MPa), 5.5e-9 J (1 GPa), 8.7e-9 J (200 GPa) of 0.12 J dissipated, the middle particle
            // 8e-5 – 6.2e-4 m/s; before, the grid's cases read 8.1e-7 – 9.0e-7 J, the middle particle 6.3 mm/s into the sphere
            // (h·g_n/2), above 1e-6 of what they dissipated
            Assert.That(kinetic, Is.LessThan(1e-6 * dissipated / 5.0));
            Assert.That(middle, Is.LessThan(PhantomSpeed / 5.0));
        }
    }
}
