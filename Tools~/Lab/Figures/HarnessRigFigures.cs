using System;
using System.Collections.Generic;
using System.Globalization;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using HookeRope.Mathematics;
using SkiaSharp;

namespace HookeRope.Lab.Figures
{
    /// <summary>
    /// The three figures of the manual's "Drop the rope onto a harness rig" section, each drawn from the core's tube mesh
    /// of a real simulation of the package-default rope (2 m, R 8 mm, E·A 30.2 kN, 24 segments, exact chain 8×1):
    /// (1) the rig and the prefab before the drop; (2) after self-wiring, the rope relaxed into its static shape between
    /// the snapped anchor and the D-ring; (3) the fall arrest at the step of peak arrest force (hatch open, 100 kg worker).
    /// </summary>
    public static class HarnessRigFigures
    {
        /// <summary>Figure width (px).</summary>
        public const int Width = 900;
        /// <summary>Figure height (px).</summary>
        public const int Height = 700;
        /// <summary>Scale (px per metre): the default 16 mm rope is 2.4 px wide.</summary>
        public const float PixelsPerMetre = 150f;
        /// <summary>The fixed step the fall is simulated with (s): the step the defaults were validated at.</summary>
        public const double FallStep = 1.0 / 90.0;
        /// <summary>Relaxation of the static shape: the editor's sag preview (1/60 s steps, velocities × 0.85, 6 s).</summary>
        const double RelaxStep = 1.0 / 60.0, RelaxSeconds = 6.0;
        const float RelaxVelocityScale = 0.85f;

        /// <summary>File names, in order.</summary>
        public static readonly string[] FileNames = { "harness-1-before-drop.png", "harness-2-wired.png", "harness-3-arrest.png" };

        static readonly Float3 PrefabAnchor = new Float3(-1.25f, 2.8f, 0.02f);

        /// <summary>All three figures.</summary>
        public static List<DocumentationFigure> All() => new List<DocumentationFigure> { BeforeDrop(), Wired(), Arrest() };

        static OrthographicView View(float centerY) =>
            new OrthographicView(new Float3(-0.35f, centerY, 0f), 32f, 14f, PixelsPerMetre, Width, Height);

        /// <summary>The package-default rope between two points (defaults of RopeParameters, through the lab's scenario).</summary>
        public static Scenario DefaultRope(AttachmentSpec start, AttachmentSpec end, InitialShape shape, double step)
        {
            return new Scenario
            {
                Name = "harness-figure",
                HostStep = step,
                Start = start,
                End = end,
                Initial = new InitialSpec { Shape = shape },
            };
        }

        /// <summary>(1) Before the drop: the prefab (Start = its Anchor child, End empty) drawn straight, as in edit mode.</summary>
        public static DocumentationFigure BeforeDrop()
        {
            var figure = new DocumentationFigure { FileName = FileNames[0], View = View(1.6f) };
            var s = DefaultRope(AttachmentSpec.FixedAt(PrefabAnchor),
                new AttachmentSpec { Kind = AttachmentKind.Free, Position = PrefabAnchor - new Float3(0f, 2f, 0f) }, InitialShape.Straight, FallStep);
            var setup = ScenarioRunner.Build(s);
            AddRig(figure.Scene, HarnessRig.DRing, hatchClosed: true);
            HarnessRig.AddAnchor(figure.Scene, PrefabAnchor);
            figure.Scene.AddRope(setup.Simulation, HarnessRig.RopeOrange);
            var bottom = setup.Rope.GetPosition(setup.Rope.ParticleCount - 1);
            figure.Numbers["rope length (m)"] = (bottom - PrefabAnchor).Length;
            figure.Annotations.Add(new FigureCaption { Text = "1  Before the drop: the ElasticRope prefab and a harness rig" });
            figure.Annotations.Add(new FigureLabel { Point = PrefabAnchor, Offset = new SKPoint(-250, -40), Text = "prefab's child 'Anchor'\n(Start > Point)" });
            figure.Annotations.Add(new FigureLabel { Point = PrefabAnchor - new Float3(0f, 1.2f, 0f), Offset = new SKPoint(-230, 0), Text = "ElasticRope prefab, 2 m\nEnd: empty" });
            figure.Annotations.Add(new FigureLabel { Point = new Float3(1.2f, HarnessRig.BeamUnderside + 0.2f, 0f), Offset = new SKPoint(-60, 40), Text = "Beam (BoxCollider)" });
            figure.Annotations.Add(new FigureLabel { Point = HarnessRig.DRing, Offset = new SKPoint(60, -60), Text = "child 'D-ring'" });
            figure.Annotations.Add(new FigureLabel { Point = new Float3(0.2f, 0.9f, 0.2f), Offset = new SKPoint(90, 10), Text = "Worker: Rigidbody 100 kg" });
            figure.Annotations.Add(new FigureArrow
            {
                From = PrefabAnchor + new Float3(0.15f, -0.5f, 0f), To = new Float3(-0.12f, 1.4f, 0f), Dashed = true,
                Color = new SKColor(40, 90, 200), Text = "drag onto the Worker", TextOffset = new SKPoint(10, -34),
            });
            return figure;
        }

        /// <summary>The settled shape of the default rope pinned at the snapped anchor and the D-ring (the sag preview's relaxation).</summary>
        public static RopeSetup RelaxedWired()
        {
            var s = DefaultRope(AttachmentSpec.FixedAt(HarnessRig.SnappedAnchor), AttachmentSpec.FixedAt(HarnessRig.DRing), InitialShape.Slack, RelaxStep);
            var setup = ScenarioRunner.Build(s);
            int steps = (int)Math.Ceiling(RelaxSeconds / RelaxStep);
            for (int k = 0; k < steps; k++)
            {
                setup.Step((float)RelaxStep);
                for (int i = 0; i < setup.Rope.ParticleCount; i++) setup.Rope.SetVelocity(i, setup.Rope.GetVelocity(i) * RelaxVelocityScale);
            }
            return setup;
        }

        /// <summary>(2) After self-wiring: Start on the snapped anchor, End on the D-ring, the slack rope in its static shape.</summary>
        public static DocumentationFigure Wired()
        {
            var figure = new DocumentationFigure { FileName = FileNames[1], View = View(1.6f) };
            var setup = RelaxedWired();
            AddRig(figure.Scene, HarnessRig.DRing, hatchClosed: true);
            HarnessRig.AddAnchor(figure.Scene, HarnessRig.SnappedAnchor);
            figure.Scene.AddRope(setup.Simulation, HarnessRig.RopeOrange);
            double lowest = double.MaxValue;
            for (int i = 0; i < setup.Rope.ParticleCount; i++) lowest = Math.Min(lowest, setup.Rope.GetPosition(i).Y);
            var readouts = setup.Simulation.Readouts;
            figure.Numbers["slack (m)"] = 2.0 - HarnessRig.Gap;
            figure.Numbers["loop below the D-ring (m)"] = HarnessRig.DRingHeight - lowest;
            figure.Numbers["TopTension (N)"] = readouts.TopTension;
            figure.Annotations.Add(new FigureCaption { Text = "2  After self-wiring (Reset or Awake): static shape of the default rope" });
            figure.Annotations.Add(new FigureLabel { Point = HarnessRig.SnappedAnchor, Offset = new SKPoint(50, 30), Text = "Start > Point = 'ElasticRope Anchor'\n(new, at the root) on the beam:\nthe ray up from the D-ring hit it" });
            figure.Annotations.Add(new FigureArrow
            {
                From = HarnessRig.DRing + new Float3(0.06f, 0.05f, 0f), To = HarnessRig.SnappedAnchor + new Float3(0.06f, -0.03f, 0f),
                Dashed = true, Color = new SKColor(40, 90, 200), Width = 1.5f,
                Text = F("upward ray: hit at {0:0.00} m (< rest length 2 m)", HarnessRig.Gap), TextOffset = new SKPoint(14, -110),
            });
            figure.Annotations.Add(new FigureLabel { Point = HarnessRig.DRing, Offset = new SKPoint(70, 30), Text = "End > Body = Worker (Rigidbody)\nEnd > Point = 'D-ring'" });
            figure.Annotations.Add(new FigureLabel
            {
                Point = new Float3(0f, (float)lowest, HarnessRig.DRingZ), Offset = new SKPoint(-300, -110),
                Text = F("{0:0.00} m of slack hangs folded,\n{1:0.00} m below the D-ring (detail)", 2.0 - HarnessRig.Gap, HarnessRig.DRingHeight - lowest),
            });
            figure.Inset = Detail(HarnessRig.DRing - new Float3(0f, 0.06f, 0f), new SKPoint(24, 370));
            return figure;
        }

        /// <summary>A ×4 detail (600 px/m, 260 × 290 px) around <paramref name="center"/>, placed at <paramref name="position"/>.</summary>
        static FigureInset Detail(Float3 center, SKPoint position) => new FigureInset
        {
            View = new OrthographicView(center, 32f, 14f, PixelsPerMetre * 4, 260, 290),
            Position = position,
            Caption = "detail ×4 (D-ring)",
        };

        /// <summary>The fall of <see cref="Arrest"/>: the wired rope, a 100 kg load released at the D-ring from the static shape <paramref name="relaxed"/> (<see cref="RelaxedWired"/>).</summary>
        public static RopeSetup FallSetup(RopeSetup relaxed)
        {
            var s = DefaultRope(AttachmentSpec.FixedAt(HarnessRig.SnappedAnchor),
                new AttachmentSpec { Kind = AttachmentKind.Body, Mass = HarnessRig.WorkerMass, Position = HarnessRig.DRing }, InitialShape.Slack, FallStep);
            var setup = ScenarioRunner.Build(s);
            for (int i = 0; i < setup.Rope.ParticleCount; i++)
            {
                setup.Rope.SetPosition(i, relaxed.Rope.GetPosition(i));
                setup.Rope.SetVelocity(i, Float3.Zero);
            }
            setup.Simulation.Readouts.ArrestLoad = setup.EndLoad;
            return setup;
        }

        /// <summary>Steps of <see cref="FallStep"/> from the release (<see cref="FallSetup"/> of <paramref name="relaxed"/>) to the largest arrest force, and that force (N), within 3 s.</summary>
        public static int StepsToPeak(RopeSetup relaxed, out float peak)
        {
            var setup = FallSetup(relaxed);
            int best = 0;
            peak = 0f;
            for (int k = 1; k <= (int)(3.0 / FallStep); k++)
            {
                setup.Step((float)FallStep);
                if (setup.Simulation.Readouts.ArrestForce > peak)
                {
                    peak = setup.Simulation.Readouts.ArrestForce;
                    best = k;
                }
            }
            return best;
        }

        /// <summary>Analytic peak force (N) for the rig's free fall of rest length − gap on the default rope (massless lanyard).</summary>
        public static double AnalyticPeak()
        {
            var rope = new RopeSpec();
            return PhysicsChecks.FallArrestForce(HarnessRig.WorkerMass, 9.81, rope.ResolvedAxialStiffness / rope.RestLength, rope.RestLength - HarnessRig.Gap);
        }

        /// <summary>(3) The fall arrest at the step of peak arrest force, with the read-outs.</summary>
        public static DocumentationFigure Arrest()
        {
            var relaxed = RelaxedWired();
            int steps = StepsToPeak(relaxed, out _);
            var setup = FallSetup(relaxed);
            for (int k = 0; k < steps; k++) setup.Step((float)FallStep);
            var readouts = setup.Simulation.Readouts;
            var dRing = setup.Rope.GetLoadPosition(setup.EndLoad);
            var figure = new DocumentationFigure { FileName = FileNames[2], View = View(1.15f) };
            AddRig(figure.Scene, dRing, hatchClosed: false);
            HarnessRig.AddAnchor(figure.Scene, HarnessRig.SnappedAnchor);
            figure.Scene.AddRope(setup.Simulation, HarnessRig.RopeOrange);
            double analytic = AnalyticPeak();
            figure.Numbers["PeakArrestForce (N)"] = readouts.PeakArrestForce;
            figure.Numbers["analytic peak (N)"] = analytic;
            figure.Numbers["time of peak (s)"] = steps * FallStep;
            figure.Numbers["Strain"] = readouts.Strain;
            figure.Numbers["drop of the D-ring (m)"] = HarnessRig.DRingHeight - dRing.Y;
            figure.Annotations.Add(new FigureCaption
            {
                Text = F("3  Fall arrest, the step of peak force (t = {0:0.000} s after the release, 1/90 s steps)", steps * FallStep),
            });
            float arrowLength = readouts.ArrestForce / 10000f;  // 1 m per 10 kN
            figure.Annotations.Add(new FigureArrow
            {
                From = dRing + new Float3(0.12f, 0f, 0f), To = dRing + new Float3(0.12f, arrowLength, 0f), Color = new SKColor(190, 20, 50), Width = 3f,
                Text = F("PeakArrestForce = {0:0} N (largest substep)\nArrestForce = {4:0} N (mean of this step)\nanalytic Mg + √((Mg)² + 2Mg·k·h) = {1:0} N\n(h = {2:0.00} m slack, k = E·A/L)\nMeetsEn355 = {3}  (≤ 6 kN)",
                    readouts.PeakArrestForce, analytic, 2.0 - HarnessRig.Gap, readouts.PeakArrestForce <= 6000f ? "true" : "false", readouts.ArrestForce),
                TextOffset = new SKPoint(20, -10),
            });
            figure.Annotations.Add(new FigureLabel
            {
                Point = Float3.Lerp(HarnessRig.SnappedAnchor, dRing, 0.4f), Offset = new SKPoint(-430, -30),
                Text = F("Strain = {0:0.0} %   Elongation = {1:0.000} m\nTopTension = {2:0} N   MinRadius = {3:0.00} mm", readouts.Strain * 100, readouts.Elongation, readouts.TopTension, readouts.MinRadius * 1000),
            });
            figure.Annotations.Add(new FigureLabel { Point = new Float3(0.4f, 0f, -0.4f), Offset = new SKPoint(60, 40), Text = "hatch open: the worker fell" });
            return figure;
        }

        static void AddRig(FigureScene scene, Float3 dRing, bool hatchClosed)
        {
            HarnessRig.AddBeam(scene);
            HarnessRig.AddFloor(scene, hatchClosed);
            HarnessRig.AddWorker(scene, dRing);
        }

        static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }
}
