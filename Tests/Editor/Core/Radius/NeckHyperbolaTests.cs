using System;
using HookeRope.Radius;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Radius
{
    public sealed class NeckHyperbolaTests
    {
        [TestCase(0.01, 0.005)]
        [TestCase(0.1, 0.005)]
        [TestCase(2.0, 0.0048)]
        [TestCase(50.0, 0.001)]
        public void CancellationFreeAndPrintedFormsAgreeInDouble(double length, double endRadius)
        {
            double a = NeckHyperbola.WaistRadius(length, endRadius);
            double b2 = NeckHyperbola.AxisSquared(length, endRadius);
            // In double the printed form keeps about 16 − 2·log10(l/r) digits: ≥ 7 here.
            Assert.That(NeckHyperbola.WaistRadiusPrinted(length, endRadius), Is.EqualTo(a).Within(1e-7 * a));
            Assert.That(NeckHyperbola.AxisSquaredPrinted(length, endRadius), Is.EqualTo(b2).Within(1e-7 * b2));
        }

        [TestCase(0.01, 0.005)]
        [TestCase(2.0, 0.0048)]
        [TestCase(50.0, 0.001)]
        public void HyperbolaPassesThroughTheEndsWithASquaredPlusBSquaredEqualRMinSquared(double length, double endRadius)
        {
            double a = NeckHyperbola.WaistRadius(length, endRadius);
            double b2 = NeckHyperbola.AxisSquared(length, endRadius);
            Assert.That(a * a + b2, Is.EqualTo(endRadius * endRadius).Within(1e-12 * endRadius * endRadius));
            Assert.That(NeckHyperbola.Radius(0.5 * length, a, b2), Is.EqualTo(endRadius).Within(1e-12 * endRadius));
            Assert.That(NeckHyperbola.Radius(-0.5 * length, a, b2), Is.EqualTo(endRadius).Within(1e-12 * endRadius));
            Assert.That(NeckHyperbola.Radius(0.0, a, b2), Is.EqualTo(a));
        }

        [Test]
        public void LongRopeNeckIsAboutTwoRMinSquaredOverLength()
        {
            // 2 m lanyard of 6 mm radius, r_min = 0.8 R = 4.8 mm: the neck jumps to a hair at onset.
            double a = NeckHyperbola.WaistRadius(2.0, 0.0048);
            Assert.That(a, Is.EqualTo(2.0 * 0.0048 * 0.0048 / 2.0).Within(1e-4 * a));
            Assert.That(a, Is.LessThan(2.4e-5));
        }

        [TestCase(2f, 5e-4)]
        [TestCase(20f, 1e-2)]
        public void Float32CancellationFreeFormKeepsDigitsThePrintedFormLoses(float length, double printedErrorAbove)
        {
            const float endRadius = 0.0048f;
            double exact = NeckHyperbola.WaistRadius((double)length, (double)endRadius);
            float stable = NeckHyperbola.WaistRadius(length, endRadius);
            float printed = (MathF.Sqrt(length * length + 16f * endRadius * endRadius) - length) / 4f;
            Assert.That(Math.Abs(stable - exact) / exact, Is.LessThan(1e-6));
            Assert.That(Math.Abs(printed - exact) / exact, Is.GreaterThan(printedErrorAbove));
            TestContext.WriteLine("l = " + length + " m: float32 printed a off by " + (Math.Abs(printed - exact) / exact).ToString("E2") + ", stable by " + (Math.Abs(stable - exact) / exact).ToString("E2"));
            float stableB2 = NeckHyperbola.AxisSquared(length, endRadius);
            Assert.That(stableB2, Is.EqualTo(NeckHyperbola.AxisSquared((double)length, (double)endRadius)).Within(1e-6 * stableB2));
        }
    }
}
