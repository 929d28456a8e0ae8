using System.Globalization;
using NUnit.Framework;
using HookeRope.Editor;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): the rows the inspector's Read-outs section draws for a
    /// multi-selection (<see cref="RopeReadoutTable"/>) hold one value per selected rope, in selection order, equal to
    /// that rope's read-outs; an unbuilt rope reads "not built". Two hanging ropes of different lengths: the top tension
    /// of a 24-segment rope pinned at its top is μ·g·L less the pinned particle's half segment, μ·g·L·(1 − 1/48).
    /// </summary>
    [TestFixture]
    public sealed class RopeReadoutTableTests
    {
        const float G = 9.81f;
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        ElasticRope Hanging(string name, float x, float length)
        {
            var rope = _scene.Rope(name, new Vector3(x, 5f, 0f));
            rope.RestLength = length;
            rope.StartAttachment.Point = _scene.Point(name + " Anchor", new Vector3(x, 5f, 0f));
            rope.Rebuild();
            UnityRopeScene.Run(rope, 400, 0.02f);
            return rope;
        }

        static float Number(string text) => float.Parse(text.Split(' ')[0], CultureInfo.InvariantCulture);

        [Test]
        public void EachSelectedRopeGetsItsOwnColumn()
        {
            var shortRope = Hanging("Short", 0f, 1f);
            var longRope = Hanging("Long", 2f, 3f);
            var unbuilt = _scene.Rope("Unbuilt", new Vector3(4f, 5f, 0f));

            var rows = RopeReadoutTable.Build(new[] { shortRope, longRope, unbuilt });
            Assert.That(rows.Count, Is.EqualTo(RopeReadoutTable.RowCount));
            Assert.That(rows.Count, Is.EqualTo(13));
            Assert.That(rows[0].Label, Is.EqualTo(RopeReadoutTable.NameLabel));
            Assert.That(rows[0].Values, Is.EqualTo(new[] { "Short", "Long", "Unbuilt" }));
            foreach (var row in rows)
            {
                Assert.That(row.Values.Count, Is.EqualTo(3), row.Label);
                if (row.Label != RopeReadoutTable.NameLabel) Assert.That(row.Values[2], Is.EqualTo(RopeReadoutTable.NotBuilt), row.Label);
            }

            var tension = Row(rows, "Top / bottom tension");
            for (int i = 0; i < 2; i++)
            {
                var rope = i == 0 ? shortRope : longRope;
                float top = Number(tension.Values[i].Split('/')[0].Trim());
                Assert.That(top, Is.EqualTo(rope.TopTension).Within(5e-4f * rope.TopTension), "the cell is that rope's value (4 digits)");
                float expected = rope.LinearDensity * G * rope.RestLength * (1f - 1f / 48f);
                Assert.That(top, Is.EqualTo(expected).Within(0.01f * expected), rope.name + " top tension μ·g·L·(1 − 1/48)");
            }
            Assert.That(Number(Row(rows, "Top / bottom tension").Values[1]) / Number(Row(rows, "Top / bottom tension").Values[0]),
                Is.EqualTo(3f).Within(0.03f), "three times the length, three times the top tension");
            Assert.That(Row(rows, "Broken").Values, Is.EqualTo(new[] { "no", "no", RopeReadoutTable.NotBuilt }));
            Assert.That(Row(rows, "EN 355 (6 kN)").Values[0], Is.EqualTo("within limit"));
            Assert.That(Row(rows, "Peak tension").Joined, Does.Contain(" | "));
        }

        [Test]
        public void OneRopeGivesOneValuePerRowAndDestroyedTargetsAreSkipped()
        {
            var rope = Hanging("Only", 0f, 2f);
            var gone = _scene.Rope("Gone", Vector3.zero);
            Object.DestroyImmediate(gone.gameObject);
            var rows = RopeReadoutTable.Build(new[] { rope, gone });
            foreach (var row in rows) Assert.That(row.Values.Count, Is.EqualTo(1), row.Label);
            Assert.That(Row(rows, "Peak tension").Values[0], Is.EqualTo(RopeReadoutTable.Format(rope.PeakTension, "N")));
            Assert.That(RopeReadoutTable.Format(1234.567f, "N"), Is.EqualTo("1235 N"));
            Assert.That(RopeReadoutTable.Format(0.001234567f, ""), Is.EqualTo("0.001235"));
        }

        static ReadoutRow Row(System.Collections.Generic.IReadOnlyList<ReadoutRow> rows, string label)
        {
            foreach (var row in rows)
                if (row.Label == label) return row;
            Assert.Fail("no row " + label);
            return null;
        }
    }
}
