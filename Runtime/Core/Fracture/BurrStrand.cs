using System;

namespace HookeRope.Fracture
{
    /// <summary>
    /// Shape of one burr strand, drawn deterministically from a seed: a thin three-sided spike standing on the
    /// broken end, one per radial segment (finer radial segments give finer burrs).
    /// </summary>
    internal readonly struct BurrStrand
    {
        /// <summary>Strand length as a fraction of <see cref="BurrSettings.Length"/> (unitless), in [0.35, 1).</summary>
        public readonly float LengthFraction;

        /// <summary>Outward tilt from the rope axis in radians, in [0, Spread).</summary>
        public readonly float Tilt;

        /// <summary>Sideways twist of the tilt direction in radians, in [−0.35, 0.35).</summary>
        public readonly float Twist;

        /// <summary>Creates a strand shape.</summary>
        public BurrStrand(float lengthFraction, float tilt, float twist)
        {
            LengthFraction = lengthFraction;
            Tilt = tilt;
            Twist = twist;
        }

        /// <summary>
        /// The strand <paramref name="strand"/> of the broken end <paramref name="endKey"/> (e.g. 2·segment + side)
        /// for <paramref name="seed"/> and the largest tilt <paramref name="spread"/> (rad). Pure function.
        /// </summary>
        public static BurrStrand Draw(uint seed, int endKey, int strand, float spread)
        {
            int key = strand * 3;
            float length = 0.35f + 0.65f * SeededRandom.Unit(seed, endKey, key);
            float tilt = spread * SeededRandom.Unit(seed, endKey, key + 1);
            float twist = 0.7f * (SeededRandom.Unit(seed, endKey, key + 2) - 0.5f);
            return new BurrStrand(length, tilt, twist);
        }
    }
}
