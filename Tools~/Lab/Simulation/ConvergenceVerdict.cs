using System;
using System.Globalization;
using HookeRope.Lab.Scenarios;

namespace HookeRope.Lab.Simulation
{
    /// <summary>Whether a run's numbers can be trusted.</summary>
    public enum Convergence
    {
        /// <summary>The solver met its constraints: the numbers mean what they say.</summary>
        Converged,
        /// <summary>Finite, but the constraints were not met (the rope is longer than its tension implies): numbers are off.</summary>
        Unconverged,
        /// <summary>NaN, a particle flung away, energy created or an incredible strain: the run is unstable and its numbers are meaningless.</summary>
        Diverged,
    }

    /// <summary>
    /// The verdict of a run from its solver residual, its strain and its energy, with the thresholds
    /// documented in Documentation~/lab.md ("Convergence verdict") and a sentence on what to change.
    /// </summary>
    public sealed class ConvergenceVerdict
    {
        /// <summary>Strain error (dimensionless) above which a host step counts as unconverged: 2 % (the tension read from the stretch is off by 2 % of E·A).</summary>
        public const double UnconvergedStrainError = 0.02;
        /// <summary>Strain error (dimensionless) above which the reason says the segments are far longer than their tension implies: 100 % (still unconverged, not diverged: the run is stable, only inaccurate).</summary>
        public const double DivergedStrainError = 1.0;
        /// <summary>Fraction of the host steps that may exceed a strain-error threshold (transients: a break, a jerk): 10 %.</summary>
        public const double AllowedFraction = 0.10;
        /// <summary>Largest credible strain l/L − 1 of any rope: 100 (10 000 %); beyond it the run diverged.</summary>
        public const double MaxCredibleStrain = 100;
        /// <summary>A particle farther than this many rope lengths from where the end started has been flung away.</summary>
        public const double ExplosionLengths = 100;
        /// <summary>Motion energy may rise above the starting energy by this fraction of M·g·L (plus |E₀|) before it counts as created.</summary>
        public const double EnergyTolerance = 0.05;

        /// <summary>The verdict.</summary>
        public Convergence Kind;
        /// <summary>Why, in words (the measured numbers against the thresholds).</summary>
        public string Reason;
        /// <summary>What to change in the scenario, in words; empty when converged.</summary>
        public string Advice = "";
        /// <summary>Fraction of host steps whose strain error exceeded <see cref="UnconvergedStrainError"/>.</summary>
        public double UnconvergedFraction;
        /// <summary>Fraction of host steps whose strain error exceeded <see cref="DivergedStrainError"/>.</summary>
        public double DivergedFraction;

        /// <summary>True when the run converged.</summary>
        public bool Converged => Kind == Convergence.Converged;

        /// <summary>One word: converged, unconverged or diverged.</summary>
        public string Word => Kind == Convergence.Converged ? "converged" : Kind == Convergence.Unconverged ? "unconverged" : "diverged";

        /// <summary>
        /// True when the motion energy (kinetic + gravitational) of the second half of the run rose above
        /// everything the rope started with by more than <see cref="EnergyTolerance"/>·(M·g·L + |E₀|) and above
        /// the first half: the solver created motion. Elastic energy is left out: an unconverged solver
        /// over-stretches the rope, which inflates that reading without creating motion.
        /// </summary>
        public static bool EnergyBlowUp(Scenario s, RunResult r, out double motionRise)
        {
            double mass = s.Rope.Mass + s.End.LoadMass;
            double scale = mass * s.Gravity.Length * s.Rope.RestLength * (1 + s.Initial.Stretch) + Math.Abs(r.InitialEnergy);
            double tolerance = EnergyTolerance * scale + 1e-3;
            motionRise = r.LateMaxMotionEnergy - r.InitialEnergy;
            bool growing = r.LateMaxMotionEnergy > Math.Max(r.EarlyMaxMotionEnergy, r.InitialEnergy) + tolerance;
            return !double.IsFinite(motionRise) || (motionRise > tolerance && growing);
        }

        /// <summary>True when a particle went farther than <see cref="ExplosionLengths"/> rope lengths (plus 10 m) from where the end started.</summary>
        public static bool Exploded(Scenario s, RunResult r) =>
            r.MaxExtent > ExplosionLengths * s.Rope.RestLength * (1 + s.Initial.Stretch) + 10;

        /// <summary>True when something moves an anchor or adds energy during the run (keyframes, timed events, a wind through drag): the energy criterion does not apply.</summary>
        public static bool Driven(Scenario s) =>
            s.Start.Kind == AttachmentKind.Keyframes || s.End.Kind == AttachmentKind.Keyframes || s.Events.Count > 0 || s.Drag.Blows;

        /// <summary>Judges a run.</summary>
        public static ConvergenceVerdict Judge(RunResult r)
        {
            var s = r.Scenario;
            var v = new ConvergenceVerdict();
            int above = 0, far = 0, counted = 0;
            if (r.ResidualSeries != null)
                foreach (float e in r.ResidualSeries)
                {
                    counted++;
                    if (!(e <= UnconvergedStrainError)) above++;
                    if (!(e <= DivergedStrainError)) far++;
                }
            v.UnconvergedFraction = counted > 0 ? (double)above / counted : 0;
            v.DivergedFraction = counted > 0 ? (double)far / counted : 0;
            double strain = r.MaxElongation / s.Rope.RestLength;
            bool gaussSeidel = s.Solver.Method == SolverMethod.GaussSeidel;
            string finer = string.Format(Invariant,
                "raise solver.substeps (now {0}) or shorten hostStep (now {1:G4} ms)", s.Solver.Substeps, s.HostStep * 1000);
            string exact = "use the exact solver (\"solver\": { \"method\": \"exact-chain\" })";
            string steadier = gaussSeidel ? exact + "; " + finer : finer;

            if (r.NonFinite)
                return v.Set(Convergence.Diverged, "NaN or ∞ in the particle positions", steadier);
            if (Exploded(s, r))
                return v.Set(Convergence.Diverged,
                    string.Format(Invariant, "a particle was flung {0:G3} m away (limit {1} rope lengths)", r.MaxExtent, ExplosionLengths),
                    steadier);
            if (strain > MaxCredibleStrain)
                return v.Set(Convergence.Diverged,
                    string.Format(Invariant, "strain {0:G3} (above {1} = {2} %, no rope stretches that far)", strain, MaxCredibleStrain, MaxCredibleStrain * 100),
                    steadier);
            if (!Driven(s) && r.LateMaxMotionEnergy > double.NegativeInfinity && EnergyBlowUp(s, r, out double rise))
                return v.Set(Convergence.Diverged,
                    string.Format(Invariant, "the solver created {0:G3} J of motion energy", rise),
                    "raise solver.damping (now " + s.Solver.Damping.ToString("G3", Invariant) + " s) or " + finer);
            if (v.UnconvergedFraction > AllowedFraction)
                return v.Set(Convergence.Unconverged,
                    v.DivergedFraction > AllowedFraction
                        ? string.Format(Invariant, "strain error above {0:P0} on {1:P0} of the host steps (max {2:G3}): segments far longer than their tension implies",
                            DivergedStrainError, v.DivergedFraction, r.MaxResidual)
                        : string.Format(Invariant, "strain error above {0:P0} on {1:P0} of the host steps (max {2:G3})", UnconvergedStrainError, v.UnconvergedFraction, r.MaxResidual),
                    gaussSeidel
                        ? exact + string.Format(Invariant, "; Gauss–Seidel carries a load one segment per iteration ({0} iterations for {1} segments)", s.Solver.Iterations, s.Rope.Segments)
                        : string.Format(Invariant, "raise solver.substeps (now {0}) or solver.iterations (now {1})", s.Solver.Substeps, s.Solver.Iterations));
            return v.Set(Convergence.Converged,
                string.Format(Invariant, "strain error ≤ {0:P0} on {1:P0} of the host steps (max {2:G3}), {3}",
                    UnconvergedStrainError, 1 - v.UnconvergedFraction, r.MaxResidual,
                    Driven(s) ? "energy not judged (driven anchors, events or wind do work)" : "energy not created"), "");
        }

        static readonly CultureInfo Invariant = CultureInfo.InvariantCulture;

        ConvergenceVerdict Set(Convergence kind, string reason, string advice)
        {
            Kind = kind;
            Reason = reason;
            Advice = advice;
            return this;
        }
    }
}
