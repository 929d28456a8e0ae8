using System;
using HookeRope.Mathematics;
using SkiaSharp;
using static HookeRope.Lab.Figures.Paper.PaperFigures;

namespace HookeRope.Lab.Figures.Paper
{
    /// <summary>
    /// Fig. 7b, the burred break as a headset shows it: the fracture cord's two broken ends at 1 m and 20 px per degree
    /// (1146 px/m), each rendered pixel drawn as a 4 × 4 block, with the strands untextured (geometry alone), with the burr
    /// texture without mipmaps (the runtime texture before issue 17) and with its mip chain (the package now). Each panel
    /// carries its shimmer: how much the pixels flicker while the head sways by fractions of a pixel.
    /// </summary>
    public static class HeadsetBurrFigure
    {
        /// <summary>File name.</summary>
        public const string FileName = "paper-fig7b-burr-headset.png";
        /// <summary>Headset resolution (px per degree) and viewing distance (m): 20 px/° at 1 m.</summary>
        public const float PixelsPerDegree = 20f, Distance = 1f;
        /// <summary>Rendered pixel per metre at that distance: 20 / (1 m · tan 1°) = 1146 px/m.</summary>
        public static readonly float PixelsPerMetre = (float)(PixelsPerDegree / (Distance * Math.Tan(Math.PI / 180.0)));
        /// <summary>Figure pixels per headset pixel at size 1.</summary>
        public const int Magnify = 4;
        /// <summary>Headset pixels of a panel (6.5 cm × 6.1 cm at 1 m).</summary>
        public const int PanelWidth = 75, PanelHeight = 70;
        /// <summary>Sub-pixel head positions the shimmer is measured over (screen x shifts of k/<see cref="Shifts"/> px).</summary>
        public const int Shifts = 6;
        /// <summary>Samples per pixel and axis of the reference render (an ideally filtered image).</summary>
        public const int ReferenceSupersampling = 12;

        /// <summary>The three ways of drawing the strands: none (geometry), level 0 only, the mip chain.</summary>
        public static readonly string[] Panels = { "geometry alone", "texture, no mipmaps", "texture + mipmaps" };

        /// <summary>The texture of panel <paramref name="k"/> (null = untextured).</summary>
        public static FigureTexture TextureOf(int k) => k == 0 ? null : FigureTexture.PackageBurr(mipmaps: k == 2);

        /// <summary>The figure; Numbers hold each panel's shimmer (% of full scale) and visible strand pixels.</summary>
        public static DocumentationFigure Build(float scale = 1f)
        {
            int magnify = Math.Max(1, (int)Math.Round(Magnify * scale));
            int width = Px(1000, scale), panelPx = PanelWidth * magnify, gap = Math.Max(0, (width - 3 * panelPx) / 4);
            var run = BurrFigure.BrokenRun(RadialSegments);
            var cut = SequenceFigure.BreakCentre(run);
            var figure = Frame(FileName, cut, BurrFigure.Yaw, BurrFigure.Pitch, PixelsPerMetre, width, PanelHeight * magnify + Px(40, scale));
            for (int k = 0; k < Panels.Length; k++)
            {
                var scene = new FigureScene();
                scene.AddRope(run.Setup.Simulation, RopeColor, Float3.Zero, TextureOf(k));
                var view = new OrthographicView(cut, BurrFigure.Yaw, BurrFigure.Pitch, PixelsPerMetre, PanelWidth, PanelHeight);
                double shimmer = Shimmer(scene, view, out double burrPixels);
                figure.Panels.Add(new FigureInset
                {
                    Scene = scene,
                    View = view,
                    Magnify = magnify,
                    Position = new SKPoint(gap + k * (panelPx + gap), 8),
                    Caption = F("{0}: shimmer {1:0.0} %", Panels[k], shimmer),
                });
                figure.Numbers[F("panel {0} shimmer (%)", k)] = shimmer;
                figure.Numbers[F("panel {0} strand pixels", k)] = burrPixels;
            }
            Caption(figure, F("Fig. 7b  The break in a headset: 1 m away at 20 px/° ({0:0} px/m), a pixel drawn {1} × {1}. Shimmer: flicker as the head\n", PixelsPerMetre, magnify) +
                            "moves by sixths of a pixel (vs an ideally filtered render, % of full scale). Mipmaps keep the texture from aliasing.");
            return figure;
        }

        /// <summary>
        /// Shimmer of <paramref name="scene"/> in <paramref name="view"/> (% of full scale): for <see cref="Shifts"/> camera
        /// positions k/Shifts px to the right, the error of the figure render (3× supersampling, mip level of the final
        /// pixel) against a <see cref="ReferenceSupersampling"/>× render (level 0, an ideally filtered image) is taken per
        /// pixel and luminance; its standard deviation over the positions, averaged over the pixels where strands show, is the
        /// shimmer. A stable error (blur) does not count; what changes as the head moves does. <paramref name="burrPixels"/>:
        /// pixels where strands show.
        /// </summary>
        public static double Shimmer(FigureScene scene, OrthographicView view, out double burrPixels)
        {
            int n = view.Width * view.Height;
            var sum = new double[n];
            var squares = new double[n];
            var mask = new bool[n];
            for (int k = 0; k < Shifts; k++)
            {
                var target = view.Target + view.Right * ((float)k / Shifts / view.PixelsPerMetre);
                var shifted = new OrthographicView(target, BurrFigure.Yaw, BurrFigure.Pitch, view.PixelsPerMetre, view.Width, view.Height);
                var frame = Luminance(scene, shifted, FigureWriter.Supersampling, FigureWriter.SupersamplingLodBias, FigureWriter.Supersampling, null);
                var reference = Luminance(scene, shifted, ReferenceSupersampling, 0f, 1, k == 0 ? mask : null);
                for (int i = 0; i < n; i++)
                {
                    double e = frame[i] - reference[i];
                    sum[i] += e;
                    squares[i] += e * e;
                }
            }
            double total = 0.0;
            int count = 0;
            for (int i = 0; i < n; i++)
            {
                if (!mask[i]) continue;
                double mean = sum[i] / Shifts;
                total += Math.Sqrt(Math.Max(0.0, squares[i] / Shifts - mean * mean));
                count++;
            }
            burrPixels = count;
            return count > 0 ? 100.0 * total / count : 0.0;
        }

        /// <summary>Per-pixel luminance in [0, 1] of a render at <paramref name="factor"/>× supersampling; marks pixels that are half or more strand.</summary>
        static double[] Luminance(FigureScene scene, OrthographicView view, int factor, float lodBias, int shadingRate, bool[] burr)
        {
            var raster = new ZBufferRasterizer(view.Scaled(factor), FigureWriter.Background) { LodBias = lodBias, ShadingRate = shadingRate };
            raster.Draw(scene.Triangles);
            int w = view.Width, fine = w * factor, samples = factor * factor;
            var result = new double[w * view.Height];
            for (int y = 0; y < view.Height; y++)
            for (int x = 0; x < w; x++)
            {
                double l = 0.0;
                int strands = 0;
                for (int sy = 0; sy < factor; sy++)
                for (int sx = 0; sx < factor; sx++)
                {
                    int i = (y * factor + sy) * fine + x * factor + sx;
                    uint c = raster.Color[i];
                    l += (0.2126 * ((c >> 16) & 0xFF) + 0.7152 * ((c >> 8) & 0xFF) + 0.0722 * (c & 0xFF)) / 255.0;
                    if (raster.Kind[i] == SurfaceKind.Burr) strands++;
                }
                result[y * w + x] = l / samples;
                if (burr != null) burr[y * w + x] = 2 * strands >= samples;
            }
            return result;
        }
    }
}
