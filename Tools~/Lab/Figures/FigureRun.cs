using System;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using HookeRope.Mathematics;

namespace HookeRope.Lab.Figures
{
    /// <summary>
    /// A scenario stepped by hand for a figure: the rope of <see cref="ScenarioRunner.Build"/>, keyframed pins moved
    /// to their targets before every host step, exactly as <see cref="ScenarioRunner.Run"/> does, stopped at chosen moments.
    /// </summary>
    public sealed class FigureRun
    {
        int steps;

        /// <summary>The scenario being stepped.</summary>
        public Scenario Scenario { get; }
        /// <summary>The rope, its pins and its <see cref="HookeRope.RopeSimulation"/>.</summary>
        public RopeSetup Setup { get; }
        /// <summary>Simulated time (s).</summary>
        public double Time => steps * Scenario.HostStep;

        /// <summary>Builds the scenario's rope in its initial state.</summary>
        public FigureRun(Scenario scenario)
        {
            Scenario = scenario ?? throw new ArgumentNullException(nameof(scenario));
            Setup = ScenarioRunner.Build(scenario);
        }

        /// <summary>One host step (s of the scenario's step).</summary>
        public void Step()
        {
            double t = (steps + 1) * Scenario.HostStep;
            if (Scenario.Start.Kind == AttachmentKind.Keyframes) Setup.Rope.SetPinTarget(Setup.StartPin, Scenario.Start.PositionAt(t));
            if (Scenario.End.Kind == AttachmentKind.Keyframes) Setup.Rope.SetPinTarget(Setup.EndPin, Scenario.End.PositionAt(t));
            Setup.Step((float)Scenario.HostStep);
            steps++;
        }

        /// <summary>Steps until <see cref="Time"/> reaches <paramref name="seconds"/> (s).</summary>
        public FigureRun AdvanceTo(double seconds)
        {
            while (Time < seconds - 1e-9) Step();
            return this;
        }

        /// <summary>Steps until <paramref name="done"/> holds or <paramref name="limit"/> s pass; true when it held.</summary>
        public bool AdvanceUntil(Func<FigureRun, bool> done, double limit)
        {
            while (!done(this))
            {
                if (Time >= limit - 1e-9) return false;
                Step();
            }
            return true;
        }

        /// <summary>Index of the first broken segment, or −1 while the rope is intact.</summary>
        public int FirstBrokenSegment()
        {
            var broken = Setup.Rope.BrokenSegments;
            for (int j = 0; j < broken.Length; j++)
                if (broken[j]) return j;
            return -1;
        }

        /// <summary>World position (m) of the radius model's defect (the neck's centre): on its segment at its fraction.</summary>
        public Float3 DefectPosition()
        {
            var model = Setup.Simulation.RadiusModel;
            int j = model.DefectSegment;
            return Float3.Lerp(Setup.Rope.GetPosition(j), Setup.Rope.GetPosition(j + 1), model.DefectFraction);
        }
    }
}
