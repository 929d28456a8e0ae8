using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// The rig coupling's bookkeeping on a slack rope (the load falls freely): the displacement is where the load
    /// ended minus where the rig was; a rig that followed keeps the load's velocity; a rig held back by δ loses δ/Δt;
    /// a deviation within the rounding is ignored; SetVelocity replaces the next step's velocity.
    /// </summary>
    public sealed class KinematicRigLoadTests
    {
        const float Dt = 0.02f;

        static Rope SlackRope(out int load)
        {
            // 1 m rope pinned at the origin, its end 0.5 m below: slack, so the 80 kg load falls freely
            var rope = new Rope(RopeTestKit.Legacy(), Float3.Zero, new Float3(0f, -0.5f, 0f));
            rope.AddPin(0, Float3.Zero);
            load = rope.AddLoad(rope.ParticleCount - 1, 80f);
            return rope;
        }

        /// <summary>A rig at the rope's end, at rest, after one coupled step.</summary>
        static KinematicRigLoad AfterFirstStep(out Rope rope, out int load, out Float3 position)
        {
            rope = SlackRope(out load);
            var rig = new KinematicRigLoad();
            position = new Float3(0f, -0.5f, 0f);
            rig.BeforeStep(rope, load, position, Dt);
            rope.Step(Dt);
            rig.AfterStep(rope, load);
            return rig;
        }

        [Test]
        public void ARigThatFollowsKeepsTheVelocityAndOneHeldBackLosesIt()
        {
            var rig = AfterFirstStep(out var rope, out int load, out var position);
            // free fall from rest over one step: about g·Δt²/2 down (the substeps' semi-implicit Euler: a little more)
            Assert.That(rig.Displacement.Y, Is.EqualTo(-0.5 * 9.81 * Dt * Dt).Within(0.15 * 0.5 * 9.81 * Dt * Dt));
            Assert.That(rig.Velocity.Y, Is.EqualTo(-9.81f * Dt).Within(1e-4f));

            // followed: the next step starts from the load's velocity
            position += rig.Displacement;
            rig.BeforeStep(rope, load, position, Dt, rounding: 1e-6f);
            Assert.That(rope.GetLoadVelocity(load).Y, Is.EqualTo(-9.81f * Dt).Within(1e-4f));
            rope.Step(Dt);
            rig.AfterStep(rope, load);

            // held back by the whole displacement (a floor): the velocity of that motion is taken away
            float velocity = rig.Velocity.Y;
            rig.BeforeStep(rope, load, position, Dt, rounding: 1e-6f);
            Assert.That(rope.GetLoadVelocity(load).Y, Is.EqualTo(velocity - rig.Displacement.Y / Dt).Within(1e-4f));
        }

        [Test]
        public void RoundingIsIgnoredAndSetVelocityReplacesTheNextVelocity()
        {
            var rig = AfterFirstStep(out var rope, out int load, out var position);
            float velocity = rig.Velocity.Y;

            // 2 µm off where it was told to go, within 4 µm of rounding: not motion
            rig.BeforeStep(rope, load, position + rig.Displacement + new Float3(0f, 2e-6f, 0f), Dt, rounding: 4e-6f);
            Assert.That(rope.GetLoadVelocity(load).Y, Is.EqualTo(velocity));
            rope.Step(Dt);
            rig.AfterStep(rope, load);

            rig.SetVelocity(new Float3(1f, 2f, 3f));
            rig.BeforeStep(rope, load, new Float3(5f, 5f, 5f), Dt);   // a teleport: the set velocity, no deviation term
            Assert.That(rope.GetLoadVelocity(load), Is.EqualTo(new Float3(1f, 2f, 3f)));
            Assert.That(() => rig.SetVelocity(new Float3(float.NaN, 0f, 0f)), Throws.ArgumentException);
            Assert.That(() => rig.BeforeStep(rope, load, Float3.Zero, 0f), Throws.InstanceOf<ArgumentOutOfRangeException>());
        }
    }
}
