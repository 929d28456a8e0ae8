using System;
using System.Collections.Generic;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using HookeRope.Mathematics;

namespace HookeRope.Lab.Stability
{
    /// <summary>One stiff or extreme case of the sweep.</summary>
    public sealed class StabilityCase
    {
        /// <summary>What is extreme about it.</summary>
        public string Name;
        /// <summary>The scenario that runs.</summary>
        public Scenario Scenario;
        /// <summary>True when an anchor is moved (does work): the energy criterion does not apply.</summary>
        public bool DrivenAnchor;
    }

    /// <summary>Outcome of one case.</summary>
    public sealed class StabilityOutcome
    {
        /// <summary>The case.</summary>
        public StabilityCase Case;
        /// <summary>NaN or ∞ appeared in positions.</summary>
        public bool NonFinite;
        /// <summary>Kinetic + gravitational energy rose above the whole starting energy by more than the tolerance and was still growing.</summary>
        public bool EnergyBlowUp;
        /// <summary>Largest kinetic + gravitational energy of the second half of the run minus the starting total energy, J.</summary>
        public double EnergyRise;
        /// <summary>A particle went farther than 100 rope lengths from where the end started.</summary>
        public bool Exploded;
        /// <summary>Largest particle speed at the end is below 0.1 m/s.</summary>
        public bool Settled;
        /// <summary>Largest solver residual (strain error) over the run.</summary>
        public double MaxConstraintError;
        /// <summary>Wall time, s.</summary>
        public double WallSeconds;

        /// <summary>NaN, energy blow-up or explosion (not accuracy or settling).</summary>
        public bool Unstable => NonFinite || EnergyBlowUp || Exploded;

        /// <summary>The case counts as a failure: the same as <see cref="Unstable"/> (no case is excused as a known limit).</summary>
        public bool Failed => Unstable;
    }

    /// <summary>
    /// The sweep of stiff and extreme cases: E from 1 MPa to 200 GPa, load-to-particle mass ratio 1 to
    /// 10⁶, host step 1/30 to 1/1000 s, 2 to 10 000 segments, a rope released at 10× its length and an
    /// anchor teleported 5 m in one step; each with the exact chain and, where it matters, Gauss–Seidel.
    /// </summary>
    public static class StabilitySweep
    {
        /// <summary>Base case: 1 m nylon-like rope (R 5 mm, E 1 GPa, 1140 kg/m³, ν 0.5, no neck, no fracture), 16 segments, 1 kg load.</summary>
        public static Scenario Base(SolverMethod method, double duration)
        {
            var s = new Scenario { Name = "stability", Duration = duration, HostStep = 1.0 / 90 };
            s.Solver.Method = method;
            s.Solver.Substeps = 4;
            s.Solver.Iterations = 2;
            s.Solver.Damping = 0.01;
            s.Rope.RestLength = 1;
            s.Rope.Segments = 16;
            s.Rope.Radius = 0.005;
            s.Rope.YoungsModulus = 1e9;
            s.Rope.Density = 1140;
            // stated explicitly, so the sweep does not move with the parameter table's defaults
            s.Rope.PoissonRatio = 0.5;
            s.Rope.Necking = false;
            s.Rope.Fracture = false;
            s.Rope.RadialSegments = 8;
            s.Start = AttachmentSpec.FixedAt(Float3.Zero);
            s.End = new AttachmentSpec { Kind = AttachmentKind.Body, Mass = 1 };
            s.Outputs.SampleRate = 10;
            return s;
        }

        /// <summary>The cases (reduced when <paramref name="quick"/>).</summary>
        public static List<StabilityCase> Cases(bool quick)
        {
            double duration = quick ? 1.0 : 2.0;
            var list = new List<StabilityCase>();
            var methods = quick ? new[] { SolverMethod.ExactChain } : new[] { SolverMethod.ExactChain, SolverMethod.GaussSeidel };
            string Tag(SolverMethod m) => m == SolverMethod.ExactChain ? "exact" : "GS";

            foreach (var m in methods)
                foreach (double e in quick ? new[] { 1e6, 2e11 } : new[] { 1e6, 1e9, 2e11 })
                {
                    var s = Base(m, duration);
                    s.Rope.YoungsModulus = e;
                    list.Add(new StabilityCase { Name = $"E = {e:G3} Pa ({Tag(m)})", Scenario = s });
                }
            foreach (var m in quick ? new[] { SolverMethod.ExactChain, SolverMethod.GaussSeidel } : methods)
                foreach (double ratio in quick ? new[] { 1e6 } : new[] { 1.0, 1e3, 1e6 })
                {
                    var s = Base(m, duration);
                    double particle = s.Rope.ResolvedLinearDensity * s.Rope.RestLength / s.Rope.Segments;
                    s.End.Mass = ratio * particle;
                    list.Add(new StabilityCase
                    {
                        Name = $"mass ratio {ratio:G3} ({Tag(m)})", Scenario = s,
                    });
                }
            foreach (double rate in quick ? new[] { 30.0 } : new[] { 30.0, 1000.0 })
            {
                var s = Base(SolverMethod.ExactChain, duration);
                s.HostStep = 1.0 / rate;
                list.Add(new StabilityCase { Name = $"host step 1/{rate:G4} s (exact)", Scenario = s });
            }
            foreach (int n in quick ? new[] { 2, 1000 } : new[] { 2, 10000 })
            {
                var s = Base(SolverMethod.ExactChain, duration);
                s.Rope.Segments = n;
                list.Add(new StabilityCase { Name = $"{n} segments (exact)", Scenario = s });
            }
            foreach (var m in quick ? new[] { SolverMethod.ExactChain, SolverMethod.GaussSeidel } : methods)
            {
                var s = Base(m, duration);
                s.Initial.Stretch = 9;   // released at 10× its rest length
                list.Add(new StabilityCase { Name = $"released at 10× length ({Tag(m)})", Scenario = s });
            }
            foreach (var m in methods)
            {
                var s = Base(m, duration);
                s.Start = new AttachmentSpec { Kind = AttachmentKind.Keyframes, Position = Float3.Zero };
                s.Start.Keys.Add(new Keyframe { Time = 0, Position = Float3.Zero });
                s.Start.Keys.Add(new Keyframe { Time = 0.3, Position = Float3.Zero });
                s.Start.Keys.Add(new Keyframe { Time = 0.3 + s.HostStep, Position = new Float3(5f, 0f, 0f) });
                list.Add(new StabilityCase { Name = $"anchor teleported 5 m ({Tag(m)})", Scenario = s, DrivenAnchor = true });
            }
            return list;
        }

        /// <summary>Runs one case.</summary>
        public static StabilityOutcome Run(StabilityCase c)
        {
            var s = c.Scenario;
            var r = ScenarioRunner.Run(s, new RunOptions { RecordSamples = false, Captures = false, TrackEnergy = true });
            // Blow-up and explosion use the run verdict's criteria (ConvergenceVerdict: motion energy, not
            // the elastic reading an unconverged solver inflates).
            bool blowUp = ConvergenceVerdict.EnergyBlowUp(s, r, out double motionRise);
            return new StabilityOutcome
            {
                Case = c,
                NonFinite = r.NonFinite,
                EnergyRise = motionRise,
                EnergyBlowUp = !c.DrivenAnchor && blowUp,
                Exploded = ConvergenceVerdict.Exploded(s, r),
                Settled = r.FinalMaxSpeed < 0.1,
                MaxConstraintError = r.MaxResidual,
                WallSeconds = r.WallSeconds,
            };
        }
    }
}
