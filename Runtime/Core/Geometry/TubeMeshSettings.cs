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
            set => radialSegments = Require.InRange(value, 3, 64, nameof(RadialSegments));
        }

        /// <summary>Rings per rope segment along the smooth curve, range [1, 64]. Default 4.</summary>
        public int RingsPerSegment
        {
            get => ringsPerSegment;
            set => ringsPerSegment = Require.InRange(value, 1, 64, nameof(RingsPerSegment));
        }

        /// <summary>Texture v per metre of rest arc length (1/m), range (0, 10000]; the texture stretches with the material. Default 10.</summary>
        public float VPerMetre
        {
            get => vPerMetre;
            set => vPerMetre = Require.InOpenClosedRange(value, 0f, 10000f, nameof(VPerMetre), "1/m");
        }

        /// <summary>Close the two intact ends of the rope with flat caps (the intact mesh is then watertight). Default true. Broken ends are always closed.</summary>
        public bool CapEnds { get; set; } = true;

        /// <summary>Burr strands at broken ends.</summary>
        public BurrSettings Burr { get; } = new BurrSettings();
    }
}
