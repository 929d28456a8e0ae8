using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Parameters
{
    /// <summary>The parameter table is consistent: every nested class is a row, its consts equal the row, ranges hold the default.</summary>
    public sealed class ParameterTableTests
    {
        static IEnumerable<Type> NestedClasses() =>
            typeof(RopeParameters).GetNestedTypes(BindingFlags.Public).Where(t => t.IsAbstract && t.IsSealed);

        static object Const(Type t, string name) =>
            t.GetField(name, BindingFlags.Public | BindingFlags.Static) is FieldInfo f && f.IsLiteral ? f.GetRawConstantValue() : null;

        [Test]
        public void EveryNestedClassIsARowOfAllAndEveryRowHasItsClass()
        {
            var classes = NestedClasses().ToList();
            Assert.That(classes.Count, Is.EqualTo(RopeParameters.All.Count));
            foreach (var t in classes)
            {
                var row = (ParameterInfo)t.GetField("Row", BindingFlags.Public | BindingFlags.Static).GetValue(null);
                Assert.That(RopeParameters.All, Does.Contain(row), t.Name);
                Assert.That(row.Name, Is.EqualTo(t.Name));
                Assert.That(RopeParameters.Find(t.Name), Is.SameAs(row));
            }
        }

        [Test]
        public void TheConstsOfEachClassEqualItsRow()
        {
            foreach (var t in NestedClasses())
            {
                var row = RopeParameters.Find(t.Name);
                Assert.That(Const(t, "Name"), Is.EqualTo(row.Name), t.Name);
                Assert.That(Const(t, "Label"), Is.EqualTo(row.Label), t.Name);
                Assert.That(Const(t, "Unit"), Is.EqualTo(row.Unit), t.Name);
                Assert.That(Const(t, "Json"), Is.EqualTo(row.Json), t.Name);
                Assert.That(Const(t, "Tooltip"), Is.EqualTo(row.Tooltip), t.Name);
                Assert.That(Const(t, "MinExclusive") ?? false, Is.EqualTo(row.MinExclusive), t.Name);
                Assert.That(Const(t, "MaxExclusive") ?? false, Is.EqualTo(row.MaxExclusive), t.Name);
                var min = Const(t, "Min");
                if (min != null) Assert.That(Convert.ToDouble(min), Is.EqualTo(row.Min), t.Name + ".Min");
                var max = Const(t, "Max");
                if (max != null) Assert.That(Convert.ToDouble(max), Is.EqualTo(row.Max), t.Name + ".Max");
                var def = Const(t, "Default");
                if (def is bool b) Assert.That(row.Default, Is.EqualTo(b ? 1.0 : 0.0), t.Name + ".Default");
                else if (def is Enum) Assert.That(row.Default, Is.EqualTo((double)Convert.ToInt32(def)), t.Name + ".Default");
                else if (def != null) Assert.That(row.Default, Is.EqualTo(Convert.ToDouble(def)), t.Name + ".Default");
                else Assert.That(row.Kind, Is.EqualTo(ParameterKind.Vector).Or.EqualTo(ParameterKind.Color), t.Name + " has no Default const");
            }
        }

        [Test]
        public void EveryDefaultLiesInItsRange()
        {
            foreach (var row in RopeParameters.All)
            {
                Assert.That(row.Min, Is.LessThan(row.Max), row.Name);
                if (row.Kind == ParameterKind.Vector || row.Kind == ParameterKind.Color)
                {
                    Assert.That(row.DefaultComponents.Count, Is.EqualTo(row.Kind == ParameterKind.Vector ? 3 : 4), row.Name);
                    foreach (float c in row.DefaultComponents) Assert.That(RopeParameters.Contains(row, c), Is.True, row.Name);
                }
                else
                {
                    Assert.That(RopeParameters.Contains(row, row.Default), Is.True, row.Name + " default " + row.Default + " in " + row.RangeText);
                    if (row.Kind == ParameterKind.Int || row.Kind == ParameterKind.Enum || row.Kind == ParameterKind.Bool)
                        Assert.That(row.Default, Is.EqualTo(Math.Floor(row.Default)), row.Name);
                }
                Assert.That(row.Label, Is.Not.Empty, row.Name);
                Assert.That(row.Tooltip, Is.Not.Empty, row.Name);
                Assert.That(row.Unit, Is.Not.Null, row.Name);
            }
        }

        [Test]
        public void NamesAndJsonNamesAreUnique()
        {
            var names = RopeParameters.All.Select(r => r.Name).ToList();
            Assert.That(names, Is.Unique);
            var json = RopeParameters.All.Where(r => r.Json != null).Select(r => r.Json).ToList();
            Assert.That(json, Is.Unique);
            Assert.That(RopeParameters.All.Select(r => r.Label).ToList(), Is.Unique);
        }

        [Test]
        public void TheDefaultsAreTheComponentValues()
        {
            Assert.That(RopeParameters.RestLength.Default, Is.EqualTo(2f));
            Assert.That(RopeParameters.Radius.Default, Is.EqualTo(0.008f));
            Assert.That(RopeParameters.SegmentCount.Default, Is.EqualTo(24));
            Assert.That(RopeParameters.YoungsModulus.Default, Is.EqualTo(1.5e8f));
            Assert.That(RopeParameters.Density.Default, Is.EqualTo(1140f));
            Assert.That(RopeParameters.PoissonRatio.Default, Is.EqualTo(0.3f));
            Assert.That(RopeParameters.Damping.Default, Is.EqualTo(0.002f));
            Assert.That(RopeParameters.NeckRadiusFraction.Default, Is.EqualTo(0.75f));
            Assert.That(RopeParameters.BreakStrain.Default, Is.EqualTo(0.6f));
            Assert.That(RopeParameters.RadialSegments.Default, Is.EqualTo(12));
        }

        [Test]
        public void DerivedDefaultsFollowTheCrossSection()
        {
            double area = Math.PI * RopeParameters.Radius.Default * RopeParameters.Radius.Default;
            Assert.That(RopeParameters.AxialStiffness.Default, Is.EqualTo(RopeParameters.YoungsModulus.Default * area).Within(0.01).Percent, "the component stores 30159 N");
            Assert.That(RopeParameters.LinearDensity.Default, Is.EqualTo(RopeParameters.Density.Default * area).Within(1e-4).Percent);
        }

        [Test]
        public void CheckAcceptsTheRangeAndNamesParameterRangeAndUnitOutside()
        {
            foreach (var row in RopeParameters.All)
            {
                if (row.Kind == ParameterKind.Float)
                {
                    float low = row.MinExclusive ? NextUp((float)row.Min) : (float)row.Min;
                    float high = row.MaxExclusive ? NextDown((float)row.Max) : (float)row.Max;
                    Assert.That(RopeParameters.Check(low, row), Is.EqualTo(low), row.Name);
                    Assert.That(RopeParameters.Check(high, row), Is.EqualTo(high), row.Name);
                    float below = row.MinExclusive ? (float)row.Min : NextDown((float)row.Min);
                    float above = row.MaxExclusive ? (float)row.Max : NextUp((float)row.Max);
                    AssertThrowsNaming(() => RopeParameters.Check(below, row), row);
                    AssertThrowsNaming(() => RopeParameters.Check(above, row), row);
                    AssertThrowsNaming(() => RopeParameters.Check(float.NaN, row), row);
                    if (row.AllowsPositiveInfinity) Assert.That(RopeParameters.Check(float.PositiveInfinity, row), Is.EqualTo(float.PositiveInfinity), row.Name);
                    else AssertThrowsNaming(() => RopeParameters.Check(float.PositiveInfinity, row), row);
                }
                else if (row.Kind == ParameterKind.Int)
                {
                    Assert.That(RopeParameters.Check((int)row.Min, row), Is.EqualTo((int)row.Min), row.Name);
                    Assert.That(RopeParameters.Check((int)row.Max, row), Is.EqualTo((int)row.Max), row.Name);
                    if (row.Min > int.MinValue) AssertThrowsNaming(() => RopeParameters.Check((int)row.Min - 1, row), row);
                    if (row.Max < int.MaxValue) AssertThrowsNaming(() => RopeParameters.Check((int)row.Max + 1, row), row);
                }
            }
        }

        [Test]
        public void CheckMessagesReadLikeTheOldLimits()
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => RopeParameters.Check(0.001f, RopeParameters.RestLength.Row));
            Assert.That(e.ParamName, Is.EqualTo("RestLength"));
            Assert.That(e.Message, Does.StartWith("RestLength must be in [0.01, 10000] m."));
            e = Assert.Throws<ArgumentOutOfRangeException>(() => RopeParameters.Check(0, RopeParameters.SegmentCount.Row));
            Assert.That(e.Message, Does.StartWith("SegmentCount must be in [1, 10000]."));
            e = Assert.Throws<ArgumentOutOfRangeException>(() => RopeParameters.Check(0f, RopeParameters.Radius.Row));
            Assert.That(e.Message, Does.StartWith("Radius must be in (0, 1] m."));
        }

        [Test]
        public void ClampBringsValuesIntoTheRangeAndSaysWhat()
        {
            float length = 20000f;
            string message = RopeParameters.Clamp(ref length, RopeParameters.RestLength.Row);
            Assert.That(length, Is.EqualTo(RopeParameters.RestLength.Max));
            Assert.That(message, Is.EqualTo("Rest length = 20000 m is outside [0.01, 10000] m; clamped to 10000 m."));

            float nan = float.NaN;
            Assert.That(RopeParameters.Clamp(ref nan, RopeParameters.PoissonRatio.Row), Does.Contain("Poisson ratio"));
            Assert.That(nan, Is.EqualTo(RopeParameters.PoissonRatio.Default));

            float low = -1f;
            Assert.That(RopeParameters.Clamp(ref low, RopeParameters.Damping.Row), Does.Contain("[0, 10] s"));
            Assert.That(low, Is.EqualTo(0f));

            float zero = 0f;
            Assert.That(RopeParameters.Clamp(ref zero, RopeParameters.Radius.Row), Does.Contain("(0, 1] m"));
            Assert.That(zero, Is.EqualTo(RopeParameters.Radius.Default), "an exclusive minimum clamps to the default");

            float infinite = float.PositiveInfinity;
            RopeParameters.Clamp(ref infinite, RopeParameters.YoungsModulus.Row);
            Assert.That(infinite, Is.EqualTo(RopeParameters.YoungsModulus.Max), "the inspector range stays finite");

            float inside = 0.5f;
            Assert.That(RopeParameters.Clamp(ref inside, RopeParameters.DefectPosition.Row), Is.Null);
            // issue 17: the defect lies strictly inside the rope, (0, 1); either end resets to the middle
            float atEnd = 1f, atStart = 0f;
            Assert.That(RopeParameters.Clamp(ref atEnd, RopeParameters.DefectPosition.Row), Is.EqualTo("Defect position = 1 is outside (0, 1); clamped to 0.5."));
            Assert.That(RopeParameters.Clamp(ref atStart, RopeParameters.DefectPosition.Row), Is.EqualTo("Defect position = 0 is outside (0, 1); clamped to 0.5."));
            Assert.That(atEnd, Is.EqualTo(0.5f));
            var defect = Assert.Throws<ArgumentOutOfRangeException>(() => new HookeRope.Radius.RadiusSettings { DefectPosition = 1f });
            Assert.That(defect.ParamName, Is.EqualTo("DefectPosition"));
            Assert.That(defect.Message, Does.Contain("DefectPosition must be in (0, 1)."));
            Assert.Throws<ArgumentOutOfRangeException>(() => new HookeRope.Radius.RadiusSettings { DefectPosition = 0f });
            Assert.That(new HookeRope.Radius.RadiusSettings { DefectPosition = 0.999f }.DefectPosition, Is.EqualTo(0.999f));

            int segments = 0;
            Assert.That(RopeParameters.Clamp(ref segments, RopeParameters.SegmentCount.Row), Is.EqualTo("Segment count = 0 is outside [1, 10000]; clamped to 1."));
            Assert.That(segments, Is.EqualTo(1));
        }

        /// <summary>Every (fresh settings instance, property, row) where a core settings class has a property named like a row.</summary>
        static IEnumerable<(object Settings, PropertyInfo Property, ParameterInfo Row)> CoreProperties()
        {
            foreach (var type in new[] { typeof(HookeRope.Solver.RopeSettings), typeof(HookeRope.Radius.RadiusSettings), typeof(HookeRope.Geometry.TubeMeshSettings) })
                foreach (var row in RopeParameters.All)
                {
                    var property = type.GetProperty(row.Name, BindingFlags.Public | BindingFlags.Instance);
                    if (property != null) yield return (Activator.CreateInstance(type), property, row);
                }
        }

        [Test]
        public void CoreSettersAcceptTheTableRangeAndNameItOutside()
        {
            int checkedRows = 0;
            foreach (var (settings, property, row) in CoreProperties())
            {
                if (!property.CanWrite || IsDerived(row)) continue;
                if (row.Kind == ParameterKind.Float && property.PropertyType == typeof(float))
                {
                    float low = row.MinExclusive ? NextUp((float)row.Min) : (float)row.Min;
                    property.SetValue(settings, low);
                    Assert.That(property.GetValue(settings), Is.EqualTo(low), row.Name);
                    property.SetValue(settings, row.MaxExclusive ? NextDown((float)row.Max) : (float)row.Max);
                    AssertSetterThrows(settings, property, row.MinExclusive ? (float)row.Min : NextDown((float)row.Min), row);
                    AssertSetterThrows(settings, property, row.MaxExclusive ? (float)row.Max : NextUp((float)row.Max), row);
                    checkedRows++;
                }
                else if (row.Kind == ParameterKind.Int && property.PropertyType == typeof(int))
                {
                    property.SetValue(settings, (int)row.Min);
                    property.SetValue(settings, (int)row.Max);
                    AssertSetterThrows(settings, property, (int)row.Min - 1, row);
                    AssertSetterThrows(settings, property, (int)row.Max + 1, row);
                    checkedRows++;
                }
            }
            Assert.That(checkedRows, Is.EqualTo(29), "RopeSettings: L, n, R, E, ρ, β, substeps, iterations, yield, hardening, necking and ultimate strains, absorber force and deployment, c, C_d, C_f, ρ_air; RadiusSettings: ν, r_min, defect, zone, growth, break strain, break radius; TubeMeshSettings: radial, ring tolerance, rings, v per metre");
        }

        [Test]
        public void FreshCoreSettingsReadTheTableDefaults()
        {
            int checkedRows = 0;
            foreach (var (settings, property, row) in CoreProperties())
            {
                if (row.Kind == ParameterKind.Vector) continue;
                object value = property.GetValue(settings);
                double actual = value is bool b ? (b ? 1 : 0) : value is Enum ? Convert.ToInt32(value) : Convert.ToDouble(value);
                // E·A and μ follow from E, ρ and R; the table stores them rounded to the component's field values.
                Assert.That(actual, IsDerived(row) ? Is.EqualTo(row.Default).Within(1e-3).Percent : Is.EqualTo(row.Default), settings.GetType().Name + "." + row.Name);
                checkedRows++;
            }
            Assert.That(checkedRows, Is.EqualTo(43), "RopeSettings 25 rows (gravity and wind are vectors; 8 of the material law and 4 of the drag, issue 15; the Gauss–Seidel kernel, issue 18), RadiusSettings 12, TubeMeshSettings 6 (the ring tolerance, issue 18)");
        }

        static bool IsDerived(ParameterInfo row) => row == RopeParameters.AxialStiffness.Row || row == RopeParameters.LinearDensity.Row;

        static void AssertSetterThrows(object settings, PropertyInfo property, object value, ParameterInfo row)
        {
            var e = Assert.Throws<TargetInvocationException>(() => property.SetValue(settings, value), row.Name + " = " + value);
            Assert.That(e.InnerException, Is.TypeOf<ArgumentOutOfRangeException>(), row.Name);
            Assert.That(e.InnerException.Message, Does.Contain(row.Name).And.Contain(row.RangeText), row.Name);
        }

        static void AssertThrowsNaming(TestDelegate call, ParameterInfo row)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(call, row.Name);
            Assert.That(e.ParamName, Is.EqualTo(row.Name));
            Assert.That(e.Message, Does.Contain(row.Name).And.Contain(row.RangeText), row.Name);
            if (row.Unit.Length > 0) Assert.That(e.Message, Does.Contain(row.Unit), row.Name);
        }

        static float NextUp(float x) => x == 0f ? float.Epsilon : BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(x) + (x > 0f ? 1 : -1));

        static float NextDown(float x) => x == 0f ? -float.Epsilon : BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(x) + (x > 0f ? -1 : 1));
    }
}
