using System;

namespace HookeRope.Radius
{
    /// <summary>
    /// Validated settings of the radius model: Poisson thinning, necking at a defect and the fracture decision.
    /// Ranges, units and messages come from <see cref="RopeParameters"/>: setters throw
    /// <see cref="ArgumentOutOfRangeException"/> naming the property, its range and unit. Changes take effect at
    /// the next <see cref="RadiusModel.Update"/>.
    /// </summary>
    public sealed class RadiusSettings
    {
        private float poissonRatio = RopeParameters.PoissonRatio.Default;
        private float neckRadiusFraction = RopeParameters.NeckRadiusFraction.Default;
        private bool necking = RopeParameters.Necking.Default;
        private NeckMode neckMode = RopeParameters.NeckMode.Default;
        private float defectPosition = RopeParameters.DefectPosition.Default;
        private float neckZoneDiameters = RopeParameters.NeckZoneDiameters.Default;
        private float neckGrowthStrain = RopeParameters.NeckGrowthStrain.Default;
        private float breakRadiusFraction = RopeParameters.BreakRadiusFraction.Default;
        private float breakStrain = RopeParameters.BreakStrain.Default;

        /// <summary>Poisson thinning on (eq. 16). Off: every segment keeps the rest radius R and no per-segment work is done. Default true.</summary>
        public bool PoissonThinning { get; set; } = RopeParameters.PoissonThinning.Default;

        /// <summary>Poisson ratio ν (dimensionless), range [−1, 0.5]; 0.5 keeps the volume (rubber). Default 0.3 (the table's).</summary>
        public float PoissonRatio
        {
            get => poissonRatio;
            set => poissonRatio = RopeParameters.Check(value, RopeParameters.PoissonRatio.Row);
        }

        /// <summary>
        /// When true (default), a segment shorter than its rest length keeps the rest radius: a tension-only rope
        /// goes slack and buckles instead of being compressed. When false, eq. 16 is applied to compression too
        /// (with the clamps documented on <see cref="HookeRope.Radius.PoissonRadius.Ratio"/>).
        /// </summary>
        public bool SlackKeepsRestRadius { get; set; } = RopeParameters.SlackKeepsRestRadius.Default;

        /// <summary>Necking on: a neck forms at the defect once the radius falls below r_min (<see cref="NeckRadiusFraction"/>·R). Default true.</summary>
        public bool Necking
        {
            get => necking;
            set => necking = value;
        }

        /// <summary>Neck model used when <see cref="Necking"/> is on: <see cref="HookeRope.Radius.NeckMode.Zone"/> (default) or Paper.</summary>
        public NeckMode NeckMode
        {
            get => neckMode;
            set
            {
                if (value != NeckMode.Paper && value != NeckMode.Zone)
                    throw new ArgumentOutOfRangeException(nameof(NeckMode), value, "NeckMode must be Paper or Zone (turn necking off with Necking = false).");
                neckMode = value;
            }
        }

        /// <summary>Neck onset radius r_min as a fraction of the rest radius R (dimensionless), range [0.01, 1]. Default 0.75.</summary>
        public float NeckRadiusFraction
        {
            get => neckRadiusFraction;
            set => neckRadiusFraction = RopeParameters.Check(value, RopeParameters.NeckRadiusFraction.Row);
        }

        /// <summary>
        /// Defect position as a fraction of the rest length from the first particle (dimensionless), range [0, 1];
        /// the neck forms and the rope breaks there. Default 0.5. Paper mode always uses the middle (eq. 18).
        /// </summary>
        public float DefectPosition
        {
            get => defectPosition;
            set => defectPosition = RopeParameters.Check(value, RopeParameters.DefectPosition.Row);
        }

        /// <summary>
        /// Zone mode: rest length of the neck zone in rope diameters 2R (dimensionless), range [0.5, 1000]. Default 4,
        /// i.e. a zone of 8·R of rest length centred on the defect.
        /// </summary>
        public float NeckZoneDiameters
        {
            get => neckZoneDiameters;
            set => neckZoneDiameters = RopeParameters.Check(value, RopeParameters.NeckZoneDiameters.Row);
        }

        /// <summary>
        /// Zone mode: strain beyond onset (dimensionless) over which the neck deepens from zero to the full
        /// hyperbola, range (0, 100]. Default 0.2.
        /// </summary>
        public float NeckGrowthStrain
        {
            get => neckGrowthStrain;
            set => neckGrowthStrain = RopeParameters.Check(value, RopeParameters.NeckGrowthStrain.Row);
        }

        /// <summary>Fracture on: the defect segment breaks when a criterion is met. Off: the model never asks for a break and skips the test. Default true.</summary>
        public bool Fracture { get; set; } = RopeParameters.Fracture.Default;

        /// <summary>
        /// The rope breaks when the strain l/L − 1 of the defect segment reaches this value (dimensionless, the
        /// elongation at break), range (0, 1000]. Default 0.6.
        /// </summary>
        public float BreakStrain
        {
            get => breakStrain;
            set => breakStrain = RopeParameters.Check(value, RopeParameters.BreakStrain.Row);
        }

        /// <summary>
        /// The rope also breaks when the neck radius falls below this fraction of R (dimensionless), range [0, 0.99];
        /// 0 turns this criterion off. Needs <see cref="Necking"/>. Default 0.25.
        /// </summary>
        public float BreakRadiusFraction
        {
            get => breakRadiusFraction;
            set => breakRadiusFraction = RopeParameters.Check(value, RopeParameters.BreakRadiusFraction.Row);
        }

        /// <summary>True when any part (thinning, neck, fracture) is on; when false the model does no per-step work.</summary>
        public bool AnyEnabled => PoissonThinning || necking || Fracture;
    }
}
