using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): the inspector agrees with the parameter table
    /// <see cref="RopeParameters"/>. For every serialized field m_&lt;Name&gt; of <see cref="ElasticRope"/> and
    /// <see cref="RopeMeshRenderer"/> that has a row (and every inspector row has such a field), the [Tooltip] and [Range]
    /// arguments (read as attribute data) equal the row, a fresh component holds the row's default, OnValidate clamps
    /// 10·Max to Max and NaN to the default, and the property setter rejects a value above Max naming the range and unit.
    /// </summary>
    [TestFixture]
    public sealed class InspectorParameterTableTests
    {
        /// <summary>Rows whose serialized field keeps its 0.1.0 name (no serialized rename this release).</summary>
        static readonly Dictionary<string, string> s_FieldNames = new Dictionary<string, string> { { "PoissonThinning", "m_RadiusModel" } };

        static readonly Type[] s_Components = { typeof(ElasticRope), typeof(RopeMeshRenderer) };

        const BindingFlags Instance = BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic;

        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        static string FieldName(ParameterInfo row) => s_FieldNames.TryGetValue(row.Name, out var name) ? name : "m_" + row.Name;

        static IEnumerable<ParameterInfo> InspectorRows => RopeParameters.All.Where(r => r.InInspector);

        static IEnumerable<ParameterInfo> ClampedRows =>
            InspectorRows.Where(r => r.Kind == ParameterKind.Float || r.Kind == ParameterKind.Int);

        static FieldInfo Field(ParameterInfo row, out Type component)
        {
            foreach (var type in s_Components)
            {
                var field = type.GetField(FieldName(row), Instance);
                if (field != null)
                {
                    component = type;
                    return field;
                }
            }
            component = null;
            return null;
        }

        static IEnumerable<FieldInfo> SerializedFields(Type type) =>
            type.GetFields(Instance).Where(f => f.IsPublic || f.GetCustomAttributesData().Any(a => a.AttributeType == typeof(SerializeField)));

        Component Fresh(Type type)
        {
            var go = _scene.Track(new GameObject("Probe", typeof(MeshFilter), typeof(MeshRenderer)));
            return go.AddComponent(type);
        }

        static double Number(object value) =>
            value is bool b ? (b ? 1 : 0) : value is Enum ? Convert.ToInt32(value) : Convert.ToDouble(value);

        [Test]
        public void EveryInspectorRowHasASerializedField()
        {
            foreach (var row in InspectorRows)
                Assert.That(Field(row, out _), Is.Not.Null, row.Name + ": no serialized field " + FieldName(row));
        }

        [Test]
        public void EveryFieldNamedAfterARowIsInTheInspector()
        {
            foreach (var type in s_Components)
            foreach (var field in SerializedFields(type))
            {
                var row = RopeParameters.All.FirstOrDefault(r => FieldName(r) == field.Name);
                if (row != null) Assert.That(row.InInspector, Is.True, type.Name + "." + field.Name + " has a row that is not marked InInspector");
            }
        }

        [TestCaseSource(nameof(InspectorRowNames))]
        public void TooltipAndRangeAreTheRows(string name)
        {
            var row = RopeParameters.Find(name);
            var field = Field(row, out _);
            var data = field.GetCustomAttributesData();

            var tooltip = data.SingleOrDefault(a => a.AttributeType == typeof(TooltipAttribute));
            Assert.That(tooltip, Is.Not.Null, name + " has no [Tooltip]");
            Assert.That(tooltip.ConstructorArguments[0].Value, Is.EqualTo(row.Tooltip), name + " tooltip");

            var range = data.SingleOrDefault(a => a.AttributeType == typeof(UnityEngine.RangeAttribute));
            if (range == null) return;
            Assert.That(Convert.ToDouble(range.ConstructorArguments[0].Value), Is.EqualTo((double)(float)row.Min), name + " slider minimum");
            Assert.That(Convert.ToDouble(range.ConstructorArguments[1].Value), Is.EqualTo((double)(float)row.Max), name + " slider maximum");
        }

        [TestCaseSource(nameof(InspectorRowNames))]
        public void FreshComponentHoldsTheDefault(string name)
        {
            var row = RopeParameters.Find(name);
            var field = Field(row, out var type);
            object value = field.GetValue(Fresh(type));
            switch (row.Kind)
            {
                case ParameterKind.Vector:
                {
                    var v = (Vector3)value;
                    Assert.That(new[] { v.x, v.y, v.z }, Is.EqualTo(row.DefaultComponents), name);
                    break;
                }
                case ParameterKind.Color:
                {
                    var c = (Color)value;
                    Assert.That(new[] { c.r, c.g, c.b, c.a }, Is.EqualTo(row.DefaultComponents), name);
                    break;
                }
                case ParameterKind.Float:
                    Assert.That((float)value, Is.EqualTo((float)row.Default), name);
                    break;
                default:
                    Assert.That(Number(value), Is.EqualTo(row.Default), name);
                    break;
            }
        }

        [TestCaseSource(nameof(ClampedRowNames))]
        public void OnValidateClampsAboveMaxAndResetsNaN(string name)
        {
            var row = RopeParameters.Find(name);
            var field = Field(row, out var type);
            var component = Fresh(type);
            var so = new SerializedObject(component);
            // E·A is kept only when it is the stiffness input; otherwise OnValidate derives it from E.
            if (row.Name == RopeParameters.AxialStiffness.Name) so.FindProperty("m_StiffnessInput").intValue = 1;
            var property = so.FindProperty(field.Name);
            if (row.Kind == ParameterKind.Int) property.intValue = (int)Math.Min(10.0 * row.Max, int.MaxValue);
            else property.floatValue = 10f * (float)row.Max;
            so.ApplyModifiedPropertiesWithoutUndo();
            // an exclusive maximum (the defect position's open (0, 1)) resets to the default, like an exclusive minimum
            double clamped = row.MaxExclusive ? row.Default : row.Max;
            Assert.That(Number(field.GetValue(component)), Is.EqualTo(row.Kind == ParameterKind.Int ? clamped : (float)clamped), name + ": 10·Max → Max (exclusive: Default)");

            if (row.Kind != ParameterKind.Float) return;
            so.Update();
            so.FindProperty(field.Name).floatValue = float.NaN;
            so.ApplyModifiedPropertiesWithoutUndo();
            Assert.That((float)field.GetValue(component), Is.EqualTo((float)row.Default), name + ": NaN → Default");
        }

        [TestCaseSource(nameof(ClampedRowNames))]
        public void SetterRejectsAboveMaxNamingTheRangeAndUnit(string name)
        {
            var row = RopeParameters.Find(name);
            Field(row, out var type);
            var property = type.GetProperty(row.Name, BindingFlags.Instance | BindingFlags.Public);
            Assert.That(property, Is.Not.Null, name + ": no public property");
            object above = row.Kind == ParameterKind.Int ? (object)(int)Math.Min(10.0 * row.Max, int.MaxValue) : 10f * (float)row.Max;
            var component = Fresh(type);
            var e = Assert.Throws<TargetInvocationException>(() => property.SetValue(component, above));
            Assert.That(e.InnerException, Is.InstanceOf<ArgumentOutOfRangeException>(), name);
            Assert.That(e.InnerException.Message, Does.Contain(row.Name).And.Contain(row.RangeText), name);
            if (row.Unit.Length > 0) Assert.That(e.InnerException.Message, Does.Contain(row.Unit), name);
        }

        [Test]
        public void GravitySetterAndOnValidateUseTheRowsComponentRange()
        {
            var row = RopeParameters.Gravity.Row;
            var rope = (ElasticRope)Fresh(typeof(ElasticRope));
            Assert.Throws<ArgumentOutOfRangeException>(() => rope.Gravity = new Vector3(0f, 10f * (float)row.Max, 0f));
            var so = new SerializedObject(rope);
            so.FindProperty("m_Gravity").vector3Value = new Vector3(10f * (float)row.Max, 10f * (float)row.Min, 0f);
            so.ApplyModifiedPropertiesWithoutUndo();
            Assert.That(rope.Gravity, Is.EqualTo(new Vector3((float)row.Max, (float)row.Min, 0f)));
        }

        [Test]
        public void WindSetterAndOnValidateUseTheRowsComponentRangeAndResetNaN()
        {
            var row = RopeParameters.Wind.Row;
            var rope = (ElasticRope)Fresh(typeof(ElasticRope));
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => rope.Wind = new Vector3(0f, 0f, 10f * (float)row.Max));
            Assert.That(e.ParamName, Is.EqualTo("Wind"));
            Assert.That(e.Message, Does.Contain(row.RangeText));
            var so = new SerializedObject(rope);
            so.FindProperty("m_Wind").vector3Value = new Vector3(10f * (float)row.Max, 10f * (float)row.Min, 3f);
            so.ApplyModifiedPropertiesWithoutUndo();
            Assert.That(rope.Wind, Is.EqualTo(new Vector3((float)row.Max, (float)row.Min, 3f)));
            so.Update();
            so.FindProperty("m_Wind").vector3Value = new Vector3(float.NaN, 1f, 0f);
            so.ApplyModifiedPropertiesWithoutUndo();
            Assert.That(rope.Wind, Is.EqualTo(Vector3.zero), "a non-finite wind resets to calm");
        }

        /// <summary>
        /// Every numeric serialized field (float, int, Vector3) of both components carries Unity's [Min] or [Range], so
        /// the Inspector clamps a typed value quietly; the attribute's arguments are the row's Min (and Max) constants.
        /// A Min-only field keeps OnValidate's clamp with a warning for values above Max.
        /// </summary>
        [Test]
        public void EveryNumericSerializedFieldHasMinOrRangeFromTheTable()
        {
            int checkedFields = 0;
            foreach (var type in s_Components)
            foreach (var field in SerializedFields(type).Where(f => f.FieldType == typeof(float) || f.FieldType == typeof(int) || f.FieldType == typeof(Vector3)))
            {
                string where = type.Name + "." + field.Name;
                var row = RopeParameters.All.FirstOrDefault(r => FieldName(r) == field.Name);
                Assert.That(row, Is.Not.Null, where + " is numeric but has no row in RopeParameters");
                var data = field.GetCustomAttributesData();
                var range = data.SingleOrDefault(a => a.AttributeType == typeof(UnityEngine.RangeAttribute));
                var min = data.SingleOrDefault(a => a.AttributeType == typeof(MinAttribute));
                Assert.That(range == null ^ min == null, Is.True, where + " needs exactly one of [Min] and [Range]");
                var lower = (range ?? min).ConstructorArguments[0].Value;
                Assert.That(Convert.ToDouble(lower), Is.EqualTo((double)(float)row.Min), where + " minimum");
                if (range != null)
                    Assert.That(Convert.ToDouble(range.ConstructorArguments[1].Value), Is.EqualTo((double)(float)row.Max), where + " maximum");
                checkedFields++;
            }
            Assert.That(checkedFields, Is.EqualTo(31), "numeric serialized fields of ElasticRope (28: 6 of the material law and 5 of the drag, issue 15) and RopeMeshRenderer (3: radial segments, ring tolerance, detail distance)");
        }

        static IEnumerable<string> InspectorRowNames() => InspectorRows.Select(r => r.Name);

        static IEnumerable<string> ClampedRowNames() => ClampedRows.Select(r => r.Name);
    }
}
