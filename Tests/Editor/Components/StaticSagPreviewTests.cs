using System;
using NUnit.Framework;
using HookeRope.Editor;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): the inspector's static-sag preview of a nearly inextensible rope between two anchors
    /// at the same height matches the catenary y = a·cosh(x/a) with 2·a·sinh(D/(2a)) = L.
    /// </summary>
    [TestFixture]
    public sealed class StaticSagPreviewTests
    {
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        static double CatenarySag(double length, double span)
        {
            // Solve 2·a·sinh(span/(2a)) = length for a by bisection on x = span/(2a): sinh(x)/x = length/span.
            double target = length / span, lo = 1e-9, hi = 20.0;
            for (int i = 0; i < 200; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (Math.Sinh(mid) / mid < target) lo = mid; else hi = mid;
            }
            double x = 0.5 * (lo + hi), a = span / (2.0 * x);
            return a * (Math.Cosh(x) - 1.0);
        }

        [Test]
        public void PreviewMatchesTheCatenary()
        {
            const float length = 2f, span = 1.6f;
            var left = _scene.Point("Left", new Vector3(-0.5f * span, 2f, 0f));
            var right = _scene.Point("Right", new Vector3(0.5f * span, 2f, 0f));
            var rope = _scene.Rope("Rope", left.position);
            rope.RestLength = length;
            rope.SegmentCount = 48;
            rope.AxialStiffness = 1e6f;
            rope.Substeps = 4;
            rope.StartAttachment.Point = left;
            rope.EndAttachment.Point = right;

            var preview = StaticSagPreview.Compute(rope, 10f);

            Assert.That(rope.IsBuilt, Is.False, "the preview does not build the rope itself");
            Assert.That(preview.Length, Is.EqualTo(49));
            float sag = 2f - preview[24].y;
            Assert.That(sag, Is.EqualTo((float)CatenarySag(length, span)).Within(0.03f * (float)CatenarySag(length, span)));
            Assert.That(preview[0].x, Is.EqualTo(-0.5f * span).Within(1e-4f));
            Assert.That(preview[48].x, Is.EqualTo(0.5f * span).Within(1e-4f));
            Assert.That(StaticSagPreview.Get(rope), Is.SameAs(preview), "the gizmo draws the last preview");
        }
    }
}
