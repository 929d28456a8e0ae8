namespace HookeRope.Lab.Stability
{
    /// <summary>What one <see cref="GridCase"/> did.</summary>
    public sealed class GridOutcome
    {
        /// <summary>The case.</summary>
        public GridCase Case;
        /// <summary>Every position, velocity and tension stayed finite.</summary>
        public bool Finite;
        /// <summary>
        /// Largest rise of the total energy (kinetic + gravitational + elastic, the elastic part the least any state within
        /// round-off stores: <see cref="HookeRope.Solver.Rope.ElasticEnergyBounds"/>) above the energy put in, J.
        /// </summary>
        public double EnergyGain;
        /// <summary>Largest rise of kinetic + gravitational energy alone above the energy put in, J (a diagnostic: the gain that shows as motion).</summary>
        public double MotionGain;
        /// <summary>The energy put in (the ceiling), J: the total at the start, or right after the teleport, with the elastic part's upper bound; gravitational energy is zero at the anchor's height.</summary>
        public double Ceiling;
        /// <summary>Farthest particle from the anchor at the end, m.</summary>
        public double Reach;
        /// <summary>Where the rope may reach at the end, m: 1.1 × max(initial length, L + 2 × static elongation).</summary>
        public double ReachBound;
        /// <summary>Largest particle speed at the end, m/s.</summary>
        public double FinalSpeed;
        /// <summary>Kinetic energy at the end, J.</summary>
        public double FinalKinetic;
        /// <summary>Energy the run lost from the ceiling to the end (drag, damping, the integrator), J.</summary>
        public double Dissipated;
        /// <summary>Substeps run.</summary>
        public long Substeps;
        /// <summary>Newton iterations of the exact solve over the run (<see cref="HookeRope.Solver.StepReport.SolveIterations"/>).</summary>
        public long SolveIterations;
        /// <summary>Violent substeps over the run (<see cref="HookeRope.Solver.StepReport.ViolentSubsteps"/>).</summary>
        public long ViolentSubsteps;
        /// <summary>Line-search-shortened iterations over the run (<see cref="HookeRope.Solver.StepReport.ShortenedSteps"/>).</summary>
        public long ShortenedSteps;
        /// <summary>Substeps that ended unconverged at their iteration limit (<see cref="HookeRope.Solver.StepReport.UnconvergedSubsteps"/>).</summary>
        public long UnconvergedSubsteps;

        /// <summary>Relative part of the round-off allowance on the energy: 1e-4 of |ceiling|.</summary>
        public const double RelativeAllowance = 1e-4;
        /// <summary>Absolute part of the round-off allowance on the energy, J.</summary>
        public const double AbsoluteAllowance = 1e-6;
        /// <summary>A damped case is at rest when its final kinetic energy is below this fraction of the energy it dissipated (plus <see cref="AbsoluteAllowance"/>).</summary>
        public const double RestFraction = 1e-6;

        /// <summary>The energy the case may gain by round-off, J: <see cref="RelativeAllowance"/> × |ceiling| + <see cref="AbsoluteAllowance"/>.</summary>
        public double Allowance => RelativeAllowance * System.Math.Abs(Ceiling) + AbsoluteAllowance;

        /// <summary>Energy gained beyond round-off.</summary>
        public bool GainedEnergy => !(EnergyGain <= Allowance);

        /// <summary>The rope is not back under its anchor at the end (a teleport case that did not recover, or a runaway).</summary>
        public bool Escaped => !(Reach < ReachBound);

        /// <summary>A damped case still moves at the end: kinetic energy above <see cref="RestFraction"/> of what it dissipated.</summary>
        public bool Unsettled => Case.Damped && !(FinalKinetic <= RestFraction * System.Math.Max(Dissipated, 0.0) + AbsoluteAllowance);

        /// <summary>Non-finite, energy gain, escape, or (damped) not at rest.</summary>
        public bool Failed => !Finite || GainedEnergy || Escaped || Unsettled;

        /// <summary>Why it failed (empty when it did not).</summary>
        public string Reason =>
            !Finite ? "non-finite" :
            GainedEnergy ? $"energy gain {EnergyGain:G3} J > {Allowance:G3} J (motion alone {MotionGain:G3} J)" :
            Escaped ? $"reach {Reach:G4} m > {ReachBound:G4} m" :
            Unsettled ? $"not at rest: kinetic {FinalKinetic:G3} J > {RestFraction:G1} × {Dissipated:G3} J dissipated" : "";
    }
}
