using System;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.MaterialLaw
{
    /// <summary>Issue 15 item 5: the quasi-static force–elongation curve (the inspector preview's geometry, the lab plot's reference) against the law's formulas.</summary>
    public sealed class ForceElongationCurveTests
    {
        [Test]
        public void ElasticCurveIsHookesLineToTheEndStrain()
        {
            var s = new RopeSettings { RestLength = 2f };
            s.AxialStiffness = 1e4f;
            var c = ForceElongationCurve.Of(s, 0.6);
            Assert.That(c.Count, Is.EqualTo(2));
            Assert.That(c.Elongation[1], Is.EqualTo(1.2).Within(1e-9));
            Assert.That(c.Force[1], Is.EqualTo(1e4 * 0.6).Within(1e-6).Percent);
            Assert.That(double.IsNaN(c.BreakElongation), Is.True, "an open end");
        }

        [Test]
        public void PlasticCurveYieldsHardensNecksAndBreaks()
        {
            // 1 m, 20 segments, E·A 1e7 N, ε_y 0.002, H 1e5 N, necking at 0.15, ultimate 0.35
            var s = new RopeSettings { RestLength = 1f, SegmentCount = 20 };
            s.AxialStiffness = 1e7f;
            s.SetPlasticity(0.002f, 1e5f, 0.15f, 0.35f);
            var c = ForceElongationCurve.Of(s, 0.6);
            double ea = s.AxialStiffness, ty = ea * 0.002, onset = (0.15 - 0.002) / (1 + 1e5 / ea), fn = ty + 1e5 * onset;
            Assert.That(c.Count, Is.EqualTo(4));
            Assert.That(c.Force[1], Is.EqualTo(ty).Within(1e-4).Percent, "yield force E·A·ε_y");
            Assert.That(c.Elongation[1], Is.EqualTo(0.002).Within(1e-4).Percent, "at the yield strain");
            Assert.That(c.Force[2], Is.EqualTo(fn).Within(1e-4).Percent, "neck onset F_n = E·A·ε_y + H·ε_pn");
            Assert.That(c.Elongation[2], Is.EqualTo(0.15).Within(1e-4).Percent, "at the necking strain (the whole rope)");
            Assert.That(c.PeakForce, Is.EqualTo(fn).Within(1e-4).Percent);
            // the neck segment (L/20) goes to the ultimate strain at zero force; the other 19 keep the set ε_pn
            double broken = 0.05 * 0.35 + 0.95 * onset;
            Assert.That(c.Force[3], Is.EqualTo(0.0));
            Assert.That(c.BreakElongation, Is.EqualTo(broken).Within(1e-4).Percent);
            for (int i = 1; i < c.Count; i++) Assert.That(c.Elongation[i], Is.GreaterThanOrEqualTo(c.Elongation[i - 1]));
            Assert.That(c.ForceAt(0.001), Is.EqualTo(ea * 0.001).Within(1e-4).Percent);
            Assert.That(c.ForceAt(broken + 0.1), Is.EqualTo(0.0), "nothing past the break");
        }

        [Test]
        public void AbsorberCurveHasThePlateauOverItsDeploymentThenTheWebbing()
        {
            var s = new RopeSettings { RestLength = 2f, SegmentCount = 20 };
            s.AxialStiffness = 1e5f;
            s.UseEnergyAbsorber(4000f, 1.75f);
            var c = ForceElongationCurve.Of(s, 0.1);
            double k = 1e5 / 2, xe = 4000 / k;
            Assert.That(c.Count, Is.EqualTo(4));
            Assert.That(c.Elongation[1], Is.EqualTo(xe).Within(1e-4).Percent, "x_e = F_p/k");
            Assert.That(c.Force[1], Is.EqualTo(4000).Within(1e-4).Percent);
            Assert.That(c.Force[2], Is.EqualTo(4000).Within(1e-4).Percent, "the plateau");
            Assert.That(c.Elongation[2] - c.Elongation[1], Is.EqualTo(1.75).Within(1e-6).Percent, "its deployment length");
            // then the webbing's stiffness k again, to a quarter beyond the deployed length
            Assert.That((c.Force[3] - c.Force[2]) / (c.Elongation[3] - c.Elongation[2]), Is.EqualTo(k).Within(1e-6).Percent);
        }

        [Test]
        public void PlasticRopeWithAnAbsorberDeploysOnTheHardeningBranch()
        {
            var s = new RopeSettings { RestLength = 2f, SegmentCount = 10 };
            s.AxialStiffness = 1e5f;
            s.SetPlasticity(0.02f, 1e4f, 0.3f, 0.4f);   // yields at 2 kN, necks at 2 kN + 1e4·ε_pn
            s.UseEnergyAbsorber(2500f, 0.5f);
            var c = ForceElongationCurve.Of(s, 0.5);
            // 0 → yield 2000 → plateau 2500 (deploys 0.5 m) → onset → break
            Assert.That(c.Force[1], Is.EqualTo(2000).Within(1e-4).Percent);
            Assert.That(c.Force[2], Is.EqualTo(2500).Within(1e-4).Percent);
            Assert.That(c.Elongation[3] - c.Elongation[2], Is.EqualTo(0.5).Within(1e-4).Percent);
            Assert.That(c.Force[c.Count - 1], Is.EqualTo(0.0));
        }

        [Test]
        public void EndStrainMustBePositiveAndFinite()
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => ForceElongationCurve.Of(new RopeSettings(), 0.0));
            Assert.That(e.ParamName, Is.EqualTo("endStrain"));
            Assert.Throws<ArgumentNullException>(() => ForceElongationCurve.Of(null, 1.0));
        }
    }
}
