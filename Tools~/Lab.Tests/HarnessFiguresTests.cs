using System.IO;
using HookeRope.Lab.Commands;
using HookeRope.Lab.Figures;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using HookeRope.Mathematics;
using NUnit.Framework;
using SkiaSharp;

namespace HookeRope.Lab.Tests
{
    /// <summary>The manual's harness-rig figures: files, sizes, and the rendered rope against the projected core mesh.</summary>
    [TestFixture]
    public sealed class HarnessFiguresTests : TempFolderTest
    {
        /// <summary>Committed figures must stay small (bytes).</summary>
        const long MaxBytes = 150 * 1024;

        [Test]
        public void FiguresCommandWritesThreeNonEmptyPngsOfTheFigureSize()
        {
            var output = new StringWriter();
            int code = FiguresCommand.Execute(LabConsole.Plain(output), dir);
            Assert.That(code, Is.EqualTo(0));
            foreach (var name in HarnessRigFigures.FileNames)
            {
                var path = Path.Combine(dir, name);
                Assert.That(File.Exists(path), Is.True, name);
                long bytes = new FileInfo(path).Length;
                Assert.That(bytes, Is.InRange(10 * 1024, MaxBytes), name + ": PNG size in bytes");
                using (var bitmap = SKBitmap.Decode(path))
                {
                    Assert.That(bitmap, Is.Not.Null, name);
                    Assert.That(bitmap.Width, Is.EqualTo(HarnessRigFigures.Width), name);
                    Assert.That(bitmap.Height, Is.EqualTo(HarnessRigFigures.Height), name);
                    // not blank: the rope's orange is in the picture
                    Assert.That(RopeColouredPixels(bitmap, null), Is.GreaterThan(200), name + ": rope-coloured pixels");
                }
            }
        }

        [TestCase(0f)]
        [TestCase(0.5f)]
        [TestCase(1.5f)]
        public void RasterizedRopeCoversTheProjectedAreaOfTheCoreMesh(float lean)
        {
            // A straight default rope alone, leaning by `lean` m over its 2 m (so it crosses the pixel grid at an angle;
            // a rope parallel to the pixel columns is quantised to whole supersamples per row): the pixels the rasterizer
            // gives it against the projected area of the core mesh's front faces (the closed tube's silhouette).
            var scene = new FigureScene();
            var s = HarnessRigFigures.DefaultRope(AttachmentSpec.FixedAt(new Float3(-lean / 2, 1f, 0f)),
                new AttachmentSpec { Kind = AttachmentKind.Free, Position = new Float3(lean / 2, -1f, 0f) }, InitialShape.Straight, 1.0 / 90.0);
            scene.AddRope(ScenarioRunner.Build(s).Simulation, HarnessRig.RopeOrange);
            var view = new OrthographicView(Float3.Zero, 32f, 14f, HarnessRigFigures.PixelsPerMetre, 400, 400);
            var raster = new ZBufferRasterizer(view.Scaled(FigureWriter.Supersampling), FigureWriter.Background);
            raster.Draw(scene.Triangles);
            double pixels = raster.CountVisible(SurfaceKind.Rope) / (double)(FigureWriter.Supersampling * FigureWriter.Supersampling);
            double projected = ZBufferRasterizer.ProjectedFrontArea(scene.Triangles, view, SurfaceKind.Rope);
            Assert.That(projected, Is.GreaterThan(500), "projected area (px²)");
            Assert.That(pixels / projected, Is.EqualTo(1.0).Within(Tolerance(lean)), $"rope pixels {pixels:F1} / projected {projected:F1}");
        }

        /// <summary>Coverage tolerance: 2 % at an angle; a rope along the pixel columns (lean 0) may gain a whole supersample per row (1/7.2).</summary>
        static double Tolerance(float lean) => lean == 0f ? 0.12 : 0.02;

        [Test]
        public void EachFiguresRopeIsDrawnWhereItsMeshProjects()
        {
            // In the written figures: the rasterizer's rope pixels against the projected core mesh (occlusion by the anchor
            // cube and the D-ring, the folded slack overlapping itself and the vertical rope's quantisation move it), and the
            // rope-coloured pixels of the PNG as written (outside the zoomed detail) against the rasterizer's count.
            foreach (var figure in HarnessRigFigures.All())
            {
                var path = Path.Combine(dir, figure.FileName);
                var stats = FigureWriter.Write(figure, path);
                using (var bitmap = SKBitmap.Decode(path))
                {
                    int coloured = RopeColouredPixels(bitmap, figure.Inset);
                    Assert.That(stats.Coverage, Is.InRange(0.8, 1.12), figure.FileName + ": rope pixels / projected mesh area");
                    Assert.That(coloured / stats.RopePixels, Is.InRange(0.75, 1.1), $"{figure.FileName}: {coloured} rope-coloured PNG pixels / {stats.RopePixels:F0} rasterized");
                }
            }
        }

        /// <summary>Rope-coloured pixels of <paramref name="bitmap"/>, leaving out the area of <paramref name="inset"/> (when not null).</summary>
        static int RopeColouredPixels(SKBitmap bitmap, FigureInset inset)
        {
            var skip = inset == null ? SKRectI.Empty
                : SKRectI.Create((int)inset.Position.X - 2, (int)inset.Position.Y - 2, inset.View.Width + 4, inset.View.Height + 4);
            int count = 0;
            for (int y = 0; y < bitmap.Height; y++)
                for (int x = 0; x < bitmap.Width; x++)
                    if (!skip.Contains(x, y) && IsRopeColoured(bitmap.GetPixel(x, y))) count++;
            return count;
        }

        /// <summary>Hue of the default safety orange (≈ 28°) with a clear saturation, any shade.</summary>
        static bool IsRopeColoured(SKColor c)
        {
            c.ToHsv(out float hue, out float saturation, out float value);
            return hue >= 15f && hue <= 40f && saturation >= 45f && value >= 20f;
        }
    }
}
