using System;

namespace HookeRope.Fracture
{
    /// <summary>
    /// One fibre of a frayed end, drawn deterministically from a seed: where its base sits on the cut (a sunflower
    /// spiral over the whole cross-section, so the fibres fill it), how long it is, how far it splays outward and how
    /// its triangular base is turned. Rendered as a three-sided spike that tapers to its tip.
    /// </summary>
    internal readonly struct BurrStrand
    {
        private const float GoldenAngle = 2.39996323f;

        /// <summary>Distance of the base centre from the axis as a fraction of the end radius, in (0, 1).</summary>
        public readonly float Radial;

        /// <summary>Angle of the base centre around the axis in radians.</summary>
        public readonly float Angle;

        /// <summary>Fibre length in end diameters (unitless), ≥ 0.1 × the mean.</summary>
        public readonly float Length;

        /// <summary>Outward splay from the rope axis in radians, in [0, Spread·Radial).</summary>
        public readonly float Tilt;

        /// <summary>Sideways twist of the splay direction in radians, in [−0.35, 0.35).</summary>
        public readonly float Twist;

        /// <summary>Turn of the triangular base in radians, in [0, 2π/3).</summary>
        public readonly float BaseTurn;

        /// <summary>Creates a fibre shape.</summary>
        public BurrStrand(float radial, float angle, float length, float tilt, float twist, float baseTurn)
        {
            Radial = radial;
            Angle = angle;
            Length = length;
            Tilt = tilt;
            Twist = twist;
            BaseTurn = baseTurn;
        }

        /// <summary>
        /// Fibre <paramref name="index"/> of <paramref name="count"/> at the broken end <paramref name="endKey"/>
        /// (e.g. 2·segment + side) for the settings' seed, lengths and splay. Pure function, allocation-free. Lengths are
        /// stratified: the count's quantiles of the uniform law FibreLength ± √3·FibreLengthSpread are dealt to the
        /// fibres in a seeded order, so every end shows the whole distribution.
        /// </summary>
        public static BurrStrand Draw(BurrSettings settings, int endKey, int index, int count) =>
            Draw(settings, endKey, index, count, ShuffleOf(settings.Seed, endKey, count));

        /// <summary>
        /// <see cref="Draw(BurrSettings, int, int, int)"/> with the end's length order <paramref name="shuffle"/> from
        /// <see cref="ShuffleOf"/> (the same for every fibre of the end: a builder computes it once per end).
        /// </summary>
        public static BurrStrand Draw(BurrSettings settings, int endKey, int index, int count, (int Step, int Offset) shuffle)
        {
            uint seed = settings.Seed;
            int key = index * 6;
            float radial = MathF.Sqrt((index + 0.5f) / count);
            float angle = index * GoldenAngle + 0.6f * (SeededRandom.Unit(seed, endKey, key) - 0.5f);
            int stratum = (int)(((long)index * shuffle.Step + shuffle.Offset) % count);
            float u = (stratum + 0.5f + 0.9f * (SeededRandom.Unit(seed, endKey, key + 1) - 0.5f)) / count;
            float mean = settings.FibreLength;
            float length = mean + 1.7320508f * settings.FibreLengthSpread * (2f * u - 1f);
            if (length < 0.1f * mean) length = 0.1f * mean;
            float tilt = settings.Spread * radial * (0.5f + 0.5f * SeededRandom.Unit(seed, endKey, key + 2));
            float twist = 0.7f * (SeededRandom.Unit(seed, endKey, key + 3) - 0.5f);
            float turn = 2.0943951f * SeededRandom.Unit(seed, endKey, key + 4);
            return new BurrStrand(radial, angle, length, tilt, twist, turn);
        }

        /// <summary>The seeded bijection of [0, count) that deals the length strata of an end: index·step + offset mod count, step coprime to count.</summary>
        public static (int Step, int Offset) ShuffleOf(uint seed, int endKey, int count)
        {
            int step = 1 + (int)(SeededRandom.Hash(seed, endKey, -1) % (uint)count);
            while (GreatestCommonDivisor(step, count) != 1) step++;
            int offset = (int)(SeededRandom.Hash(seed, endKey, -2) % (uint)count);
            return (step, offset);
        }

        private static int GreatestCommonDivisor(int a, int b)
        {
            while (b != 0) { int t = a % b; a = b; b = t; }
            return a;
        }
    }
}
