using HookeRope.Mathematics;
using SkiaSharp;
using static HookeRope.Lab.Figures.Paper.PaperFigures;

namespace HookeRope.Lab.Figures.Paper
{
    /// <summary>
    /// Fig. 9a, collision bend: the built-in "collision-bend" cord (2 m, R 5 mm) pulled down over a frictionless bar of
    /// radius 0.1 m, seen along the bar's axis at the end of the run, with a zoomed detail of the wrap. The bar is drawn
    /// from the rope's plane backwards (a section), so any part of the tube inside the bar would show in front of it.
    /// </summary>
    public static class CollisionBendFigure
    {
        /// <summary>File name.</summary>
        public const string FileName = "paper-fig9a-collision-bend.png";
        /// <summary>Scale at size 1 (px per metre).</summary>
        public const float PixelsPerMetre = 420f;
        /// <summary>Scale of the detail at size 1 (px per metre).</summary>
        public const float DetailPixelsPerMetre = 2400f;
        /// <summary>Moment of the picture (s): the end of the scenario.</summary>
        public const double Time = 3.0;

        /// <summary>Centre of the bar's section (m).</summary>
        public static Float3 BarCenter(HookeRope.Lab.Scenarios.Scenario s) => Float3.Lerp(s.Colliders[0].Center, s.Colliders[0].PointB, 0.5f);

        /// <summary>The figure; Numbers hold the bar and rope radii and the deepest particle (mm below the bar's surface).</summary>
        public static DocumentationFigure Build(float scale = 1f)
        {
            var run = new FigureRun(Scenario("collision-bend")).AdvanceTo(Time);
            var s = run.Scenario;
            var bar = s.Colliders[0];
            var centre = BarCenter(s);
            float barRadius = (float)bar.Radius;
            var figure = Frame(FileName, centre + new Float3(0f, -0.2f, 0f), 0f, 0f, PixelsPerMetre * scale, Px(1000, scale), Px(420, scale));
            figure.Scene.AddCylinder(centre, centre + new Float3(0f, 0f, 0.5f), barRadius, PropColor);
            figure.Scene.AddRope(run.Setup.Simulation, RopeColor);
            int detail = Px(300, scale), detailHeight = Px(190, scale);
            figure.Inset = new FigureInset
            {
                View = new OrthographicView(centre + new Float3(0f, barRadius * 0.7f, 0f), 0f, 0f, DetailPixelsPerMetre * scale, detail, detailHeight),
                Position = new SKPoint((figure.View.Width - detail) / 2f, Px(190, scale)),
                Caption = F("detail, {0:0}× the scale", DetailPixelsPerMetre / PixelsPerMetre),
            };
            double deepest = 0;
            for (int i = 0; i < run.Setup.Rope.ParticleCount; i++)
            {
                var p = run.Setup.Rope.GetPosition(i) - centre;
                double inside = barRadius + run.Setup.Simulation.ParticleRadii[i] - new Float3(p.X, p.Y, 0f).Length;
                if (inside > deepest) deepest = inside;
            }
            figure.Numbers["bar radius (mm)"] = barRadius * 1000;
            figure.Numbers["rope radius (mm)"] = run.Setup.Simulation.RestRadius * 1000;
            figure.Numbers["deepest particle overlap (mm)"] = deepest * 1000;
            figure.Numbers["top tension (N)"] = run.Setup.Simulation.Readouts.TopTension;
            Tag(figure, 8, 8, F("t = {0:0.0} s, tension {1:0} N", run.Time, run.Setup.Simulation.Readouts.TopTension));
            Caption(figure, "Fig. 9a  Collision bend (collision-bend scenario, 2 m cord, R = 5 mm, E·A = 1 kN) over a frictionless bar of radius 0.1 m,\n" +
                            "seen along the bar, whose section is drawn at the rope's plane: the tube wraps the bar without entering it.");
            return figure;
        }
    }
}
