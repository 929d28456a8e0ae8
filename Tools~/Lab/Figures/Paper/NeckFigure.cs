using HookeRope.Mathematics;
using static HookeRope.Lab.Figures.Paper.PaperFigures;

namespace HookeRope.Lab.Figures.Paper
{
    /// <summary>
    /// Fig. 6, the neck: the built-in "necking" cord (1 m, R 10 mm, ν 0.5, Zone neck at the defect, pulled on at its
    /// speed past the run's end) with r_min = 0.8, 0.75 and 0.7 R, each drawn <see cref="AfterOnset"/> after its own neck
    /// onset (the same progress of the neck), 40 cm around each neck, one row each at the same scale.
    /// </summary>
    public static class NeckFigure
    {
        /// <summary>File name.</summary>
        public const string FileName = "paper-fig6-neck.png";
        /// <summary>Neck onset radii r_min / R of the rows.</summary>
        public static readonly double[] Fractions = { 0.8, 0.75, 0.7 };
        /// <summary>World distance between rows (m).</summary>
        public const float RowSpacing = 0.045f;
        /// <summary>Scale at size 1 (px per metre).</summary>
        public const float PixelsPerMetre = 2500f;
        /// <summary>Time after each rope's neck onset (s) at which it is drawn (the pull adds 0.225 m/s).</summary>
        public const double AfterOnset = 0.3;
        /// <summary>Longest pull (s).</summary>
        public const double Limit = 7.0;

        /// <summary>The run of one row: the necking scenario with onset radius <paramref name="fraction"/>·R, at <see cref="AfterOnset"/> after the onset.</summary>
        public static FigureRun NeckRun(double fraction)
        {
            var s = PullLonger(Scenario("necking"), Limit);
            s.Rope.NeckRadiusFraction = fraction;
            var run = new FigureRun(s);
            run.AdvanceUntil(r => r.Setup.Simulation.RadiusModel.IsNecking, Limit);
            return run.AdvanceTo(run.Time + AfterOnset);
        }

        /// <summary>Centre of row <paramref name="row"/>: where that rope's defect is drawn (m).</summary>
        public static Float3 RowCenter(int row) => new Float3(0f, -row * RowSpacing, 0f);

        /// <summary>The figure; Numbers hold per row the model's neck (waist) radius and its expected drawn width (px).</summary>
        public static DocumentationFigure Build(float scale = 1f)
        {
            float ppm = PixelsPerMetre * scale;
            var figure = Frame(FileName, RowCenter(1), 0f, 15f, ppm, Px(1000, scale), Px(340, scale));
            for (int k = 0; k < Fractions.Length; k++)
            {
                var run = NeckRun(Fractions[k]);
                var sim = run.Setup.Simulation;
                figure.Scene.AddRope(sim, RopeColor, RowCenter(k) - run.DefectPosition());
                figure.Numbers[F("row {0} waist radius (mm)", k)] = sim.MinRadius * 1000;
                figure.Numbers[F("row {0} waist width (px)", k)] = 2 * sim.MinRadius * ppm;
                var (_, y, _) = figure.View.Project(RowCenter(k));
                Tag(figure, 8, y - sim.RestRadius * ppm - 30,
                    F("r_min = {0:0.##} R: waist {1:0.00} mm at t = {2:0.00} s, l/L = {3:0.00}", Fractions[k], sim.MinRadius * 1000, run.Time, PoissonSweepFigure.Stretch(run)));
            }
            Caption(figure, "Fig. 6  Neck (necking scenario, R = 10 mm, ν = 0.5, Zone neck at the defect, in the middle): onset radius\n" +
                            F("r_min = 0.8, 0.75, 0.7 R from top to bottom, each {0:0.0} s after its own onset, centred on its defect.", AfterOnset));
            return figure;
        }
    }
}
