using System;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.MaterialLaw
{
    /// <summary>
    /// Issue 15, bad input: a yield strain above the break (ultimate) strain, a negative hardening, a plateau force ≤ 0 throw
    /// an <see cref="ArgumentException"/> naming the parameter and its valid range, and change nothing.
    /// </summary>
    public sealed class MaterialSettingsTests
    {
        static RopeSettings Plastic()
        {
            var s = new RopeSettings();
            s.SetPlasticity(0.1f, 5000f, 0.45f, 0.6f);
            return s;
        }

        static void AssertNames(Action set, string name, string range)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => set());
            Assert.That(e, Is.InstanceOf<ArgumentException>());
            Assert.That(e.ParamName, Is.EqualTo(name));
            Assert.That(e.Message, Does.Contain(name).And.Contain(range));
        }

        [Test]
        public void YieldStrainAboveTheUltimateStrainIsRejected()
        {
            var s = Plastic();
            int version = s.Version;
            AssertNames(() => s.YieldStrain = 0.7f, "YieldStrain", "(0, NeckingStrain = 0.45] and below UltimateStrain = 0.6");
            AssertNames(() => s.SetPlasticity(0.7f, 5000f, 0.45f, 0.6f), "YieldStrain", "below UltimateStrain = 0.6");
            AssertNames(() => s.UltimateStrain = 0.05f, "UltimateStrain", "(max(YieldStrain, NeckingStrain) = 0.45, 1000]");
            AssertNames(() => s.NeckingStrain = 0.05f, "NeckingStrain", "[YieldStrain = 0.1, UltimateStrain = 0.6)");
            Assert.That(s.YieldStrain, Is.EqualTo(0.1f));
            Assert.That(s.UltimateStrain, Is.EqualTo(0.6f));
            Assert.That(s.Version, Is.EqualTo(version), "a rejected value changes nothing");
        }

        [Test]
        public void SwitchingToPlasticChecksTheOrderOfTheStoredStrains()
        {
            var s = new RopeSettings { YieldStrain = 0.9f };   // elastic: the law's strains are not in use yet
            AssertNames(() => s.MaterialModel = MaterialModel.ElasticPlastic, "YieldStrain", "below UltimateStrain = 0.6");
            Assert.That(s.MaterialModel, Is.EqualTo(MaterialModel.Elastic));
            s.UltimateStrain = 1.2f;
            s.NeckingStrain = 1f;
            s.MaterialModel = MaterialModel.ElasticPlastic;
            Assert.That(s.MaterialModel, Is.EqualTo(MaterialModel.ElasticPlastic));
        }

        [Test]
        public void NegativeHardeningIsRejected()
        {
            var s = Plastic();
            AssertNames(() => s.HardeningModulus = -1f, "HardeningModulus", RopeParameters.HardeningModulus.Row.RangeText);
            AssertNames(() => s.SetPlasticity(0.1f, -1f, 0.45f, 0.6f), "HardeningModulus", RopeParameters.HardeningModulus.Row.RangeText);
            Assert.That(s.HardeningModulus, Is.EqualTo(5000f));
            s.HardeningModulus = 0f;   // a plateau
            Assert.That(s.HardeningModulus, Is.EqualTo(0f));
        }

        [TestCase(0f)]
        [TestCase(-4000f)]
        [TestCase(float.NaN)]
        public void PlateauForceAtOrBelowZeroIsRejected(float force)
        {
            var s = new RopeSettings();
            AssertNames(() => s.AbsorberForce = force, "AbsorberForce", RopeParameters.AbsorberForce.Row.RangeText);
            AssertNames(() => s.UseEnergyAbsorber(force, 1.75f), "AbsorberForce", RopeParameters.AbsorberForce.Row.RangeText);
            Assert.That(s.EnergyAbsorber, Is.False, "the preset changes nothing when rejected");
            Assert.That(s.AbsorberForce, Is.EqualTo(RopeParameters.AbsorberForce.Default));
        }

        [Test]
        public void DeploymentLengthAtOrBelowZeroIsRejected()
        {
            var s = new RopeSettings();
            AssertNames(() => s.AbsorberDeployment = 0f, "AbsorberDeployment", RopeParameters.AbsorberDeployment.Row.RangeText);
            AssertNames(() => s.UseEnergyAbsorber(4000f, -1f), "AbsorberDeployment", RopeParameters.AbsorberDeployment.Row.RangeText);
        }

        [Test]
        public void DefaultsAreTheTablesAndConsistent()
        {
            var s = new RopeSettings();
            Assert.That(s.MaterialModel, Is.EqualTo(MaterialModel.Elastic));
            Assert.That(s.EnergyAbsorber, Is.False);
            Assert.That(s.YieldStrain, Is.LessThanOrEqualTo(s.NeckingStrain));
            Assert.That(s.NeckingStrain, Is.LessThan(s.UltimateStrain));
            s.MaterialModel = MaterialModel.ElasticPlastic;   // the defaults are a valid law
            Assert.That(s.YieldForce, Is.EqualTo(s.AxialStiffness * s.YieldStrain).Within(1e-6).Percent);
            s.UseEnergyAbsorber();
            Assert.That(s.AbsorberForce, Is.EqualTo(4000f));
            Assert.That(s.AbsorberDeployment, Is.EqualTo(1.75f));
        }
    }
}
