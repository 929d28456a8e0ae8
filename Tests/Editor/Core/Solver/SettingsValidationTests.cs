using System;
using System.Collections.Generic;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    public sealed class SettingsValidationTests
    {
        private static IEnumerable<TestCaseData> BadSettings()
        {
            yield return new TestCaseData(new Action<RopeSettings>(s => s.RestLength = 0f), "RestLength", "(0, 100000] m").SetName("RestLength zero");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.RestLength = -1f), "RestLength", "(0, 100000] m").SetName("RestLength negative");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.RestLength = float.NaN), "RestLength", "(0, 100000] m").SetName("RestLength NaN");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.RestLength = float.PositiveInfinity), "RestLength", "(0, 100000] m").SetName("RestLength infinite");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.SegmentCount = 0), "SegmentCount", "[1, 10000]").SetName("SegmentCount zero");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.SegmentCount = 10001), "SegmentCount", "[1, 10000]").SetName("SegmentCount too many");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Radius = 0f), "Radius", "(0, 10] m").SetName("Radius zero");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Radius = float.NaN), "Radius", "(0, 10] m").SetName("Radius NaN");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.YoungsModulus = 0f), "YoungsModulus", "(0, +inf] Pa").SetName("YoungsModulus zero");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.YoungsModulus = float.NaN), "YoungsModulus", "(0, +inf] Pa").SetName("YoungsModulus NaN");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.AxialStiffness = -5f), "AxialStiffness", "(0, +inf] N").SetName("AxialStiffness negative");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.LinearDensity = 0f), "LinearDensity", "(0, +inf) kg/m").SetName("LinearDensity zero");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.LinearDensity = float.PositiveInfinity), "LinearDensity", "(0, +inf) kg/m").SetName("LinearDensity infinite");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Density = -1f), "Density", "(0, 1000000] kg/m³").SetName("Density negative");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Damping = -0.1f), "Damping", "[0, +inf) s").SetName("Damping negative");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Damping = float.NaN), "Damping", "[0, +inf) s").SetName("Damping NaN");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Gravity = new Float3(0f, float.NaN, 0f)), "Gravity", "finite").SetName("Gravity NaN");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Substeps = 0), "Substeps", "[1, 1000]").SetName("Substeps zero");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Iterations = 1001), "Iterations", "[1, 1000]").SetName("Iterations too many");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Solver = (ConstraintSolverKind)7), "Solver", "GaussSeidel or ExactChain").SetName("Solver undefined");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Tension = (TensionModel)7), "Tension", "TensionOnly or Bilateral").SetName("Tension undefined");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.BreakStrain = -0.5f), "BreakStrain", "[0, +inf]").SetName("BreakStrain negative");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.BreakStrain = float.NaN), "BreakStrain", "[0, +inf]").SetName("BreakStrain NaN");
        }

        [TestCaseSource(nameof(BadSettings))]
        public void InvalidSettingThrowsNamingParameterAndRangeAndKeepsTheOldValue(Action<RopeSettings> set, string parameter, string range)
        {
            var settings = new RopeSettings();
            int version = settings.Version;
            var error = Assert.Throws(Is.InstanceOf<ArgumentException>(), () => set(settings)) as ArgumentException;
            Assert.That(error.ParamName, Is.EqualTo(parameter));
            Assert.That(error.Message, Does.Contain(parameter));
            Assert.That(error.Message, Does.Contain(range));
            Assert.That(settings.Version, Is.EqualTo(version), "a rejected value changes nothing");
            Assert.That(settings.RestLength, Is.EqualTo(RopeSettings.DefaultRestLength));
        }

        [Test]
        public void InfiniteYoungsModulusMeansAnInextensibleRope()
        {
            var settings = RopeTestKit.Legacy(length: 1f, segments: 8, youngsModulus: float.PositiveInfinity);
            var rope = RopeTestKit.Hanging(settings, 10f, out _);
            for (int i = 0; i < 90; i++) rope.Step(RopeTestKit.HostStep);
            Assert.That(-RopeTestKit.Bottom(rope), Is.EqualTo(1.0).Within(1e-5));
            Assert.That(rope.GetPinForce(0).Length, Is.EqualTo((10.0 + settings.LinearDensity) * RopeTestKit.G).Within(0.5).Percent);
        }

        [Test]
        public void AreaLinksModulusAndStiffnessAndDensities()
        {
            var settings = new RopeSettings { Radius = 0.01f, YoungsModulus = 2e9f, Density = 1000f };
            double area = Math.PI * 0.01 * 0.01;
            Assert.That(settings.AxialStiffness, Is.EqualTo(2e9 * area).Within(1e-5).Percent);
            Assert.That(settings.LinearDensity, Is.EqualTo(1000 * area).Within(1e-5).Percent);
            settings.AxialStiffness = 1e5f;
            Assert.That(settings.YoungsModulus, Is.EqualTo(1e5 / area).Within(1e-5).Percent);
            settings.LinearDensity = 0.5f;
            Assert.That(settings.Density, Is.EqualTo(0.5 / area).Within(1e-5).Percent);
            settings.Radius = 0.02f; // the material stays, the cross-section quadruples
            Assert.That(settings.AxialStiffness, Is.EqualTo(4e5).Within(1e-4).Percent);
            Assert.That(settings.LinearDensity, Is.EqualTo(2.0).Within(1e-4).Percent);
        }

        [Test]
        public void BadRopeArgumentsThrowNamingTheParameter()
        {
            var settings = new RopeSettings();
            Assert.That(Assert.Throws<ArgumentNullException>(() => new Rope(null, Float3.Zero, Float3.Zero)).ParamName, Is.EqualTo("settings"));
            Assert.That(Assert.Throws<ArgumentException>(() => new Rope(settings, new Float3(float.NaN, 0f, 0f), Float3.Zero)).ParamName, Is.EqualTo("start"));
            var rope = new Rope(settings, Float3.Zero, new Float3(0f, -1f, 0f));
            var stepError = Assert.Throws<ArgumentOutOfRangeException>(() => rope.Step(0f));
            Assert.That(stepError.ParamName, Is.EqualTo("hostDeltaTime"));
            Assert.That(stepError.Message, Does.Contain("(0, 1] s"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => rope.Step(float.NaN)).ParamName, Is.EqualTo("hostDeltaTime"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => rope.AddLoad(0, -1f)).ParamName, Is.EqualTo("mass"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => rope.AddLoad(0, float.NaN)).ParamName, Is.EqualTo("mass"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => rope.AddPin(rope.ParticleCount, Float3.Zero)).ParamName, Is.EqualTo("particle"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => rope.AddPin(0, Float3.Zero, -1f)).ParamName, Is.EqualTo("compliance"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => rope.AddPin(0, Float3.Zero, 0f, 0f)).ParamName, Is.EqualTo("breakForce"));
            Assert.That(Assert.Throws<ArgumentException>(() => rope.SetVelocity(1, new Float3(float.PositiveInfinity, 0f, 0f))).ParamName, Is.EqualTo("velocity"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => ColliderShape.Sphere(Float3.Zero, 0f)).ParamName, Is.EqualTo("radius"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => ColliderShape.Sphere(Float3.Zero, 1f, -1f)).ParamName, Is.EqualTo("friction"));
            Assert.That(Assert.Throws<ArgumentException>(() => ColliderShape.Plane(Float3.Zero, Float3.Zero)).ParamName, Is.EqualTo("normal"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => rope.BreakSegment(-1)).ParamName, Is.EqualTo("segment"));
        }

        [Test]
        public void NaNPinTargetIsRejectedWithoutCorruptingTheRope()
        {
            var settings = RopeTestKit.Legacy(segments: 8);
            var rope = RopeTestKit.Hanging(settings, 1f, out _);
            var twin = RopeTestKit.Hanging(settings.Clone(), 1f, out _);
            for (int i = 0; i < 10; i++) { rope.Step(RopeTestKit.HostStep); twin.Step(RopeTestKit.HostStep); }
            var error = Assert.Throws<ArgumentException>(() => rope.SetPinTarget(0, new Float3(0f, float.NaN, 0f)));
            Assert.That(error.ParamName, Is.EqualTo("target"));
            Assert.Throws<ArgumentException>(() => rope.SetPinTarget(0, new Float3(float.PositiveInfinity, 0f, 0f)));
            Assert.Throws<ArgumentOutOfRangeException>(() => rope.SetColliderPose(0, Float3.Zero, Quat.Identity), "no collider yet");
            for (int i = 0; i < 30; i++) { rope.Step(RopeTestKit.HostStep); twin.Step(RopeTestKit.HostStep); }
            Assert.That(rope.GetPinTarget(0), Is.EqualTo(Float3.Zero));
            Assert.That(RopeTestKit.AllFinite(rope), Is.True);
            for (int i = 0; i < rope.ParticleCount; i++) Assert.That(rope.GetPosition(i), Is.EqualTo(twin.GetPosition(i)));
        }
    }
}
