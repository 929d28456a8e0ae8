using HookeRope.Mathematics;
using SkiaSharp;
using static HookeRope.Lab.Figures.Paper.PaperFigures;

namespace HookeRope.Lab.Figures.Paper
{
    /// <summary>
    /// Fig. 7, burred ends: the built-in "fracture" cord pulled until it breaks, with 8, 16 and 32 radial segments,
    /// the two broken ends seen obliquely in one panel each: both pieces keep their half of the neck and end at its waist
    /// in the core's burr strands, with the package's burr texture.
    /// </summary>
    public static class BurrFigure
    {
        /// <summary>File name.</summary>
        public const string FileName = "paper-fig7-burr.png";
        /// <summary>Radial segments of the panels.</summary>
        public static readonly int[] RadialCounts = { 8, 16, 32 };
        /// <summary>Scale at size 1 (px per metre).</summary>
        public const float PixelsPerMetre = 4200f;
        /// <summary>Camera yaw (degrees): from the side of the break, so the cut faces the camera.</summary>
        public const float Yaw = -60f;
        /// <summary>Camera pitch (degrees).</summary>
        public const float Pitch = 20f;

        /// <summary>The run of one panel, stopped at the step of the break (at most 2 s).</summary>
        public static FigureRun BrokenRun(int radialSegments)
        {
            var run = new FigureRun(Scenario("fracture", radialSegments));
            run.AdvanceUntil(r => r.Setup.Simulation.IsBroken, 2.0);
            return run;
        }

        /// <summary>Where the rope parted: between the two broken ends (m), else the defect.</summary>
        public static Float3 BrokenEnd(FigureRun run) => SequenceFigure.BreakCentre(run);

        /// <summary>The figure: three panels; Numbers hold per panel the burr triangles drawn and the core's burr index count / 3.</summary>
        public static DocumentationFigure Build(float scale = 1f)
        {
            int width = Px(1000, scale), panel = Px(310, scale), gap = (width - 3 * panel) / 4;
            var figure = Frame(FileName, Float3.Zero, Yaw, Pitch, PixelsPerMetre * scale, width, panel + 40);
            var texture = FigureTexture.PackageBurr();
            for (int k = 0; k < RadialCounts.Length; k++)
            {
                var run = BrokenRun(RadialCounts[k]);
                var scene = new FigureScene();
                var update = scene.AddRope(run.Setup.Simulation, RopeColor, Float3.Zero, texture);
                var end = BrokenEnd(run);
                figure.Panels.Add(new FigureInset
                {
                    Scene = scene,
                    View = new OrthographicView(end, Yaw, Pitch, PixelsPerMetre * scale, panel, panel),
                    Position = new SKPoint(gap + k * (panel + gap), 8),
                    Caption = F("{0} radial segments: {1} strand triangles", RadialCounts[k], scene.BurrTriangleCount),
                });
                figure.Numbers[F("panel {0} burr triangles", k)] = scene.BurrTriangleCount;
                figure.Numbers[F("panel {0} core burr indices / 3", k)] = update.BurrIndexCount / 3;
                figure.Numbers[F("panel {0} break time (s)", k)] = run.Time;
            }
            Caption(figure, "Fig. 7  Burred ends (fracture scenario, R = 10 mm, break strain 0.5) at the step of the break, 8/16/32 radial segments:\n" +
                            "both pieces keep half the neck and end at its waist in the core's burr strands, with the mipmapped burr texture.");
            return figure;
        }
    }
}
