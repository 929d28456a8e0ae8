using System;
using System.IO;
using HookeRope.Lab.Commands;
using HookeRope.Lab.Figures;
using HookeRope.Lab.Figures.Paper;
using HookeRope.Mathematics;
using NUnit.Framework;
using SkiaSharp;

namespace HookeRope.Lab.Tests
{
    /// <summary>
    /// The seed paper's Figs. 5, 6, 7, 8 and 9a redrawn by <c>figures paper</c>: files, sizes, captions, and per figure a
    /// number read back from the rendered PNG (rendered at <see cref="Small"/> × the committed size to stay fast).
    /// </summary>
    [TestFixture]
    public sealed class PaperFiguresTests : TempFolderTest
    {
        /// <summary>Render scale of the per-figure checks.</summary>
        const float Small = 0.5f;
        /// <summary>Committed figures must stay below this (bytes).</summary>
        const long MaxBytes = 200 * 1024;

        DocumentationFigure Written(DocumentationFigure figure, out FigureStats stats)
        {
            stats = FigureWriter.Write(figure, Path.Combine(dir, figure.FileName));
            return figure;
        }

        [Test]
        public void FiguresPaperWritesSixPngsTheirCaptionsAndTheBurrTexture()
        {
            var output = new StringWriter();
            int code = LabCli.Invoke(new[] { "figures", "paper", "--out", dir }, LabConsole.Plain(output), output, output);
            Assert.That(code, Is.EqualTo(0), output.ToString());
            string markdown = File.ReadAllText(Path.Combine(dir, FigureCaptions.MarkdownFile));
            string json = File.ReadAllText(Path.Combine(dir, FigureCaptions.JsonFile));
            foreach (var name in PaperFigures.FileNames)
            {
                var path = Path.Combine(dir, name);
                Assert.That(new FileInfo(path).Length, Is.InRange(5 * 1024, MaxBytes), name + ": PNG bytes");
                using (var bitmap = SKBitmap.Decode(path))
                {
                    Assert.That(bitmap.Width, Is.EqualTo(1000), name);
                    Assert.That(bitmap.Height, Is.InRange(300, 600), name);
                }
                Assert.That(markdown, Does.Contain("## " + name), "caption section of " + name);
                Assert.That(json, Does.Contain("\"file\": \"" + name + "\""), "caption entry of " + name);
            }
            Assert.That(markdown, Does.Contain("Fig. 5").And.Contain("Fig. 6").And.Contain("Fig. 7").And.Contain("Fig. 7b").And.Contain("Fig. 8").And.Contain("Fig. 9a"));
            using (var texture = SKBitmap.Decode(Path.Combine(dir, BurrTexturePng.FileName)))
            {
                Assert.That(texture.Width, Is.EqualTo(FigureTexture.BurrWidth));
                Assert.That(texture.Height, Is.EqualTo(FigureTexture.BurrHeight));
            }
            Assert.That(File.Exists(Path.Combine(dir, HarnessRigFigures.FileNames[0])), Is.False, "the paper set writes only its own figures");
        }

        [Test]
        public void EachFigureAtASmallSizeWritesAPngOfTheViewSizeWithItsCaption()
        {
            foreach (var figure in PaperFigures.All(Small))
            {
                Written(figure, out var stats);
                using (var bitmap = SKBitmap.Decode(stats.Path))
                {
                    Assert.That(bitmap.Width, Is.EqualTo(figure.View.Width), figure.FileName);
                    Assert.That(bitmap.Height, Is.EqualTo(figure.View.Height), figure.FileName);
                    Assert.That(bitmap.Width, Is.EqualTo(PaperFigures.Px(1000, Small)), figure.FileName);
                }
                Assert.That(figure.Caption, Does.StartWith("Fig. "), figure.FileName);
                // Fig. 7 draws its ropes in panels (checked by its own test); the others in the main render
                if (figure.Panels.Count == 0)
                    Assert.That(stats.RopePixels + stats.BurrPixels, Is.GreaterThan(500), figure.FileName + ": rope pixels (main render)");
            }
        }

        [Test]
        public void Fig5DrawnWidthPerPoissonRatioIsTheModelDiameter()
        {
            var figure = Written(PoissonSweepFigure.Build(Small), out var stats);
            float ppm = PoissonSweepFigure.PixelsPerMetre * Small;
            var widths = new double[PoissonSweepFigure.Ratios.Length + 1];
            using (var png = new RenderReadback(stats.Path))
            {
                int column = (int)(png.Width * 0.75);
                for (int row = 0; row < widths.Length; row++)
                {
                    var (_, y, _) = figure.View.Project(PoissonSweepFigure.RowCenter(row));
                    int half = (int)Math.Ceiling(0.01f * ppm) + 2;  // R = 10 mm is the widest row
                    widths[row] = png.ColumnWidth(column, (int)y - half, (int)y + half);
                    double expected = figure.Numbers[$"row {row} width (px)"];
                    // the 16-gon's silhouette lies between 2r·cos(π/16) and 2r
                    Assert.That(widths[row], Is.EqualTo(expected).Within(0.6), $"row {row}: drawn width (px) against 2·r·scale");
                }
            }
            Assert.That(widths[1], Is.EqualTo(widths[0]).Within(0.3), "ν = 0 keeps the rest width");
            Assert.That(widths[1] - widths[2], Is.GreaterThan(2.0), "ν = 0.25 is thinner than ν = 0 (px)");
            Assert.That(widths[2] - widths[3], Is.GreaterThan(2.0), "ν = 0.5 is thinner than ν = 0.25 (px)");
            TestContext.WriteLine("Fig. 5 widths (px at {0} px/m): {1}", ppm, string.Join(", ", Array.ConvertAll(widths, w => w.ToString("F2"))));
        }

        [Test]
        public void Fig6WaistWidthsOrderAsTheOnsetRadius()
        {
            var figure = Written(NeckFigure.Build(Small), out var stats);
            float ppm = NeckFigure.PixelsPerMetre * Small;
            var waists = new double[NeckFigure.Fractions.Length];
            using (var png = new RenderReadback(stats.Path))
            {
                for (int row = 0; row < waists.Length; row++)
                {
                    var (cx, cy, _) = figure.View.Project(NeckFigure.RowCenter(row));
                    int half = (int)Math.Ceiling(0.01f * ppm) + 1;
                    int reach = (int)(0.1f * ppm);  // ±10 cm around the defect
                    waists[row] = double.MaxValue;
                    for (int x = (int)cx - reach; x <= (int)cx + reach; x++)
                        waists[row] = Math.Min(waists[row], png.ColumnWidth(x, (int)cy - half, (int)cy + half));
                    double expected = figure.Numbers[$"row {row} waist width (px)"];
                    // The 8-sided waist ring's silhouette is between 2r·cos(π/8) and 2r wide, whichever way it is turned.
                    Assert.That(waists[row], Is.InRange(expected * Math.Cos(Math.PI / 8) - 0.6, expected + 0.6), $"row {row}: drawn waist (px) against 2·MinRadius·scale");
                }
            }
            // r_min 0.8 > 0.75 > 0.7 R: the waists order the same way
            Assert.That(waists[0], Is.GreaterThan(waists[1]), "waist at r_min 0.8 R wider than at 0.75 R");
            Assert.That(waists[1], Is.GreaterThan(waists[2]), "waist at r_min 0.75 R wider than at 0.7 R");
            TestContext.WriteLine("Fig. 6 waists (px at {0} px/m): {1}", ppm, string.Join(", ", Array.ConvertAll(waists, w => w.ToString("F2"))));
        }

        [Test]
        public void Fig7BurrsHaveTrianglesInProportionToTheRadialSegmentsAndShowInTheirPanels()
        {
            var figure = Written(BurrFigure.Build(Small), out _);
            Assert.That(figure.Panels.Count, Is.EqualTo(3));
            for (int k = 0; k < 3; k++)
            {
                var panel = figure.Panels[k];
                int radial = BurrFigure.RadialCounts[k];
                int drawn = panel.Scene.BurrTriangleCount;
                Assert.That(drawn, Is.EqualTo((int)figure.Numbers[$"panel {k} core burr indices / 3"]), "every strand triangle of the core is drawn");
                // Issue 17: fibres across the cut, as many as the cross-section holds (at least one per radial segment), 3 faces each.
                Assert.That(drawn % 3, Is.EqualTo(0), $"{drawn} fibre triangles: three-sided fibres");
                Assert.That(drawn, Is.GreaterThanOrEqualTo(3 * radial), "at least one fibre per radial segment");
                var raster = new ZBufferRasterizer(panel.View.Scaled(FigureWriter.Supersampling), FigureWriter.Background);
                raster.Draw(panel.Scene.Triangles);
                double burrPixels = raster.CountVisible(SurfaceKind.Burr) / (double)(FigureWriter.Supersampling * FigureWriter.Supersampling);
                Assert.That(burrPixels, Is.GreaterThan(100), $"panel {k}: visible strand pixels");
                TestContext.WriteLine("Fig. 7 panel {0}: {1} radial segments, {2} strand triangles, {3:F0} strand px", k, radial, drawn, burrPixels);
            }
        }

        [Test]
        public void Fig7bAtOneMetreTheStrandsShowAndMipmapsKeepTheTextureFromShimmering()
        {
            // issue 17 item 3: at 1 m and 20 px per degree the broken ends read as frayed (strand pixels) and, with the
            // package's mip chain, the texture adds little flicker to the strands' own edges; level 0 alone aliases
            var figure = Written(HeadsetBurrFigure.Build(Small), out _);
            double geometry = figure.Numbers["panel 0 shimmer (%)"], plain = figure.Numbers["panel 1 shimmer (%)"], mipmapped = figure.Numbers["panel 2 shimmer (%)"];
            TestContext.WriteLine("Fig. 7b shimmer: geometry {0:F3} %, texture without mipmaps {1:F3} %, with mipmaps {2:F3} %; strand pixels {3}",
                geometry, plain, mipmapped, figure.Numbers["panel 2 strand pixels"]);
            Assert.That(HeadsetBurrFigure.PixelsPerMetre, Is.EqualTo(1146.0).Within(1.0), "20 px/° at 1 m");
            Assert.That(figure.Numbers["panel 2 strand pixels"], Is.GreaterThan(60), "the frayed ends cover pixels at 1 m");
            Assert.That(plain, Is.GreaterThan(geometry + 0.3), "level 0 alone aliases on the minified strands");
            Assert.That(mipmapped - geometry, Is.LessThan(0.5 * (plain - geometry)), "the mip chain removes most of the texture's flicker");
        }

        [Test]
        public void Fig8ThirdRowShowsTwoSeparatePiecesAndTheFirstTwoOne()
        {
            var figure = Written(SequenceFigure.Build(Small), out var stats);
            using (var png = new RenderReadback(stats.Path))
            {
                for (int row = 0; row < 3; row++)
                {
                    var (_, y, _) = figure.View.Project(SequenceFigure.RowCenter(row));
                    var runs = png.RowRuns((int)y);
                    Assert.That(runs.Count, Is.EqualTo(row < 2 ? 1 : 2), $"row {row}: rope pieces along its axis");
                    if (row == 2)
                    {
                        int gap = runs[1].Start - (runs[0].Start + runs[0].Length);
                        Assert.That(gap, Is.GreaterThan(5), "gap between the pieces (px)");
                        Assert.That(runs[0].Length, Is.GreaterThan(50), "left piece (px)");
                        Assert.That(runs[1].Length, Is.GreaterThan(50), "right piece (px)");
                        TestContext.WriteLine("Fig. 8 row 3: pieces {0} px and {1} px, gap {2} px", runs[0].Length, runs[1].Length, gap);
                    }
                }
            }
            Assert.That(figure.Numbers["row 1 min radius (mm)"], Is.LessThan(figure.Numbers["row 0 min radius (mm)"]), "the neck is thinner than the uniform rope");
        }

        [Test]
        public void Fig9aRopePixelsStayOutsideTheBarsDisc()
        {
            var figure = Written(CollisionBendFigure.Build(Small), out var stats);
            var centre = CollisionBendFigure.BarCenter(PaperFigures.Scenario("collision-bend"));
            double barRadius = figure.Numbers["bar radius (mm)"] / 1000;
            double ropeRadius = figure.Numbers["rope radius (mm)"] / 1000;
            var inset = figure.Inset;
            using (var png = new RenderReadback(stats.Path))
            {
                double mainDepth = DeepestRopePixel(png, figure.View, 0, 0, figure.View.Width, figure.View.Height, inset, centre, barRadius, out int mainPixels);
                double detailDepth = DeepestRopePixel(png, inset.View, (int)inset.Position.X, (int)inset.Position.Y, inset.View.Width, inset.View.Height, null, centre, barRadius, out int detailPixels);
                Assert.That(mainPixels, Is.GreaterThan(500), "rope pixels in the main view");
                Assert.That(detailPixels, Is.GreaterThan(500), "rope pixels in the detail");
                // a rope pixel centre may lie half a pixel inside the disc's edge; beyond that the tube would enter the bar
                double mainTolerance = 1.0 / figure.View.PixelsPerMetre, detailTolerance = 1.0 / inset.View.PixelsPerMetre;
                Assert.That(mainDepth, Is.LessThan(mainTolerance), $"main view: deepest rope pixel {mainDepth * 1000:F2} mm inside the bar");
                // issue 17 item 4: the drawn surface stays outside the collider within 2 % of the rope's radius
                Assert.That(detailDepth, Is.LessThan(detailTolerance + 0.02 * ropeRadius), $"detail: deepest rope pixel {detailDepth * 1000:F2} mm inside the bar");
                TestContext.WriteLine("Fig. 9a deepest rope pixel inside the bar: main {0:F2} mm ({1:F2} px), detail {2:F2} mm ({3:F2} px)",
                    mainDepth * 1000, mainDepth * figure.View.PixelsPerMetre, detailDepth * 1000, detailDepth * inset.View.PixelsPerMetre);
            }
        }

        /// <summary>Largest depth (m) inside the bar's disc of a rope pixel's centre in the given screen rectangle (skipping <paramref name="skip"/>), through <paramref name="view"/>.</summary>
        static double DeepestRopePixel(RenderReadback png, OrthographicView view, int left, int top, int width, int height, FigureInset skip,
            Float3 centre, double barRadius, out int ropePixels)
        {
            double deepest = double.NegativeInfinity;
            ropePixels = 0;
            for (int y = top; y < top + height; y++)
            {
                for (int x = left; x < left + width; x++)
                {
                    if (skip != null && x >= skip.Position.X - 2 && x <= skip.Position.X + skip.View.Width + 2
                        && y >= skip.Position.Y - 2 && y <= skip.Position.Y + skip.View.Height + 2) continue;
                    if (!png.IsRope(x, y)) continue;
                    ropePixels++;
                    // the detail and the main view look along +Z: screen right = +X, screen up = +Y
                    double wx = view.Target.X + (x - left + 0.5 - view.Width * 0.5) / view.PixelsPerMetre;
                    double wy = view.Target.Y - (y - top + 0.5 - view.Height * 0.5) / view.PixelsPerMetre;
                    double depth = barRadius - Math.Sqrt((wx - centre.X) * (wx - centre.X) + (wy - centre.Y) * (wy - centre.Y));
                    deepest = Math.Max(deepest, depth);
                }
            }
            return deepest;
        }
    }
}
