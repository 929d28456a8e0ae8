using System;

namespace HookeRope.Fracture
{
    /// <summary>
    /// Validated settings of the fracture ends (burr strands) drawn at every broken end of a rope. Setters throw
    /// <see cref="ArgumentOutOfRangeException"/> naming the property and its valid range.
    /// </summary>
    public sealed class BurrSettings
    {
        private float length = 1.5f;
        private float spread = 0.6f;

        /// <summary>Strands on. Off: a broken end is closed by a flat cap and no strand vertex exists. Default true.</summary>
        public bool Enabled { get; set; } = true;

        /// <summary>Seed of the strand lengths and directions; the same seed gives the same burr. Default 1.</summary>
        public uint Seed { get; set; } = 1u;

        /// <summary>Longest strand length in end radii (unitless), range (0, 20]; strands are 35–100 % of it. Default 1.5.</summary>
        public float Length
        {
            get => length;
            set => length = Require.InOpenClosedRange(value, 0f, 20f, nameof(Length), "end radii");
        }

        /// <summary>Largest outward tilt of a strand from the rope axis in radians, range [0, 1.4]. Default 0.6.</summary>
        public float Spread
        {
            get => spread;
            set => spread = Require.InClosedRange(value, 0f, 1.4f, nameof(Spread), "rad");
        }
    }
}
