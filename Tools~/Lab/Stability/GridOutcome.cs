namespace HookeRope.Lab.Stability
{
    /// <summary>What one <see cref="GridCase"/> did.</summary>
    public sealed class GridOutcome
    {
        /// <summary>The case.</summary>
        public GridCase Case;
        /// <summary>Every position, velocity and tension stayed finite.</summary>
        public bool Finite;
        /// <summary>Largest rise of kinetic + gravitational energy above the energy put in (start, or right after the teleport), J.</summary>
        public double EnergyGain;
        /// <summary>The energy put in (the ceiling), J.</summary>
        public double Ceiling;
        /// <summary>Farthest particle from the anchor at the end, m.</summary>
        public double Reach;
        /// <summary>Where the rope may reach at the end, m: 1.1 × max(initial length, L + 2 × static elongation).</summary>
        public double ReachBound;
        /// <summary>Largest particle speed at the end, m/s.</summary>
        public double FinalSpeed;

        /// <summary>Energy gained beyond round-off: more than 1e-4 of the ceiling (plus 1 µJ).</summary>
        public bool GainedEnergy => !(EnergyGain <= 1e-4 * System.Math.Abs(Ceiling) + 1e-6);

        /// <summary>The rope is not back under its anchor at the end (a teleport case that did not recover, or a runaway).</summary>
        public bool Escaped => !(Reach < ReachBound);

        /// <summary>Non-finite, energy gain or escape.</summary>
        public bool Failed => !Finite || GainedEnergy || Escaped;

        /// <summary>Why it failed (empty when it did not).</summary>
        public string Reason => !Finite ? "non-finite" : GainedEnergy ? $"energy gain {EnergyGain:G3} J" : Escaped ? $"reach {Reach:G4} m > {ReachBound:G4} m" : "";
    }
}
