using System;
using HookeRope.Fracture;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Validated settings of the procedural tube mesh. Setters throw <see cref="ArgumentOutOfRangeException"/>
    /// naming the property and its valid range. RadialSegments, RingsPerSegment, CapEnds and Burr.Enabled fix the
    /// topology and are read when a <see cref="TubeMeshBuilder"/> is created; VPerMetre and the other burr values
    /// are read at every build.
    /// </summary>
    public sealed class TubeMeshSettings
    {
        private int radialSegments = 16;
        private int ringsPerSegment = 4;
        private float vPerMetre = 10f;

        /// <summary>Vertices around the tube, range [3, 64] (the paper shows 8, 16, 32). Default 16.</summary>
        public int RadialSegments
        {
            get => radialSegments;
            set
            {
                if (value < 3 || value > 64)
                    throw new ArgumentOutOfRangeException(nameof(RadialSegments), value, "RadialSegments must be in [3, 64].");
                radialSegments = value;
            }
        }

        /// <summary>Rings per rope segment along the smooth curve, range [1, 64]. Default 4.</summary>
        public int RingsPerSegment
        {
            get => ringsPerSegment;
            set
            {
                if (value < 1 || value > 64)
                    throw new ArgumentOutOfRangeException(nameof(RingsPerSegment), value, "RingsPerSegment must be in [1, 64].");
                ringsPerSegment = value;
            }
        }

        /// <summary>Texture v per metre of rest arc length (1/m), range (0, 10000]; the texture stretches with the material. Default 10.</summary>
        public float VPerMetre
        {
            get => vPerMetre;
            set
            {
                if (!float.IsFinite(value) || !(value > 0f) || value > 10000f)
                    throw new ArgumentOutOfRangeException(nameof(VPerMetre), value, "VPerMetre must be finite and in (0, 10000] 1/m.");
                vPerMetre = value;
            }
        }

        /// <summary>Close the two intact ends of the rope with flat caps (the intact mesh is then watertight). Default true. Broken ends are always closed.</summary>
        public bool CapEnds { get; set; } = true;

        /// <summary>Burr strands at broken ends.</summary>
        public BurrSettings Burr { get; } = new BurrSettings();
    }
}
