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
        /// <summary>Largest push (compressive force, N, ≥ 0) any segment read after a host step: 0 for a rope that never pushed.</summary>
        public double LargestPush;
        /// <summary>The energy put in (the ceiling), J: the total at the start, or right after the teleport, with the elastic part's upper bound; gravitational energy is zero at the anchor's height.</summary>
        public double Ceiling;
        /// <summary>Farthest particle from the anchor at the end, m.</summary>
        public double Reach;
        /// <summary>Where the rope may reach at the end, m: 1.1 × max(initial length, L + 2 × static elongation).</summary>
        public double ReachBound;
        /// <summary>Largest particle speed at the end, m/s.</summary>
        public double FinalSpeed;
        /// <summary>A teleport case: how far its load is at the end from its hanging point under the new anchor, m.</summary>
        public double HangingOffset;
        /// <summary>A teleport case: how far its load may be from its hanging point, m (<see cref="GridSweep.HangingTolerance"/>).</summary>
        public double HangingBound;
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

        /// <summary>
        /// The round-off allowance on the energy accumulated up to the end, J: <see cref="RoundOffPerSubstep"/> × (K + |G| +
        /// U) after every substep (U: the elastic energy's upper bound within round-off). A gain is checked against the
        /// allowance accumulated up to the step it is seen in.
        /// </summary>
        public double RoundOff;
        /// <summary>Largest excess of the energy gain over the allowance accumulated so far, J (≤ 0: no gain beyond round-off).</summary>
        public double Excess = double.NegativeInfinity;

        /// <summary>
        /// Worst-case round-off of the energy per substep, as a fraction of the energy the state carries (2⁻²²): every
        /// substep stores each particle's displacement and velocity in float32, each rounded by at most half an ulp (2⁻²⁴
        /// relative), and BDF2's velocity (3·d_{n+1} − d_n)/(2h) doubles the displacement's share: four half-ulps. The
        /// bound adds up linearly over the substeps (no cancellation assumed); positions themselves carry sub-float
        /// remainders, and the elastic energy's own round-off (the solve's floor of 4 ulps of the rope's size on each length)
        /// is taken out by the bounds the energy is read with (<see cref="HookeRope.Solver.Rope.ElasticEnergyBounds"/>).
        /// </summary>
        public const double RoundOffPerSubstep = 1.0 / 4194304.0;

        /// <summary>A damped case is at rest when its final kinetic energy is below this fraction of the energy it dissipated.</summary>
        public const double RestFraction = 1e-6;

        /// <summary>The energy the case may gain by round-off, J (<see cref="RoundOff"/>).</summary>
        public double Allowance => RoundOff;

        /// <summary>Energy gained beyond round-off: at some step the total energy rose above the ceiling by more than the allowance accumulated so far.</summary>
        public bool GainedEnergy => !(Excess <= 0.0);

        /// <summary>The rope is not back under its anchor at the end (a teleport case that did not recover, or a runaway).</summary>
        public bool Escaped => !(Reach < ReachBound);

        /// <summary>A teleport case whose load is not back near its hanging point under the new anchor at the end.</summary>
        public bool NotRecovered => Case.Teleport && !(HangingOffset <= HangingBound);

        /// <summary>A damped case still moves at the end: kinetic energy above <see cref="RestFraction"/> of what it dissipated.</summary>
        public bool Unsettled => Case.Damped && !(FinalKinetic <= RestFraction * System.Math.Max(Dissipated, 0.0));

        /// <summary>Non-finite, energy gain, escape, or (damped) not at rest.</summary>
        public bool Failed => !Finite || GainedEnergy || Escaped || NotRecovered || Unsettled;

        /// <summary>The documented domain limit the failure falls under (<see cref="GridLimits"/>), or null.</summary>
        public string Limit => GridLimits.Explain(this);

        /// <summary>Failed, and under no documented domain limit: what makes <c>stability --full</c> exit 1.</summary>
        public bool Undocumented => Failed && Limit == null;

        /// <summary>Why it failed (empty when it did not).</summary>
        public string Reason =>
            !Finite ? "non-finite" :
            GainedEnergy ? $"energy gain {EnergyGain:G3} J, {Excess:G3} J beyond the round-off bound (motion alone {MotionGain:G3} J)" :
            Escaped ? $"reach {Reach:G4} m > {ReachBound:G4} m" :
            NotRecovered ? $"load {HangingOffset:G3} m from its hanging point (> {HangingBound:G3} m) {Case.Duration - 0.5:G3} s after the jump" :
            Unsettled ? $"not at rest: kinetic {FinalKinetic:G3} J > {RestFraction:G1} × {Dissipated:G3} J dissipated" : "";
    }
}
