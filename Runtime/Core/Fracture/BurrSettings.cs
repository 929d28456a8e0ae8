using System;

namespace HookeRope.Fracture
{
    /// <summary>
    /// Validated settings of the frayed fracture ends (burr fibres) drawn at every broken end of a rope. Setters throw
    /// <see cref="ArgumentOutOfRangeException"/> naming the property and its valid range.
    /// </summary>
    public sealed class BurrSettings
    {
        /// <summary>Largest number of fibres at one broken end.</summary>
        public const int MaxFibres = 256;

        /// <summary>Smallest number of fibres at one broken end.</summary>
        public const int MinFibres = 3;

        private float spread = 0.6f;
        private float fibreLength = 0.6f;
        private float fibreLengthSpread = 0.15f;
        private float fibreDensity = 40f;

        /// <summary>Fibres on. Off: a broken end is closed by a flat cap and no fibre vertex exists. Default true.</summary>
        public bool Enabled { get; set; } = true;

        /// <summary>Seed of the fibre positions, lengths and directions; the same seed gives the same burr. Default 1.</summary>
        public uint Seed { get; set; } = 1u;

        /// <summary>
        /// Mean fibre length in diameters of the broken end (2·r_end, unitless), range (0, 5]. Default 0.6.
        /// </summary>
        public float FibreLength
        {
            get => fibreLength;
            set => fibreLength = Require.InOpenClosedRange(value, 0f, 5f, nameof(FibreLength), "end diameters");
        }

        /// <summary>
        /// Standard deviation of the fibre length in diameters of the broken end (unitless), range [0, 2]. Lengths are
        /// uniform over FibreLength ± √3·FibreLengthSpread, never below 0.1·FibreLength. Default 0.15.
        /// </summary>
        public float FibreLengthSpread
        {
            get => fibreLengthSpread;
            set => fibreLengthSpread = Require.InClosedRange(value, 0f, 2f, nameof(FibreLengthSpread), "end diameters");
        }

        /// <summary>
        /// Fibres per square centimetre of the rope's rest cross-section π R² (1/cm²), range [1, 400]; the count at
        /// an end is this times π R², at least the radial segment count, clamped to [3, 256]. Read when the mesh
        /// topology is made. Default 40 (126 fibres for R = 10 mm, 45 for 6 mm).
        /// </summary>
        public float FibreDensity
        {
            get => fibreDensity;
            set => fibreDensity = Require.InClosedRange(value, 1f, 400f, nameof(FibreDensity), "1/cm²");
        }

        /// <summary>Largest outward splay of a rim fibre from the rope axis in radians, range [0, 1.4]; fibres nearer the axis splay less. Default 0.6.</summary>
        public float Spread
        {
            get => spread;
            set => spread = Require.InClosedRange(value, 0f, 1.4f, nameof(Spread), "rad");
        }

        /// <summary>
        /// Fibres at one broken end of a rope with rest radius <paramref name="restRadius"/> (m; 0 = unknown, then the
        /// radial count) drawn with <paramref name="radialSegments"/> around the tube: FibreDensity·π R², at least
        /// <paramref name="radialSegments"/>, in [<see cref="MinFibres"/>, <see cref="MaxFibres"/>].
        /// </summary>
        public int FibreCount(float restRadius, int radialSegments)
        {
            double centimetres = Math.Max(0.0, restRadius) * 100.0;
            double byArea = Math.Round(fibreDensity * Math.PI * centimetres * centimetres);
            double count = Math.Max(byArea, radialSegments);
            return count < MinFibres ? MinFibres : (count > MaxFibres ? MaxFibres : (int)count);
        }
    }
}
