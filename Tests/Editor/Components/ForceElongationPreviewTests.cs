using HookeRope.Editor;
using HookeRope.Solver;
using NUnit.Framework;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in), issue 15 item 5: the geometry of the inspector's
    /// force–elongation preview. The stand-in cannot draw IMGUI, so the curve's points in the preview rectangle and the
    /// caption are what is tested; the drawing call only passes them to Handles.DrawAAPolyLine.
    /// </summary>
    [TestFixture]
    public sealed class ForceElongationPreviewTests
    {
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        const float X = 20f, Y = 300f, W = 400f, H = ForceElongationPreview.Height;

        [Test]
        public void PlasticRopeCurveRisesPeaksAtTheNeckOnsetAndFallsToTheBreakInsideTheRectangle()
        {
            var rope = _scene.Rope("Rope", Vector3.zero);
            rope.SegmentCount = 20;
            rope.AxialStiffness = 1e7f;
            rope.SetPlasticity(0.002f, 1e5f, 0.15f, 0.35f);
            var curve = rope.ForceElongationCurve();
            var p = ForceElongationPreview.Points(curve, X, Y, W, H);
            Assert.That(p.Length, Is.EqualTo(curve.Count));
            Assert.That(p[0], Is.EqualTo(new Vector3(X, Y + H, 0f)), "(0 m, 0 N) at the bottom-left corner");
            foreach (var q in p)
            {
                Assert.That(q.x, Is.InRange(X, X + W));
                Assert.That(q.y, Is.InRange(Y, Y + H));
            }
            for (int i = 1; i < p.Length; i++) Assert.That(p[i].x, Is.GreaterThanOrEqualTo(p[i - 1].x), "elongation grows to the right");
            // the neck onset is the highest point, at (1 − headroom) of the height; the break returns to the axis
            Assert.That(p[2].y, Is.EqualTo(Y + H * ForceElongationPreview.Headroom).Within(1e-3f));
            Assert.That(p[p.Length - 1].y, Is.EqualTo(Y + H).Within(1e-3f));
            Assert.That(p[p.Length - 1].x, Is.EqualTo(X + W * (1f - ForceElongationPreview.Headroom)).Within(1e-3f), "the break is the longest elongation");
            // the yield point's height against the onset's: E·A·ε_y / F_n
            double onset = (0.15 - 0.002) / (1 + 1e5 / 1e7), fn = 2e4 + 1e5 * onset;
            Assert.That((Y + H - p[1].y) / (Y + H - p[2].y), Is.EqualTo(2e4 / fn).Within(1e-4));
            string caption = ForceElongationPreview.Caption(curve);
            TestContext.WriteLine(caption);
            Assert.That(caption, Does.StartWith("peak 34.65 kN at 0.3 m; breaks at"), "the default 2 m rope at the necking strain 0.15");
        }

        [Test]
        public void AbsorberCurveShowsAFlatPlateauOverTheDeploymentLength()
        {
            var rope = _scene.Rope("Rope", Vector3.zero);
            rope.AxialStiffness = 1e5f;
            rope.UseEnergyAbsorber(4000f, 1.75f);
            var curve = rope.ForceElongationCurve();
            var p = ForceElongationPreview.Points(curve, X, Y, W, H);
            ForceElongationPreview.Scale(curve, out double elongation, out double force);
            Assert.That(p[2].y, Is.EqualTo(p[1].y).Within(1e-4f), "the plateau is flat");
            Assert.That((p[2].x - p[1].x) / W * elongation, Is.EqualTo(1.75).Within(1e-4), "over the deployment length (m)");
            Assert.That((Y + H - p[1].y) / H * force, Is.EqualTo(4000).Within(0.01), "at the plateau force (N)");
            Assert.That(ForceElongationPreview.Caption(curve), Does.Contain("elastic end at"));
        }

        [Test]
        public void ElasticRopeIsAStraightLineToTheBreakStrain()
        {
            var rope = _scene.Rope("Rope", Vector3.zero);
            rope.RestLength = 2f;
            rope.AxialStiffness = 5000f;
            rope.BreakStrain = 0.6f;
            var curve = rope.ForceElongationCurve();
            Assert.That(curve.Count, Is.EqualTo(2));
            Assert.That(curve.Elongation[1], Is.EqualTo(1.2).Within(1e-6));
            Assert.That(curve.Force[1], Is.EqualTo(3000).Within(1e-3));
        }
    }
}
