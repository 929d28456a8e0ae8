using System;
using System.Text.RegularExpressions;
using HookeRope.Solver;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in), issue 15 item 5: the component's material law. Its fields
    /// reach the core live, the setters reject bad input naming the parameter and its range, OnValidate restores the
    /// order of the plastic strains, and a worker Rigidbody arrested by a stiff lanyard with the absorber preset reads a
    /// plateau arrest force, an EN 355 pass and the deployment.
    /// </summary>
    [TestFixture]
    public sealed class MaterialLawComponentTests
    {
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        ElasticRope Lanyard(float axialStiffness, out Rigidbody body)
        {
            var anchor = _scene.Point("Anchor", new Vector3(0f, 20f, 0f));
            body = _scene.Body("Worker", new Vector3(0.01f, 20f + 4f - 2f, 0f), 100f);
            var rope = _scene.Rope("Lanyard", anchor.position);
            rope.RestLength = 2f;
            rope.AxialStiffness = axialStiffness;
            rope.SegmentCount = 16;
            rope.Damping = 0f;
            rope.Fracture = false;
            rope.StartAttachment.Point = anchor;
            rope.EndAttachment.Body = body;
            return rope;
        }

        [Test]
        public void AbsorberPresetCapsTheWorkersArrestForceAndPassesEn355()
        {
            var rope = Lanyard(1e5f, out _);
            rope.UseEnergyAbsorber();   // 4 kN, 1.75 m
            rope.Rebuild();
            UnityRopeScene.Run(rope, 600, 0.005f);
            TestContext.WriteLine($"peak arrest force {rope.PeakArrestForce:F1} N, deployed {rope.AbsorberDeployed:F4} m, permanent set {rope.PlasticElongation:F4} m, plastic work {rope.PlasticWork:F1} J");
            // the lanyard starts pointing up from the anchor to the worker, folds over and whips taut (measured 3999.9 N, 1.258 m)
            Assert.That(rope.PeakArrestForce, Is.EqualTo(4000f).Within(2).Percent);
            Assert.That(rope.MeetsEn355, Is.True);
            Assert.That(rope.AbsorberDeployed, Is.EqualTo(1.27f).Within(3).Percent, "the energy balance's 1.27 m less what the rope's own whip took");
            Assert.That(rope.PlasticWork, Is.EqualTo(4000f * rope.AbsorberDeployed).Within(1).Percent);
        }

        [Test]
        public void MaterialFieldsReachTheCoreLive()
        {
            var rope = Lanyard(3e4f, out _);
            rope.Rebuild();
            var core = rope.Simulation.Rope;
            rope.SetPlasticity(0.05f, 2000f, 0.3f, 0.5f);
            rope.UseEnergyAbsorber(3500f, 1.2f);
            rope.Simulate(0.01f);
            Assert.That(rope.Simulation.Rope, Is.SameAs(core), "no rebuild");
            var s = core.Settings;
            Assert.That(s.MaterialModel, Is.EqualTo(MaterialModel.ElasticPlastic));
            Assert.That(new[] { s.YieldStrain, s.HardeningModulus, s.NeckingStrain, s.UltimateStrain }, Is.EqualTo(new[] { 0.05f, 2000f, 0.3f, 0.5f }));
            Assert.That(s.EnergyAbsorber, Is.True);
            Assert.That(s.AbsorberForce, Is.EqualTo(3500f));
            Assert.That(s.AbsorberDeployment, Is.EqualTo(1.2f));
            Assert.That(core.AbsorberSegment, Is.EqualTo(15));
            rope.MaterialModel = MaterialModel.Elastic;
            rope.EnergyAbsorber = false;
            rope.Simulate(0.01f);
            Assert.That(s.MaterialModel, Is.EqualTo(MaterialModel.Elastic));
            Assert.That(core.AbsorberSegment, Is.EqualTo(-1));
        }

        [Test]
        public void SettersRejectBadInputNamingTheParameterAndRange()
        {
            var rope = _scene.Rope("Rope", Vector3.zero);
            rope.SetPlasticity(0.1f, 5000f, 0.45f, 0.6f);
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => rope.YieldStrain = 0.7f);
            Assert.That(e.ParamName, Is.EqualTo("YieldStrain"));
            Assert.That(e.Message, Does.Contain("below UltimateStrain = 0.6"));
            Assert.That(rope.YieldStrain, Is.EqualTo(0.1f));
            e = Assert.Throws<ArgumentOutOfRangeException>(() => rope.HardeningModulus = -5f);
            Assert.That(e.Message, Does.Contain("HardeningModulus").And.Contain(RopeParameters.HardeningModulus.Row.RangeText));
            e = Assert.Throws<ArgumentOutOfRangeException>(() => rope.AbsorberForce = 0f);
            Assert.That(e.Message, Does.Contain("AbsorberForce").And.Contain(RopeParameters.AbsorberForce.Row.RangeText));
            e = Assert.Throws<ArgumentOutOfRangeException>(() => rope.UseEnergyAbsorber(-1f));
            Assert.That(e.ParamName, Is.EqualTo("AbsorberForce"));
            Assert.That(rope.EnergyAbsorber, Is.False);
        }

        [Test]
        public void OnValidateRestoresTheOrderOfThePlasticStrains()
        {
            var rope = _scene.Rope("Rope", Vector3.zero);
            var so = new SerializedObject(rope);
            so.FindProperty("m_MaterialModel").intValue = (int)MaterialModel.ElasticPlastic;
            so.FindProperty("m_YieldStrain").floatValue = 0.5f;
            so.FindProperty("m_NeckingStrain").floatValue = 0.2f;
            so.FindProperty("m_UltimateStrain").floatValue = 0.3f;
            LogAssert.Expect(LogType.Warning, new Regex("Necking strain 0.2 is below the yield strain 0.5; raised to it"));
            LogAssert.Expect(LogType.Warning, new Regex("Ultimate strain 0.3 is not above the necking strain 0.5; raised to 0.625"));
            so.ApplyModifiedPropertiesWithoutUndo();
            Assert.That(rope.YieldStrain, Is.EqualTo(0.5f), "the yield strain is kept");
            Assert.That(rope.NeckingStrain, Is.EqualTo(0.5f), "necking raised to the yield strain");
            Assert.That(rope.UltimateStrain, Is.GreaterThan(rope.NeckingStrain), "ultimate above necking");
            Assert.DoesNotThrow(() => new RopeSettings().SetPlasticity(rope.YieldStrain, rope.HardeningModulus, rope.NeckingStrain, rope.UltimateStrain));
        }
    }
}
