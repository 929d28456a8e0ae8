namespace HookeRope
{
    /// <summary>
    /// Maximum arrest forces of fall-protection standards, for safety-training read-outs. Values in newtons.
    /// EN 355 (energy absorbers): arrest force at most 6 kN with a 100 kg test mass. ANSI Z359.13 (personal
    /// energy absorbers and lanyards): maximum arrest force at most 8 kN (average at most 4 kN in the 6 ft class).
    /// </summary>
    public static class FallArrestLimits
    {
        /// <summary>EN 355 maximum arrest force, 6000 N.</summary>
        public const float En355 = 6000f;

        /// <summary>ANSI Z359.13 maximum arrest force, 8000 N.</summary>
        public const float AnsiZ359_13 = 8000f;

        /// <summary>True when <paramref name="force"/> (N) is within the EN 355 limit.</summary>
        public static bool MeetsEn355(float force) => force <= En355;

        /// <summary>True when <paramref name="force"/> (N) is within the ANSI Z359.13 limit.</summary>
        public static bool MeetsAnsiZ359_13(float force) => force <= AnsiZ359_13;
    }
}
