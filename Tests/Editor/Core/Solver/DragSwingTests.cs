using System;
using System.Collections.Generic;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Issue 15 item 4: viscous drag settles a swinging rope at the rate the drag law predicts. A uniform rope under a drag
    /// −c·v per metre has the same drag per unit mass γ = c/μ everywhere (each particle carries ℓ/m = 1/μ), so every mode of
    /// the linearised swing, μ·ẍ = (T x′)′ − c·ẋ, is a damped oscillator ẍ + γ·ẋ + ω²x = 0: amplitude ∝ exp(−c·t/(2μ)) whatever
    /// the mode mix. Released at θ₀ = 30° the swing falls below 1 cm at t = (2μ/c)·ln(L·sin θ₀ / 1 cm). The rope is the
    /// package default (2 m, R 8 mm, 1140 kg/m³: μ = 0.2292 kg/m, 24 segments, 8 substeps at 1/90 s, β 0.002 s) with c = 0.5 N·s/m².
    /// </summary>
    public sealed class DragSwingTests
    {
        private const float Viscous = 0.5f;
        private const float HostStep = 1f / 90f;
        private const double Release = Math.PI / 6.0;

        private static Rope Released(TimeIntegrator integrator, float viscous = Viscous)
        {
            var settings = new RopeSettings { ViscousDrag = viscous, Integrator = integrator };
            float length = settings.RestLength;
            var rope = new Rope(settings, Float3.Zero, new Float3(length * (float)Math.Sin(Release), -length * (float)Math.Cos(Release), 0f));
            rope.AddPin(0, Float3.Zero);
            return rope;
        }

        /// <summary>Horizontal position (m) of the rope's centre of mass.</summary>
        private static double CentreOfMassX(Rope rope)
        {
            double m = 0.0, mx = 0.0;
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                double mi = rope.GetParticleMass(i);
                m += mi;
                mx += mi * rope.GetPosition(i).X;
            }
            return mx / m;
        }

        /// <summary>Largest horizontal distance (m) of a particle from the vertical through the pin.</summary>
        private static double OffVertical(Rope rope)
        {
            double off = 0.0;
            for (int i = 0; i < rope.ParticleCount; i++) off = Math.Max(off, Math.Abs(rope.GetPosition(i).X));
            return off;
        }

        /// <summary>−slope of ln|peak| against time over the local maxima of |x| (host-step samples dt apart): the decay rate in 1/s.</summary>
        private static double DecayRate(IReadOnlyList<double> x, double dt, out int peaks)
        {
            double st = 0, sy = 0, stt = 0, sty = 0;
            peaks = 0;
            for (int k = 1; k + 1 < x.Count; k++)
            {
                double a = Math.Abs(x[k]);
                if (!(a > Math.Abs(x[k - 1]) && a >= Math.Abs(x[k + 1]))) continue;
                double t = (k + 1) * dt, y = Math.Log(a);
                st += t; sy += y; stt += t * t; sty += t * y;
                peaks++;
            }
            return -(peaks * sty - st * sy) / (peaks * stt - st * st);
        }

        [TestCase(TimeIntegrator.Bdf2)]
        [TestCase(TimeIntegrator.BackwardEuler)]
        public void SwingDecaysAtHalfTheDragPerUnitMass(TimeIntegrator integrator)
        {
            var rope = Released(integrator);
            double expected = Viscous / (2.0 * rope.Settings.LinearDensity);
            var x = new List<double>();
            for (int k = 0; k < 90 * 8; k++)
            {
                rope.Step(HostStep);
                x.Add(CentreOfMassX(rope));
            }
            double measured = DecayRate(x, HostStep, out int peaks);
            TestContext.WriteLine($"{integrator}: decay rate {measured:F5} 1/s over {peaks} peaks vs c/(2μ) = {expected:F5} 1/s ({(measured / expected - 1) * 100:+0.00;-0.00} %)");
            Assert.That(peaks, Is.GreaterThanOrEqualTo(6));
            Assert.That(measured, Is.EqualTo(expected).Within(2).Percent);
        }

        [Test]
        public void SwingSettlesWithinACentimetreWhenTheDecayFormulaSays()
        {
            var rope = Released(TimeIntegrator.Bdf2);
            double mu = rope.Settings.LinearDensity;
            double predicted = 2.0 * mu / Viscous * Math.Log(rope.Settings.RestLength * Math.Sin(Release) / 0.01);
            double lastAbove = 0.0;
            for (int k = 0; k < 90 * 10; k++)
            {
                rope.Step(HostStep);
                if (OffVertical(rope) >= 0.01) lastAbove = (k + 1) * HostStep;
            }
            TestContext.WriteLine($"within 1 cm of vertical from {lastAbove:F3} s on vs (2μ/c)·ln(L sin30°/1 cm) = {predicted:F3} s ({(lastAbove / predicted - 1) * 100:+0.0;-0.0} %); after 10 s {OffVertical(rope) * 1000:G3} mm");
            Assert.That(lastAbove, Is.EqualTo(predicted).Within(5).Percent);
            Assert.That(OffVertical(rope), Is.LessThan(1e-3), "and it keeps settling");
        }

        /// <summary>
        /// Energy both ways: the total never rises by more than round-off in a host step, and what it loses is the work of the
        /// drag forces (<see cref="Rope.DragWork"/>, Σ f·d per substep) plus the integrator's own loss, read over the first 1.5 s
        /// while the rope still swings (the drag takes 0.5 J of the 0.6 J above rest). Backward Euler loses more by itself
        /// (its numerical damping), BDF2 about as much as the same swing without drag.
        /// </summary>
        [TestCase(TimeIntegrator.Bdf2, 5e-4)]
        [TestCase(TimeIntegrator.BackwardEuler, 1e-2)]
        public void EnergyNeverRisesAndTheLossIsTheDragWork(TimeIntegrator integrator, double relativeTolerance)
        {
            var rope = Released(integrator);
            var still = Released(integrator, viscous: 0f);
            double e0 = rope.TotalEnergy(), previous = e0, largestRise = double.NegativeInfinity;
            double scale = rope.Settings.LinearDensity * rope.Settings.RestLength * 9.81 * rope.Settings.RestLength;
            for (int k = 0; k < 135; k++)
            {
                rope.Step(HostStep);
                still.Step(HostStep);
                double e = rope.TotalEnergy();
                largestRise = Math.Max(largestRise, e - previous);
                previous = e;
            }
            double lost = e0 - rope.TotalEnergy(), drag = -rope.DragWork, ownLoss = e0 - still.TotalEnergy();
            TestContext.WriteLine($"{integrator}: lost {lost:G6} J, drag work {drag:G6} J (difference {(lost - drag):G3} J, {(lost - drag) / drag * 100:G3} %), " +
                $"the undamped run loses {ownLoss:G3} J; largest rise in a step {largestRise:G3} J of μgL² = {scale:G3} J");
            Assert.That(largestRise, Is.LessThan(1e-8 * scale), "energy never rises");
            Assert.That(drag, Is.GreaterThan(0.0));
            Assert.That(lost, Is.EqualTo(drag).Within(relativeTolerance * drag), "the loss is the drag work");
            Assert.That(lost - drag, Is.GreaterThanOrEqualTo(-1e-6 * drag), "no more work than energy lost");
            Assert.That(lost - drag, Is.LessThan(1.5 * ownLoss), "the rest is at most what the integrator loses on the same swing without drag");
        }
    }
}
