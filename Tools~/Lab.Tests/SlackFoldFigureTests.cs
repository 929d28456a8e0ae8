using System;
using System.IO;
using HookeRope.Geometry;
using HookeRope.Lab.Commands;
using HookeRope.Lab.Figures;
using HookeRope.Lab.Figures.Diagnostics;
using NUnit.Framework;
using SkiaSharp;

namespace HookeRope.Lab.Tests
{
    /// <summary>
    /// The diagnostic picture of slack folds after a break (issue 17: since the fold repair, 0 inverted at every step) and the winding census it
    /// counts with: the census on hand-made triangles, the figure's panels and numbers.
    /// </summary>
    [TestFixture]
    public sealed class SlackFoldFigureTests : TempFolderTest
    {
        static TubeVertex Vertex(float x, float y, float z, float nz) => new TubeVertex { PX = x, PY = y, PZ = z, NZ = nz };

        [Test]
        public void CensusCountsTrianglesWoundAgainstTheirNormalsAndTheirArea()
        {
            // three triangles in z = 0 with normals +z: (0,0)-(1,0)-(0,1) wound along +z, (0,0)-(0,2)-(2,0) wound along
            // −z (inverted, area 2), and a degenerate one (no area: never inverted)
            var vertices = new[]
            {
                Vertex(0, 0, 0, 1), Vertex(1, 0, 0, 1), Vertex(0, 1, 0, 1),
                Vertex(0, 0, 0, 1), Vertex(0, 2, 0, 1), Vertex(2, 0, 0, 1),
                Vertex(0, 0, 0, 1), Vertex(1, 1, 0, 1), Vertex(2, 2, 0, 1),
            };
            var indices = new[] { 0, 1, 2, 3, 4, 5, 6, 7, 8 };
            var census = WindingCensus.Of(vertices, indices, 0, 9);
            Assert.That(census.Triangles, Is.EqualTo(3));
            Assert.That(census.Inverted, Is.EqualTo(1));
            Assert.That(census.InvertedArea, Is.EqualTo(2.0).Within(1e-12));
            Assert.That(census.LeastCosine, Is.EqualTo(-1.0).Within(1e-12));
            var front = WindingCensus.Of(vertices, indices, 0, 3);
            Assert.That(front.Inverted, Is.EqualTo(0));
            Assert.That(front.LeastCosine, Is.EqualTo(1.0).Within(1e-12));
            Assert.Throws<ArgumentOutOfRangeException>(() => WindingCensus.Of(vertices, indices, 3, 9));
            Assert.Throws<ArgumentOutOfRangeException>(() => WindingCensus.Of(vertices, indices, 0, 4));
        }

        [Test]
        public void TheFigureDrawsEveryPanelAndCountsEveryStepWithCleanEndsAtTheBreakAndTenStepsOn()
        {
            var figure = SlackFoldFigure.Build(0.5f);
            Assert.That(figure.Panels.Count, Is.EqualTo(2 * SlackFoldFigure.Steps.Length));
            foreach (var panel in figure.Panels)
                Assert.That(panel.Scene.RopeTriangleCount, Is.GreaterThan(500), panel.Caption + ": the tube is in the panel");
            for (int row = 0; row < 2; row++)
            {
                for (int step = 0; step <= SlackFoldFigure.CensusSteps; step++)
                {
                    Assert.That(figure.Numbers.ContainsKey($"row {row} step {step} inverted"), Is.True, $"row {row} step {step}");
                    // issue 17: the folds close into cones, no triangle wound against its normals at any step
                    Assert.That(figure.Numbers[$"row {row} step {step} inverted"], Is.EqualTo(0), $"row {row} step {step}");
                }
                // the states the mesh tests draw: the step of the break, and the pieces straight again 10 steps on
                Assert.That(figure.Numbers[$"row {row} step 0 inverted"], Is.EqualTo(0), $"row {row}: at the break");
                Assert.That(figure.Numbers[$"row {row} step 10 inverted"], Is.EqualTo(0), $"row {row}: 10 steps on");
                Assert.That(figure.Numbers[$"row {row} step 10 shortest segment / rest"], Is.GreaterThan(0.9), $"row {row}: straight again");
            }
            var stats = FigureWriter.Write(figure, Path.Combine(dir, SlackFoldFigure.FileName));
            using (var bitmap = SKBitmap.Decode(stats.Path))
                Assert.That(bitmap.Width, Is.EqualTo(figure.View.Width));
            string inverted = "";
            for (int step = 0; step <= SlackFoldFigure.CensusSteps; step++)
                inverted += figure.Numbers[$"row 0 step {step} inverted"] + "/" + figure.Numbers[$"row 1 step {step} inverted"] + " ";
            TestContext.WriteLine("inverted tube triangles per step after the break (no gravity / gravity): " + inverted);
        }

        [Test]
        public void TheFoldsSetWritesOnlyItsFigure()
        {
            var output = new StringWriter();
            int code = LabCli.Invoke(new[] { "figures", "folds", "--out", dir }, LabConsole.Plain(output), output, output);
            Assert.That(code, Is.EqualTo(0), output.ToString());
            Assert.That(Directory.GetFiles(dir), Has.Length.EqualTo(1));
            Assert.That(File.Exists(Path.Combine(dir, SlackFoldFigure.FileName)), Is.True);
        }
    }
}
