using System;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>Issue 17 item 4: the drawn tube stays outside the bar it wraps.</summary>
    public sealed class ContactDrawingTests
    {
        [Test]
        public void DrawnTubeStaysOutsideTheWrappedBar()
        {
            var s = BuiltInScenarios.Load("collision-bend");
            var r = ScenarioRunner.Run(s, new RunOptions { TrackEnergy = false });
            Assert.That(r.Meshes.Count, Is.EqualTo(1));
            var mesh = r.Meshes[0];
            const double bar = 0.1; // capsule along z through the origin, radius 0.1 m
            double deepest = double.MaxValue;
            for (int k = 0; k < mesh.TubeIndexCount; k++)
            {
                int o = 12 * mesh.Indices[k];
                double x = mesh.Vertices[o], y = mesh.Vertices[o + 1];
                deepest = Math.Min(deepest, Math.Sqrt(x * x + y * y) - bar);
            }
            double radius = s.Rope.Radius;
            TestContext.WriteLine("drawn surface to bar: " + deepest / radius + " rope radii (rest radius " + radius + " m)");
            Assert.That(deepest, Is.GreaterThan(-0.02 * radius));
        }
    }
}
