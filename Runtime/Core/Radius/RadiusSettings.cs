using System;

namespace HookeRope.Radius
{
    /// <summary>
    /// Validated settings of the radius model (Poisson thinning, necking at a defect, break decision).
    /// Setters throw <see cref="ArgumentOutOfRangeException"/> naming the property and its valid range.
    /// Changes take effect at the next <see cref="RadiusModel.Update"/>.
    /// </summary>
    public sealed class RadiusSettings
    {
        private float poissonRatio = 0.5f;
        private float rMinFraction = 0.8f;
        private NeckMode neckMode = NeckMode.Zone;
        private float defectPosition = 0.5f;
        private float neckZoneDiameters = 4f;
        private float neckGrowthStrain = 0.2f;
        private float breakRadiusFraction = 0.25f;
        private float breakElongation = float.PositiveInfinity;

        /// <summary>Poisson thinning on (eq. 16). Off: every segment keeps the rest radius R and no per-segment work is done. Default true.</summary>
        public bool PoissonEnabled { get; set; } = true;

        /// <summary>Poisson ratio ν (unitless), range [−1, 0.5]; 0.5 keeps the volume (rubber). Default 0.5.</summary>
        public float PoissonRatio
        {
            get => poissonRatio;
            set => poissonRatio = Require.InClosedRange(value, -1f, 0.5f, nameof(PoissonRatio));
        }

        /// <summary>
        /// When true (default), a segment shorter than its rest length keeps the rest radius: a tension-only rope
        /// goes slack and buckles instead of being compressed. When false, eq. 16 is applied to compression too
        /// (with the clamps documented on <see cref="HookeRope.Radius.PoissonRadius.Ratio"/>).
        /// </summary>
        public bool SlackKeepsRestRadius { get; set; } = true;

        /// <summary>Neck onset radius r_min as a fraction of the rest radius R (unitless), range (0, 1]. Default 0.8.</summary>
        public float RMinFraction
        {
            get => rMinFraction;
            set => rMinFraction = Require.InOpenClosedRange(value, 0f, 1f, nameof(RMinFraction));
        }

        /// <summary>Neck model: <see cref="HookeRope.Radius.NeckMode.Off"/>, Paper or Zone (default).</summary>
        public NeckMode NeckMode
        {
            get => neckMode;
            set
            {
                if (value != NeckMode.Off && value != NeckMode.Paper && value != NeckMode.Zone)
                    throw new ArgumentOutOfRangeException(nameof(NeckMode), value, "NeckMode must be Off, Paper or Zone.");
                neckMode = value;
            }
        }

        /// <summary>
        /// Defect position as a fraction of the rest length from the first particle (unitless), range [0, 1];
        /// the neck forms and the rope breaks there. Default 0.5. Paper mode always uses the middle (eq. 18).
        /// </summary>
        public float DefectPosition
        {
            get => defectPosition;
            set => defectPosition = Require.InClosedRange(value, 0f, 1f, nameof(DefectPosition));
        }

        /// <summary>
        /// Zone mode: rest length of the neck zone in rope diameters 2R (unitless), range [0.5, 1000]. Default 4,
        /// i.e. a zone of 8·R of rest length centred on the defect.
        /// </summary>
        public float NeckZoneDiameters
        {
            get => neckZoneDiameters;
            set => neckZoneDiameters = Require.InClosedRange(value, 0.5f, 1000f, nameof(NeckZoneDiameters));
        }

        /// <summary>
        /// Zone mode: strain beyond onset (unitless) over which the neck deepens from zero to the full
        /// hyperbola, range (0, 100]. Default 0.2.
        /// </summary>
        public float NeckGrowthStrain
        {
            get => neckGrowthStrain;
            set => neckGrowthStrain = Require.InOpenClosedRange(value, 0f, 100f, nameof(NeckGrowthStrain));
        }

        /// <summary>Break decision on. Off: the model never asks for a break and skips the test. Default true.</summary>
        public bool BreakEnabled { get; set; } = true;

        /// <summary>
        /// The rope breaks when the neck radius falls below this fraction of R (unitless), range [0, 1); 0 turns
        /// this criterion off. Default 0.25.
        /// </summary>
        public float BreakRadiusFraction
        {
            get => breakRadiusFraction;
            set => breakRadiusFraction = Require.InClosedOpenRange(value, 0f, 1f, nameof(BreakRadiusFraction));
        }

        /// <summary>
        /// The rope breaks when the strain l/L − 1 of the defect segment reaches this value (unitless, the
        /// elongation at break), range (0, +∞]; +∞ (default) turns this criterion off.
        /// </summary>
        public float BreakElongation
        {
            get => breakElongation;
            set
            {
                if (float.IsNaN(value) || !(value > 0f))
                    throw new ArgumentOutOfRangeException(nameof(BreakElongation), value, "BreakElongation must be in (0, +inf].");
                breakElongation = value;
            }
        }

        /// <summary>True when any part (thinning, neck, break) is on; when false the model does no per-step work.</summary>
        public bool AnyEnabled => PoissonEnabled || neckMode != NeckMode.Off || BreakEnabled;
    }
}
