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
            yield return Case(s => s.RestLength = 0f, RopeParameters.RestLength.Row, "RestLength zero");
            yield return Case(s => s.RestLength = -1f, RopeParameters.RestLength.Row, "RestLength negative");
            yield return Case(s => s.RestLength = float.NaN, RopeParameters.RestLength.Row, "RestLength NaN");
            yield return Case(s => s.RestLength = float.PositiveInfinity, RopeParameters.RestLength.Row, "RestLength infinite");
            yield return Case(s => s.SegmentCount = 0, RopeParameters.SegmentCount.Row, "SegmentCount zero");
            yield return Case(s => s.SegmentCount = 10001, RopeParameters.SegmentCount.Row, "SegmentCount too many");
            yield return Case(s => s.Radius = 0f, RopeParameters.Radius.Row, "Radius zero");
            yield return Case(s => s.Radius = float.NaN, RopeParameters.Radius.Row, "Radius NaN");
            yield return Case(s => s.YoungsModulus = 0f, RopeParameters.YoungsModulus.Row, "YoungsModulus zero");
            yield return Case(s => s.YoungsModulus = float.NaN, RopeParameters.YoungsModulus.Row, "YoungsModulus NaN");
            yield return Case(s => s.AxialStiffness = -5f, RopeParameters.AxialStiffness.Row, "AxialStiffness negative");
            yield return Case(s => s.LinearDensity = 0f, RopeParameters.LinearDensity.Row, "LinearDensity zero");
            yield return Case(s => s.LinearDensity = float.PositiveInfinity, RopeParameters.LinearDensity.Row, "LinearDensity infinite");
            yield return Case(s => s.Density = -1f, RopeParameters.Density.Row, "Density negative");
            yield return Case(s => s.Damping = -0.1f, RopeParameters.Damping.Row, "Damping negative");
            yield return Case(s => s.Damping = float.NaN, RopeParameters.Damping.Row, "Damping NaN");
            yield return Case(s => s.Gravity = new Float3(0f, float.NaN, 0f), RopeParameters.Gravity.Row, "Gravity NaN");
            yield return Case(s => s.ViscousDrag = -0.1f, RopeParameters.ViscousDrag.Row, "ViscousDrag negative");
            yield return Case(s => s.ViscousDrag = float.NaN, RopeParameters.ViscousDrag.Row, "ViscousDrag NaN");
            yield return Case(s => s.ViscousDrag = float.PositiveInfinity, RopeParameters.ViscousDrag.Row, "ViscousDrag infinite");
            yield return Case(s => s.DragCoefficient = -1f, RopeParameters.DragCoefficient.Row, "DragCoefficient negative");
            yield return Case(s => s.DragCoefficient = float.NaN, RopeParameters.DragCoefficient.Row, "DragCoefficient NaN");
            yield return Case(s => s.SkinFriction = -0.01f, RopeParameters.SkinFriction.Row, "SkinFriction negative");
            yield return Case(s => s.AirDensity = -1.2f, RopeParameters.AirDensity.Row, "AirDensity negative");
            yield return Case(s => s.AirDensity = float.PositiveInfinity, RopeParameters.AirDensity.Row, "AirDensity infinite");
            yield return Case(s => s.Wind = new Float3(float.NaN, 0f, 0f), RopeParameters.Wind.Row, "Wind NaN");
            yield return Case(s => s.Wind = new Float3(0f, 0f, float.NegativeInfinity), RopeParameters.Wind.Row, "Wind infinite");
            yield return Case(s => s.Substeps = 0, RopeParameters.Substeps.Row, "Substeps zero");
            yield return Case(s => s.Iterations = 1001, RopeParameters.Iterations.Row, "Iterations too many");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Solver = (ConstraintSolverKind)7), "Solver", "named values").SetName("Solver undefined");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Tension = (TensionModel)7), "Tension", "named values").SetName("Tension undefined");
            yield return new TestCaseData(new Action<RopeSettings>(s => s.Integrator = (TimeIntegrator)7), "Integrator", "named values").SetName("Integrator undefined");
        }

        /// <summary>A bad value of a table parameter: the error names the row and its range and unit.</summary>
        private static TestCaseData Case(Action<RopeSettings> set, ParameterInfo row, string name) =>
            new TestCaseData(set, row.Name, row.RangeText).SetName(name);

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
            Assert.That(settings.RestLength, Is.EqualTo(RopeParameters.RestLength.Default));
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
