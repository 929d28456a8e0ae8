using System;
using System.IO;
using System.Runtime.InteropServices;
using SkiaSharp;

namespace HookeRope.Lab.Figures
{
    /// <summary>
    /// Renders a <see cref="DocumentationFigure"/>: the depth-buffered rasterizer at <see cref="Supersampling"/>× the
    /// resolution, box-filtered down (smooth edges), then the annotations with SkiaSharp, written as PNG. Textures are read
    /// once per final pixel at its mip level, as a GPU with multisampling does.
    /// </summary>
    public static class FigureWriter
    {
        /// <summary>Samples per pixel along each axis.</summary>
        public const int Supersampling = 3;

        /// <summary>log2(<see cref="Supersampling"/>): the rasterizer's level-of-detail bias, so textures are filtered per final pixel.</summary>
        public static readonly float SupersamplingLodBias = MathF.Log2(Supersampling);

        /// <summary>Background colour 0xRRGGBB.</summary>
        public const uint Background = 0xF4F5F7;

        /// <summary>Renders, annotates and writes <paramref name="figure"/> to <paramref name="path"/>; returns the numbers.</summary>
        public static FigureStats Write(DocumentationFigure figure, string path)
        {
            var view = figure.View;
            var fine = view.Scaled(Supersampling);
            var raster = new ZBufferRasterizer(fine, Background) { LodBias = SupersamplingLodBias, ShadingRate = Supersampling };
            raster.Draw(figure.Scene.Triangles);
            var stats = new FigureStats
            {
                Path = path,
                Width = view.Width,
                Height = view.Height,
                RopePixels = raster.CountVisible(SurfaceKind.Rope) / (double)(Supersampling * Supersampling),
                BurrPixels = raster.CountVisible(SurfaceKind.Burr) / (double)(Supersampling * Supersampling),
                ProjectedRopeArea = ZBufferRasterizer.ProjectedFrontArea(figure.Scene.Triangles, view, SurfaceKind.Rope),
            };
            using (var bitmap = Downsample(raster.Color, view.Width, view.Height, Supersampling))
            {
                using (var canvas = new SKCanvas(bitmap))
                using (var typeface = SKTypeface.FromFamilyName("DejaVu Sans") ?? SKTypeface.Default)
                using (var font = new SKFont(typeface, 15f) { Edging = SKFontEdging.Antialias })
                {
                    foreach (var panel in figure.Panels) DrawInset(canvas, panel, figure.Scene, font);
                    foreach (var annotation in figure.Annotations) annotation.Draw(canvas, view, font);
                    if (figure.Inset != null) DrawInset(canvas, figure.Inset, figure.Scene, font);
                }
                var directory = System.IO.Path.GetDirectoryName(System.IO.Path.GetFullPath(path));
                Directory.CreateDirectory(directory);
                using (var data = bitmap.Encode(SKEncodedImageFormat.Png, 100))
                using (var file = File.Create(path))
                    data.SaveTo(file);
            }
            stats.Bytes = new FileInfo(path).Length;
            return stats;
        }

        /// <summary>Renders an inset or panel (its own scene, else <paramref name="scene"/>; its own camera) and draws it framed at its position.</summary>
        static void DrawInset(SKCanvas canvas, FigureInset inset, FigureScene scene, SKFont font)
        {
            var raster = new ZBufferRasterizer(inset.View.Scaled(Supersampling), Background) { LodBias = SupersamplingLodBias, ShadingRate = Supersampling };
            raster.Draw((inset.Scene ?? scene).Triangles);
            using (var detail = Downsample(raster.Color, inset.View.Width, inset.View.Height, Supersampling))
            {
                int magnify = Math.Max(1, inset.Magnify);
                var frame = SKRect.Create(inset.Position.X, inset.Position.Y, inset.View.Width * magnify, inset.View.Height * magnify);
                // a magnified detail shows its pixels as blocks (nearest neighbour), as a headset's pixels are seen
                using (var image = SKImage.FromBitmap(detail))
                    canvas.DrawImage(image, frame, new SKSamplingOptions(SKFilterMode.Nearest, SKMipmapMode.None));
                using (var border = new SKPaint { Color = FigureAnnotation.Ink, IsAntialias = true, Style = SKPaintStyle.Stroke, StrokeWidth = 1.5f })
                    canvas.DrawRect(frame, border);
                if (!string.IsNullOrEmpty(inset.Caption))
                {
                    using (var ink = new SKPaint { Color = FigureAnnotation.Ink, IsAntialias = true })
                        canvas.DrawText(inset.Caption, frame.Left, frame.Bottom + font.Size + 4, SKTextAlign.Left, font, ink);
                }
            }
        }

        /// <summary>Averages <paramref name="factor"/>² samples per pixel into an opaque RGBA bitmap.</summary>
        internal static SKBitmap Downsample(uint[] color, int width, int height, int factor)
        {
            int fineWidth = width * factor;
            var rgba = new byte[width * height * 4];
            int samples = factor * factor;
            for (int y = 0; y < height; y++)
            {
                for (int x = 0; x < width; x++)
                {
                    int r = 0, g = 0, b = 0;
                    for (int sy = 0; sy < factor; sy++)
                    {
                        int row = (y * factor + sy) * fineWidth + x * factor;
                        for (int sx = 0; sx < factor; sx++)
                        {
                            uint c = color[row + sx];
                            r += (int)((c >> 16) & 0xFF);
                            g += (int)((c >> 8) & 0xFF);
                            b += (int)(c & 0xFF);
                        }
                    }
                    int o = (y * width + x) * 4;
                    rgba[o] = (byte)((r + samples / 2) / samples);
                    rgba[o + 1] = (byte)((g + samples / 2) / samples);
                    rgba[o + 2] = (byte)((b + samples / 2) / samples);
                    rgba[o + 3] = 255;
                }
            }
            var bitmap = new SKBitmap(new SKImageInfo(width, height, SKColorType.Rgba8888, SKAlphaType.Opaque));
            var pixels = bitmap.GetPixels();
            for (int y = 0; y < height; y++)
                Marshal.Copy(rgba, y * width * 4, pixels + y * bitmap.RowBytes, width * 4);
            return bitmap;
        }
    }
}
