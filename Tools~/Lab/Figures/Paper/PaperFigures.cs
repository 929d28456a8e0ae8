using System;
using System.Collections.Generic;
using System.Globalization;
using HookeRope.Lab.Scenarios;
using HookeRope.Mathematics;
using SkiaSharp;

namespace HookeRope.Lab.Figures.Paper
{
    /// <summary>
    /// The seed paper's result figures (Chen et al. 2022, Figs. 5, 6, 7, 8 and 9a) redrawn from the package's own
    /// simulations: the built-in scenarios stepped by <see cref="FigureRun"/>, the mesh exactly as
    /// <see cref="HookeRope.RopeSimulation.FillMesh(HookeRope.Geometry.TubeVertex[], int[])"/> builds it (radius model,
    /// neck, burr strands with the package's burr texture), flat-shaded and lit by the <see cref="ZBufferRasterizer"/>,
    /// orthographic, with a caption drawn at the bottom of each image.
    /// </summary>
    public static class PaperFigures
    {
        /// <summary>Height (px) of the caption band under the rendered area.</summary>
        public const int CaptionBand = 52;
        /// <summary>Radial segments of the figures' tube (Fig. 7 varies them).</summary>
        public const int RadialSegments = 16;
        /// <summary>Rope colour (0xRRGGBB): the harness figures' safety orange.</summary>
        public const uint RopeColor = HarnessRig.RopeOrange;
        /// <summary>Colliders and props (0xRRGGBB).</summary>
        public const uint PropColor = 0x8C939C;

        /// <summary>File names, in figure order (5, 6, 7, 7b, 8, 9a).</summary>
        public static readonly string[] FileNames =
        {
            PoissonSweepFigure.FileName, NeckFigure.FileName, BurrFigure.FileName, HeadsetBurrFigure.FileName, SequenceFigure.FileName, CollisionBendFigure.FileName,
        };

        /// <summary>All six figures at <paramref name="scale"/> × their committed size (1 = committed; tests use less).</summary>
        public static List<DocumentationFigure> All(float scale = 1f) => new List<DocumentationFigure>
        {
            PoissonSweepFigure.Build(scale), NeckFigure.Build(scale), BurrFigure.Build(scale), HeadsetBurrFigure.Build(scale), SequenceFigure.Build(scale), CollisionBendFigure.Build(scale),
        };

        /// <summary>A built-in scenario with the figures' tube resolution.</summary>
        public static Scenario Scenario(string name, int radialSegments = RadialSegments)
        {
            var s = BuiltInScenarios.Load(name);
            s.Rope.RadialSegments = radialSegments;
            return s;
        }

        /// <summary>
        /// Continues the keyframed end of <paramref name="s"/> at its last speed up to <paramref name="seconds"/> s (and the
        /// duration with it): lets a slow pull go past the built-in run's end.
        /// </summary>
        public static Scenario PullLonger(Scenario s, double seconds)
        {
            var keys = s.End.Keys;
            var a = keys[keys.Count - 2];
            var b = keys[keys.Count - 1];
            var velocity = (b.Position - a.Position) * (float)(1.0 / (b.Time - a.Time));
            keys.Add(new Keyframe { Time = seconds, Position = b.Position + velocity * (float)(seconds - b.Time) });
            s.Duration = seconds;
            return s;
        }

        /// <summary><paramref name="pixels"/> × <paramref name="scale"/>, rounded, at least 1.</summary>
        public static int Px(int pixels, float scale) => Math.Max(1, (int)Math.Round(pixels * scale));

        /// <summary>A figure of <paramref name="width"/> × (<paramref name="renderHeight"/> + <see cref="CaptionBand"/>) px whose render area is centred on <paramref name="target"/>.</summary>
        public static DocumentationFigure Frame(string fileName, Float3 target, float yaw, float pitch, float pixelsPerMetre, int width, int renderHeight)
        {
            // the view is centred on the render area: shift the target down by half the caption band
            var probe = new OrthographicView(target, yaw, pitch, pixelsPerMetre, width, renderHeight + CaptionBand);
            var shifted = target - probe.Up * (CaptionBand * 0.5f / pixelsPerMetre);
            return new DocumentationFigure { FileName = fileName, View = new OrthographicView(shifted, yaw, pitch, pixelsPerMetre, width, renderHeight + CaptionBand) };
        }

        /// <summary>Sets the caption and draws it in the band at the bottom.</summary>
        public static void Caption(DocumentationFigure figure, string text)
        {
            figure.Caption = text;
            figure.Annotations.Add(new FigureCaption { Text = text, Position = new SKPoint(8, figure.View.Height - CaptionBand + 4) });
        }

        /// <summary>A label box at a fixed screen position (no leader).</summary>
        public static void Tag(DocumentationFigure figure, float x, float y, string text) =>
            figure.Annotations.Add(new FigureCaption { Text = text, Position = new SKPoint(x, y) });

        /// <summary>Invariant-culture formatting.</summary>
        public static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }
}
