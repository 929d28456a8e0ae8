using HookeRope.Mathematics;
using static HookeRope.Lab.Figures.Paper.PaperFigures;

namespace HookeRope.Lab.Figures.Paper
{
    /// <summary>
    /// Fig. 5, the Poisson sweep: the built-in "poisson-sweep" cord (1 m, R 10 mm) at rest and pulled to l/L = 2 with
    /// ν = 0, 0.25 and 0.5, the middle 40 cm of each drawn side by side (one row each, same scale): thinner as ν grows.
    /// </summary>
    public static class PoissonSweepFigure
    {
        /// <summary>File name.</summary>
        public const string FileName = "paper-fig5-poisson-sweep.png";
        /// <summary>Poisson ratios of the rows under the rest row.</summary>
        public static readonly double[] Ratios = { 0.0, 0.25, 0.5 };
        /// <summary>World distance between rows (m).</summary>
        public const float RowSpacing = 0.045f;
        /// <summary>Time of the stretched rows (s): the keyframed end has reached 2 m.</summary>
        public const double StretchedTime = 4.0;
        /// <summary>Scale at size 1 (px per metre).</summary>
        public const float PixelsPerMetre = 2500f;
        /// <summary>Camera pitch (degrees) showing the facets' shading.</summary>
        public const float Pitch = 15f;

        /// <summary>Centre of row <paramref name="row"/> (0 = rest) on the window's centre line (m).</summary>
        public static Float3 RowCenter(int row) => new Float3(1f, -row * RowSpacing, 0f);

        /// <summary>The figure; Numbers hold per row the model radius (mm) and the expected drawn width (px).</summary>
        public static DocumentationFigure Build(float scale = 1f)
        {
            float ppm = PixelsPerMetre * scale;
            var figure = Frame(FileName, RowCenter(0) + (RowCenter(Ratios.Length) - RowCenter(0)) * 0.5f, 0f, Pitch, ppm, Px(1000, scale), Px(440, scale));
            var rest = new FigureRun(Scenario("poisson-sweep"));
            // the rest rope spans 0 … 1 m: shift it by 0.5 m so its middle is in the window as well
            AddRow(figure, rest, 0, new Float3(0.5f, 0f, 0f), "rest, l/L = 1", ppm);
            for (int k = 0; k < Ratios.Length; k++)
            {
                var s = Scenario("poisson-sweep");
                s.Rope.PoissonRatio = Ratios[k];
                var run = new FigureRun(s).AdvanceTo(StretchedTime);
                AddRow(figure, run, k + 1, Float3.Zero, F("ν = {0:0.##}, l/L = {1:0.00}", Ratios[k], Stretch(run)), ppm);
            }
            Caption(figure, "Fig. 5  Poisson sweep (poisson-sweep scenario, R = 10 mm, 1 m pulled to 2 m in 4 s): the middle 40 cm of each rope at\n" +
                            "the same stretch, ν = 0, 0.25, 0.5 under the rest rope; r = R·√(1 + 2ν(L/l − 1)) (eq. 16), ν = 0.5 keeps the volume.");
            return figure;
        }

        /// <summary>Current length over rest length of the run's rope.</summary>
        public static double Stretch(FigureRun run) => 1.0 + run.Setup.Simulation.Readouts.Strain;

        static void AddRow(DocumentationFigure figure, FigureRun run, int row, Float3 shift, string label, float ppm)
        {
            var sim = run.Setup.Simulation;
            figure.Scene.AddRope(sim, RopeColor, shift + new Float3(0f, -row * RowSpacing, 0f));
            float radius = sim.RadiusModel.SegmentRadii[sim.RadiusModel.SegmentCount / 2];
            figure.Numbers[F("row {0} radius (mm)", row)] = radius * 1000;
            figure.Numbers[F("row {0} width (px)", row)] = 2 * radius * ppm;
            var (x, y, _) = figure.View.Project(RowCenter(row));
            float rpx = sim.RestRadius * ppm;
            Tag(figure, 8, y - rpx - 30, F("{0}: r = {1:0.00} mm", label, radius * 1000));
        }
    }
}
