using System;
using HookeRope.Mathematics;
using static HookeRope.Lab.Figures.Paper.PaperFigures;

namespace HookeRope.Lab.Figures.Paper
{
    /// <summary>
    /// Fig. 8, the whole sequence: the built-in "necking" cord with fracture on, pulled until it breaks, drawn at three
    /// moments (uniform thinning before the onset, the neck one step before the break, the two pieces at the step of the break),
    /// 60 cm around the defect, one row each.
    /// </summary>
    public static class SequenceFigure
    {
        /// <summary>File name.</summary>
        public const string FileName = "paper-fig8-sequence.png";
        /// <summary>World distance between rows (m).</summary>
        public const float RowSpacing = 0.05f;
        /// <summary>Scale at size 1 (px per metre).</summary>
        public const float PixelsPerMetre = 1650f;
        /// <summary>Host steps drawn after the break (0: the step of the break; the pieces recoil out of the window within a few steps).</summary>
        public const int StepsAfterBreak = 0;

        /// <summary>Centre of row <paramref name="row"/> (m).</summary>
        public static Float3 RowCenter(int row) => new Float3(0f, -row * RowSpacing, 0f);

        /// <summary>Strain of the defect segment at which it breaks (the neck-radius criterion may come first).</summary>
        public const double BreakStrain = 1.0;

        /// <summary>The scenario: "necking" pulled on to 7 s, fracture on at <see cref="BreakStrain"/> (the default 0.6 is reached at the neck's onset).</summary>
        public static HookeRope.Lab.Scenarios.Scenario BreakingNeck()
        {
            var s = PullLonger(Scenario("necking"), 7.0);
            s.Rope.Fracture = true;
            s.Rope.BreakStrain = BreakStrain;
            return s;
        }

        /// <summary>The figure; Numbers hold the three moments (s) and radii.</summary>
        public static DocumentationFigure Build(float scale = 1f)
        {
            float ppm = PixelsPerMetre * scale;
            var figure = Frame(FileName, RowCenter(1), 0f, 15f, ppm, Px(1000, scale), Px(340, scale));
            var probe = new FigureRun(BreakingNeck());
            probe.AdvanceUntil(r => r.Setup.Simulation.RadiusModel.IsNecking || r.Setup.Simulation.IsBroken, 7.0);
            double onset = probe.Time;
            probe.AdvanceUntil(r => r.Setup.Simulation.IsBroken, 7.0);
            double broken = probe.Time;
            double dt = probe.Scenario.HostStep;
            var moments = new[] { 0.6 * onset, Math.Max(onset, broken - dt), broken + StepsAfterBreak * dt };
            var names = new[] { "uniform", "neck", "break" };
            Float3 centre = Float3.Zero;
            for (int k = 0; k < 3; k++)
            {
                var run = new FigureRun(BreakingNeck()).AdvanceTo(moments[k]);
                var sim = run.Setup.Simulation;
                if (k < 2) centre = run.DefectPosition();
                else centre = BreakCentre(run);
                figure.Scene.AddRope(sim, RopeColor, RowCenter(k) - centre, FigureTexture.PackageBurr());
                figure.Numbers[F("row {0} time (s)", k)] = run.Time;
                figure.Numbers[F("row {0} min radius (mm)", k)] = sim.MinRadius * 1000;
                var (_, y, _) = figure.View.Project(RowCenter(k));
                Tag(figure, 8, y - sim.RestRadius * ppm - 30,
                    F("{0}: t = {1:0.000} s, l/L = {2:0.00}, min r = {3:0.00} mm", names[k], run.Time, PoissonSweepFigure.Stretch(run), sim.MinRadius * 1000));
            }
            figure.Numbers["onset (s)"] = onset;
            figure.Numbers["break (s)"] = broken;
            Caption(figure, F("Fig. 8  Uniform → neck → break (necking scenario, R = 10 mm, r_min = 0.75 R, break at strain {0:0.#} or neck radius {1:0.##} R):\n", BreakStrain, probe.Scenario.Rope.BreakRadiusFraction) +
                            F("60 cm around the defect before the onset, one step before the break and at the step of the break (t = {0:0.000} s).", broken + StepsAfterBreak * dt));
            return figure;
        }

        /// <summary>Midpoint between the two broken ends (m), else the defect.</summary>
        public static Float3 BreakCentre(FigureRun run)
        {
            int j = run.FirstBrokenSegment();
            return j >= 0 ? Float3.Lerp(run.Setup.Rope.GetPosition(j), run.Setup.Rope.GetPosition(j + 1), 0.5f) : run.DefectPosition();
        }
    }
}
