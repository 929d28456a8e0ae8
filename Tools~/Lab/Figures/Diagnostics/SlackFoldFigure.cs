using System;
using System.Collections.Generic;
using HookeRope.Geometry;
using HookeRope.Lab.Figures.Paper;
using HookeRope.Lab.Scenarios;
using HookeRope.Mathematics;
using SkiaSharp;
using static HookeRope.Lab.Figures.Paper.PaperFigures;

namespace HookeRope.Lab.Figures.Diagnostics
{
    /// <summary>
    /// Slack folds made visible (issue 17): the slack pieces of the built-in "fracture" cord, a few host steps after the
    /// break, fold tighter than the tube radius (BDF2 keeps the recoil's energy). The tube mesh used to pass through itself
    /// there; since the fold repair (rings that never cross, fold tips, the Hermite tangent clamp) it closes into cones and
    /// the census is 0 at every step. Two rows (the built-in cord without gravity, the same cord with gravity), one panel per step after
    /// the break, each drawn as a GPU with back-face culling draws it, the tube triangles wound against their own normals
    /// in red, centred on the folds of the piece on the fixed end. Numbers: per panel the inverted triangles and their
    /// area, the shortest segment against its rest length and the sharpest turn between segments; per row the inverted
    /// triangles at every step from the break to <see cref="CensusSteps"/>.
    /// </summary>
    public static class SlackFoldFigure
    {
        /// <summary>File name.</summary>
        public const string FileName = "diagnostic-slack-folds.png";
        /// <summary>Host steps after the break drawn, one panel each.</summary>
        public static readonly int[] Steps = { 3, 4, 5, 10 };
        /// <summary>Steps after the break counted per row.</summary>
        public const int CensusSteps = 10;
        /// <summary>Scale at size 1 (px per metre).</summary>
        public const float PixelsPerMetre = 2600f;
        /// <summary>Camera yaw (degrees).</summary>
        public const float Yaw = -35f;
        /// <summary>Camera pitch (degrees).</summary>
        public const float Pitch = 25f;
        /// <summary>Colour of inverted tube triangles (0xRRGGBB).</summary>
        public const uint InvertedColor = 0xE0201C;

        /// <summary>The two rows' scenarios: the built-in fracture cord, and the same with gravity (−9.81 m/s² along y).</summary>
        public static Scenario Row(int row)
        {
            var s = Scenario("fracture");
            if (row == 1) s.Gravity = new Float3(0f, -9.81f, 0f);
            return s;
        }

        /// <summary>Row titles.</summary>
        public static readonly string[] RowNames = { "fracture cord (no gravity)", "with gravity" };

        /// <summary>The census of the tube and caps of <paramref name="run"/>'s current mesh.</summary>
        public static WindingCensus Census(FigureRun run, out Float3 centre)
        {
            var sim = run.Setup.Simulation;
            var vertices = new TubeVertex[sim.GetVertexCount()];
            var indices = new int[sim.GetIndexCount()];
            var update = sim.FillMesh(vertices, indices);
            var census = WindingCensus.Of(vertices, indices, 0, update.TubeIndexCount);
            // the folds of the piece on the fixed end (rest arc before the cut), else its broken end
            int j = run.FirstBrokenSegment();
            float cutV = j < 0 ? float.MaxValue : (float)((j + 0.5) * sim.Rope.RestLengths[0] * sim.MeshSettings.VPerMetre);
            Float3 sum = Float3.Zero;
            int found = 0;
            for (int k = 0; k < update.TubeIndexCount; k += 3)
            {
                TubeVertex a = vertices[indices[k]], b = vertices[indices[k + 1]], c = vertices[indices[k + 2]];
                if (a.V > cutV || !WindingCensus.IsInverted(a, b, c, out _, out _)) continue;
                sum = sum + new Float3(a.PX + b.PX + c.PX, a.PY + b.PY + c.PY, a.PZ + b.PZ + c.PZ) * (1f / 3f);
                found++;
            }
            centre = found > 0 ? sum * (1f / found) + sim.Rope.Origin : (j >= 0 ? run.Setup.Rope.GetPosition(j) : run.DefectPosition());
            return census;
        }

        /// <summary>Shortest intact segment against its rest length and the sharpest turn (degrees) between neighbouring intact segments.</summary>
        public static (double ShortestRatio, double SharpestTurn) Shape(FigureRun run)
        {
            var rope = run.Setup.Rope;
            var broken = rope.BrokenSegments;
            double shortest = double.MaxValue, sharpest = 0.0;
            for (int i = 0; i < rope.SegmentCount; i++)
            {
                if (broken[i]) continue;
                var d = rope.GetPosition(i + 1) - rope.GetPosition(i);
                shortest = Math.Min(shortest, d.Length / rope.RestLengths[i]);
                if (i + 1 < rope.SegmentCount && !broken[i + 1])
                {
                    var e = rope.GetPosition(i + 2) - rope.GetPosition(i + 1);
                    double cos = Float3.Dot(d.NormalizedOr(Float3.Zero), e.NormalizedOr(Float3.Zero));
                    sharpest = Math.Max(sharpest, Math.Acos(Math.Max(-1.0, Math.Min(1.0, cos))) * 180.0 / Math.PI);
                }
            }
            return (shortest, sharpest);
        }

        /// <summary>The figure: two rows of <see cref="Steps"/> panels.</summary>
        public static DocumentationFigure Build(float scale = 1f)
        {
            int width = Px(1000, scale), panel = Px(230, scale), gap = (width - Steps.Length * panel) / (Steps.Length + 1);
            int rowHeight = panel + Px(56, scale);
            var figure = Frame(FileName, Float3.Zero, Yaw, Pitch, PixelsPerMetre * scale, width, 2 * rowHeight);
            var texture = FigureTexture.PackageBurr();
            for (int row = 0; row < 2; row++)
            {
                var run = new FigureRun(Row(row));
                run.AdvanceUntil(r => r.Setup.Simulation.IsBroken, 2.0);
                double breakTime = run.Time;
                float radius = run.Setup.Simulation.RestRadius;
                var counts = new List<string>();
                for (int step = 0; step <= Math.Max(CensusSteps, Steps[Steps.Length - 1]); step++)
                {
                    if (step > 0) run.Step();
                    var census = Census(run, out var centre);
                    figure.Numbers[F("row {0} step {1} inverted", row, step)] = census.Inverted;
                    if (step <= CensusSteps) counts.Add(census.Inverted.ToString(System.Globalization.CultureInfo.InvariantCulture));
                    int k = Array.IndexOf(Steps, step);
                    if (k < 0) continue;
                    var view = new OrthographicView(centre, Yaw, Pitch, PixelsPerMetre * scale, panel, panel);
                    var scene = new FigureScene();
                    scene.AddRopeCulled(run.Setup.Simulation, RopeColor, view.TowardCamera, InvertedColor, Float3.Zero, texture);
                    var (shortest, sharpest) = Shape(run);
                    double area = census.InvertedArea / (radius * radius);
                    figure.Panels.Add(new FigureInset
                    {
                        Scene = scene,
                        View = view,
                        Position = new SKPoint(gap + k * (panel + gap), 8 + row * rowHeight),
                        Caption = F("step {0}: {1} inverted, {2:0.0} R²", step, census.Inverted, area),
                    });
                    figure.Numbers[F("row {0} step {1} inverted area (R²)", row, step)] = area;
                    figure.Numbers[F("row {0} step {1} shortest segment / rest", row, step)] = shortest;
                    figure.Numbers[F("row {0} step {1} sharpest turn (deg)", row, step)] = sharpest;
                }
                figure.Numbers[F("row {0} break time (s)", row)] = breakTime;
                figure.Numbers[F("row {0} rest radius R (mm)", row)] = radius * 1000;
                Tag(figure, 8, row * rowHeight + panel + Px(30, scale), F("{0}: inverted tube triangles at steps 0–{1} after the break: {2}", RowNames[row], CensusSteps, string.Join(", ", counts)));
            }
            Caption(figure, "Slack folds after a break (fracture scenario, BDF2, 90 Hz × 4): a GPU's view (back faces culled), tube triangles wound\n" +
                            "against their normals in red, around the folds of the fixed piece; areas in R² (rest radius 10 mm). Fold tips (issue 17).");
            return figure;
        }
    }
}
