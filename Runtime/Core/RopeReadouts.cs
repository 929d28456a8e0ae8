using System;
using HookeRope.Solver;

namespace HookeRope
{
    /// <summary>
    /// The read-outs of a <see cref="RopeSimulation"/>, updated at its construction and at the end of every
    /// <see cref="RopeSimulation.Step"/>: tensions, elongation and strain of the intact segments, the arrest force
    /// on a load and its fall-arrest limits, the permanent set, absorber deployment and plastic work, radii, the solver
    /// residual and the first break. The component, its inspector and the lab all read
    /// these; nobody recomputes them. Allocation-free.
    /// </summary>
    public sealed class RopeReadouts
    {
        private readonly RopeSimulation simulation;
        private int arrestLoad = -1;

        internal RopeReadouts(RopeSimulation simulation)
        {
            this.simulation = simulation;
        }

        /// <summary>Σ over the intact segments of (current length − rest length), in metres. Right after a break too.</summary>
        public double Elongation { get; private set; }

        /// <summary><see cref="Elongation"/> divided by the rest length of the intact segments (dimensionless); 0 when every segment is broken.</summary>
        public double Strain { get; private set; }

        /// <summary>Tension of the first segment in newtons (0 once it is broken).</summary>
        public float TopTension { get; private set; }

        /// <summary>Tension of the last segment in newtons (0 once it is broken).</summary>
        public float BottomTension { get; private set; }

        /// <summary>
        /// Largest tension of any intact segment since the construction or <see cref="ResetPeaks"/>, in newtons, over every
        /// substep (<see cref="Rope.PeakTensions"/>): a peak that falls between host steps still reads.
        /// </summary>
        public float PeakTension { get; private set; }

        /// <summary>
        /// Index of the load (<see cref="Rope.AddLoad"/>) whose force is the arrest force, or −1 (default): the
        /// arrest force is then <see cref="BottomTension"/>. Set by the host when it attaches a body.
        /// </summary>
        public int ArrestLoad
        {
            get => arrestLoad;
            set
            {
                if (value < -1 || value >= simulation.Rope.LoadCount)
                    throw new ArgumentOutOfRangeException(nameof(ArrestLoad), value, "ArrestLoad must be -1 (none) or a load index in [0, LoadCount - 1].");
                arrestLoad = value;
            }
        }

        /// <summary>Force in newtons on the <see cref="ArrestLoad"/> (its magnitude), else <see cref="BottomTension"/>.</summary>
        public float ArrestForce { get; private set; }

        /// <summary>
        /// Largest arrest force since the construction or <see cref="ResetPeaks"/>, in newtons, over every substep: the
        /// load's <see cref="Rope.GetLoadPeakForce"/> (or the last segment's <see cref="Rope.PeakTensions"/> without an
        /// <see cref="ArrestLoad"/>), never below <see cref="ArrestForce"/>.
        /// </summary>
        public float PeakArrestForce { get; private set; }

        /// <summary>True while <see cref="PeakArrestForce"/> is within EN 355's 6 kN (<see cref="FallArrestLimits.En355"/>): the pass/fail of an energy-absorber lanyard.</summary>
        public bool MeetsEn355 => FallArrestLimits.MeetsEn355(PeakArrestForce);

        /// <summary>True while <see cref="PeakArrestForce"/> is within ANSI Z359.13's 8 kN (<see cref="FallArrestLimits.AnsiZ359_13"/>).</summary>
        public bool MeetsAnsiZ359_13 => FallArrestLimits.MeetsAnsiZ359_13(PeakArrestForce);

        /// <summary>Permanent set in metres: Σ (L_p − L) over the intact segments, the energy absorber's deployment included (<see cref="Rope.PlasticElongation"/>; 0 for an elastic rope).</summary>
        public double PlasticElongation { get; private set; }

        /// <summary>How far the energy absorber has deployed, in metres (<see cref="Rope.AbsorberDeployment"/>; 0 without one).</summary>
        public double AbsorberDeployment { get; private set; }

        /// <summary>Plastic work in joules: the energy the permanent set, the neck and the absorber took (<see cref="Rope.PlasticWork"/>).</summary>
        public double PlasticWork { get; private set; }

        /// <summary>Smallest radius along the rope in metres, neck included (R without a radius model).</summary>
        public float MinRadius { get; private set; }

        /// <summary>Radius at the defect in metres, neck included (R without a radius model).</summary>
        public float NeckRadius { get; private set; }

        /// <summary>Constraint residual of the last step (<see cref="StepReport.Residual"/>); 0 before the first step.</summary>
        public float Residual { get; private set; }

        /// <summary>True once any segment has broken (the radius model's fracture, a cut, a pin).</summary>
        public bool IsBroken => simulation.Rope.BrokenSegmentCount > 0;

        /// <summary>The first break of the rope (time, position, segment, tension), or null while it is intact.</summary>
        public RopeBreakEvent? FirstBreak { get; private set; }

        /// <summary>Clears <see cref="PeakTension"/> and <see cref="PeakArrestForce"/>.</summary>
        public void ResetPeaks()
        {
            PeakTension = 0f;
            PeakArrestForce = 0f;
        }

        internal void RecordBreak(RopeBreakEvent e)
        {
            if (!FirstBreak.HasValue) FirstBreak = e;
        }

        internal void Update(float residual)
        {
            Rope rope = simulation.Rope;
            ReadOnlySpan<float> tensions = rope.Tensions;
            ReadOnlySpan<float> substepPeaks = rope.PeakTensions;
            ReadOnlySpan<float> lengths = rope.SegmentLengths;
            ReadOnlySpan<float> rest = rope.RestLengths;
            ReadOnlySpan<bool> broken = rope.BrokenSegments;
            int n = tensions.Length;
            double elongation = 0.0, intactRest = 0.0;
            float peak = PeakTension;
            for (int j = 0; j < n; j++)
            {
                if (broken[j]) continue;
                elongation += lengths[j] - rest[j];
                intactRest += rest[j];
                if (substepPeaks[j] > peak) peak = substepPeaks[j];
                if (tensions[j] > peak) peak = tensions[j];
            }
            Elongation = elongation;
            Strain = intactRest > 0.0 ? elongation / intactRest : 0.0;
            TopTension = n > 0 && !broken[0] ? tensions[0] : 0f;
            BottomTension = n > 0 && !broken[n - 1] ? tensions[n - 1] : 0f;
            PeakTension = peak;
            ArrestForce = arrestLoad >= 0 ? rope.GetLoadForce(arrestLoad).Length : BottomTension;
            float arrestPeak = arrestLoad >= 0 ? rope.GetLoadPeakForce(arrestLoad)
                : n > 0 && !broken[n - 1] ? substepPeaks[n - 1] : 0f;
            PeakArrestForce = Math.Max(PeakArrestForce, Math.Max(ArrestForce, arrestPeak));
            PlasticElongation = rope.PlasticElongation;
            AbsorberDeployment = rope.AbsorberDeployment;
            PlasticWork = rope.PlasticWork;
            MinRadius = simulation.MinRadius;
            NeckRadius = simulation.NeckRadius;
            Residual = residual;
        }
    }
}
