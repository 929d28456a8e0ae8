using System;
using System.Linq;
using System.Text.RegularExpressions;
using HookeRope.Radius;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): the Neck Mode drop-down offers exactly the values the
    /// validation accepts. The Inspector's enum popup lists the enum's named members (SerializedProperty.enumNames); the
    /// rejected value 0 (the former "Off", deleted in 0.1.x: necking is switched with the Necking toggle) has no name,
    /// so it cannot be picked, and a 0 still stored in an old scene is reset to Zone with a warning.
    /// </summary>
    [TestFixture]
    public sealed class NeckModePopupTests
    {
        UnityRopeScene _scene;
        ElasticRope _rope;

        [SetUp]
        public void SetUp()
        {
            _scene = new UnityRopeScene();
            _scene.Begin();
            _rope = _scene.Track(new GameObject("Rope", typeof(MeshFilter), typeof(MeshRenderer))).AddComponent<ElasticRope>();
        }

        [TearDown] public void TearDown() => _scene.End();

        static ParameterInfo Row => RopeParameters.NeckMode.Row;

        [Test]
        public void PopupNamesAreExactlyTheAcceptedValues()
        {
            var property = new SerializedObject(_rope).FindProperty("m_NeckMode");
            Assert.That(property.enumNames, Is.EqualTo(new[] { "Paper", "Zone" }));

            var accepted = Enumerable.Range((int)Row.Min, (int)(Row.Max - Row.Min) + 1).Where(v => RopeParameters.Contains(Row, v)).ToArray();
            var named = ((NeckMode[])Enum.GetValues(typeof(NeckMode))).Select(m => (int)m).ToArray();
            Assert.That(named, Is.EqualTo(accepted), "every popup entry is accepted and every accepted value has an entry");
            Assert.That(RopeParameters.Contains(Row, 0), Is.False, "0 (the former Off) is rejected");
        }

        [TestCase(0, NeckMode.Paper)]
        [TestCase(1, NeckMode.Zone)]
        public void PickingEachEntryKeepsItWithoutWarning(int index, NeckMode expected)
        {
            var so = new SerializedObject(_rope);
            so.FindProperty("m_NeckMode").enumValueIndex = index;
            so.ApplyModifiedPropertiesWithoutUndo();
            Assert.That(_rope.NeckMode, Is.EqualTo(expected));
            LogAssert.NoUnexpectedReceived();
        }

        [Test]
        public void StoredZeroFromAnOldSceneIsResetToZoneWithAWarning()
        {
            var so = new SerializedObject(_rope);
            so.FindProperty("m_NeckMode").intValue = 0;
            LogAssert.Expect(LogType.Warning, new Regex("Neck mode must be Zone or Paper; set to Zone"));
            so.ApplyModifiedPropertiesWithoutUndo();
            Assert.That(_rope.NeckMode, Is.EqualTo(NeckMode.Zone));
            Assert.That((int)_rope.NeckMode, Is.EqualTo(2));
        }
    }
}
