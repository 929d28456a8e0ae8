using System;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    public sealed class SteelCableTests
    {
        [Test]
        public void SteelCableWithHalfATonneIsStableAndSettlesToItsStaticElongation()
        {
            // damped (ζ ≈ 0.14 on the load's 56 rad/s mode) so that the released load comes to rest within the 8 s
            var settings = RopeTestKit.Legacy(length: 10f, segments: 64, radius: 0.005f, youngsModulus: 200e9f, density: 7850f, damping: 0.005f);
            var rope = RopeTestKit.Hanging(settings, 500f, out _);
            double ropeMass = settings.LinearDensity * 10.0;
            double expected = (500.0 + ropeMass / 2.0) * RopeTestKit.G * 10.0 / settings.AxialStiffness;
            double largest = 0.0;
            for (int i = 0; i < 90 * 8; i++)
            {
                rope.Step(RopeTestKit.HostStep);
                largest = Math.Max(largest, -RopeTestKit.Bottom(rope) - 10.0);
            }
            Assert.That(RopeTestKit.AllFinite(rope), Is.True);
            double elongation = -RopeTestKit.Bottom(rope) - 10.0;
            TestContext.WriteLine($"elongation {elongation:G6} m vs {expected:G6} m ({(elongation / expected - 1) * 100:F3} %), largest {largest:G6} m");
            Assert.That(largest, Is.LessThan(2.2 * expected), "overshoot of a released load is at most 2x the static elongation");
            Assert.That(elongation, Is.EqualTo(expected).Within(1).Percent);
            Assert.That(rope.GetPinForce(0).Length, Is.EqualTo((500.0 + ropeMass) * RopeTestKit.G).Within(1).Percent);
        }
    }
}
