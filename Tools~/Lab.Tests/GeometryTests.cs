using System;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using HookeRope.Mathematics;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>Initial shapes and the analytic helpers the physics checks rely on.</summary>
    [TestFixture]
    public sealed class GeometryTests
    {
        [Test]
        public void CatenaryParameterSatisfiesItsLengthEquation()
        {
            double a = ScenarioGeometry.CatenaryParameter(8, 10);
            Assert.That(2 * a * Math.Sinh(8 / (2 * a)), Is.EqualTo(10).Within(1e-9));
        }

        [Test]
        public void CatenaryShapeHasTheRopeLengthAndTheAnalyticSag()
        {
            var s = BuiltInScenarios.Load("catenary");
            var p = new Float3[s.Rope.Segments + 1];
            ScenarioGeometry.InitialPositions(s, p);
            double length = 0, sag = 0;
            for (int i = 1; i < p.Length; i++) length += (p[i] - p[i - 1]).Length;
            foreach (var q in p) sag = Math.Max(sag, -q.Y);
            Assert.That(length, Is.EqualTo(10).Within(0.01));  // chords of the arc: slightly shorter
            Assert.That(sag, Is.EqualTo(ScenarioGeometry.CatenarySag(8, 10)).Within(1e-3));
        }

        [Test]
        public void FallHeightRaisesTheLoadAboveTheAnchor()
        {
            var s = BuiltInScenarios.Load("fall-arrest");
            var end = ScenarioGeometry.EndPosition(s);
            Assert.That(end.Y, Is.EqualTo(4.0 - 2.0).Within(1e-6));
            var p = new Float3[s.Rope.Segments + 1];
            ScenarioGeometry.InitialPositions(s, p);
            for (int i = 1; i < p.Length; i++) Assert.That((p[i] - p[i - 1]).Length, Is.EqualTo(0.1).Within(1e-5));
        }

        [Test]
        public void SlackShapeIsAVeeOfTheRestLength()
        {
            var s = ScenarioParser.Parse("{\"rope\":{\"restLength\":2,\"segments\":10},\"end\":{\"type\":\"fixed\",\"position\":[1,0,0]},\"initial\":{\"shape\":\"slack\"}}");
            var p = new Float3[11];
            ScenarioGeometry.InitialPositions(s, p);
            double length = 0;
            for (int i = 1; i < p.Length; i++) length += (p[i] - p[i - 1]).Length;
            Assert.That(length, Is.EqualTo(2).Within(1e-5));
            Assert.That(p[5].Y, Is.EqualTo(-Math.Sqrt(1 - 0.25)).Within(1e-5));
        }

        [Test]
        public void AnalyticAnswersMatchTheNotes()
        {
            // 100 kg, k = 2500 N/m, h = 4 m: F = 981 + sqrt(981² + 2·981·2500·4).
            Assert.That(PhysicsChecks.FallArrestForce(100, 9.81, 2500, 4), Is.EqualTo(981 + Math.Sqrt(981.0 * 981 + 2 * 981.0 * 2500 * 4)).Within(1e-9));
            // Light rope limit of the heavy-rope period is the spring period.
            Assert.That(PhysicsChecks.HeavyRopePeriod(10, 1e-6, 1, 1e4), Is.EqualTo(2 * Math.PI * Math.Sqrt(10.0 / 1e4)).Within(1e-6));
            Assert.That(PhysicsChecks.PoissonRadiusRatio(0.5, 1.0), Is.EqualTo(Math.Sqrt(0.5)).Within(1e-12));
            Assert.That(PhysicsChecks.NeckWaist(1.0, 0.01), Is.EqualTo((Math.Sqrt(1 + 16e-4) - 1) / 4).Within(1e-12));
        }

        [Test]
        public void PeriodEstimatorRecoversASine()
        {
            var series = new double[2000];
            for (int i = 0; i < series.Length; i++) series[i] = 3 + Math.Sin(2 * Math.PI * i * 0.001 / 0.123);
            Assert.That(PhysicsChecks.Period(series, 0.001), Is.EqualTo(0.123).Within(1e-4));
        }
    }
}
