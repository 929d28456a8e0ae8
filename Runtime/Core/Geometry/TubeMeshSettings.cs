using System;
using HookeRope.Fracture;

namespace HookeRope.Geometry
{
    /// <summary>
    /// Validated settings of the procedural tube mesh. Ranges come from <see cref="RopeParameters"/>: setters throw
    /// <see cref="ArgumentOutOfRangeException"/> naming the property, its range and unit. RadialSegments, RingsPerSegment,
    /// AdaptiveRings, CapEnds and Burr.Enabled fix the topology and are read when a <see cref="TubeMeshBuilder"/> is
    /// created; RingTolerance, VPerMetre and the other burr values are read at every build.
    /// </summary>
    public sealed class TubeMeshSettings
    {
        private int radialSegments = RopeParameters.RadialSegments.Default;
        private int ringsPerSegment = RopeParameters.RingsPerSegment.Default;
        private float vPerMetre = RopeParameters.VPerMetre.Default;
        private float ringTolerance = RopeParameters.RingTolerance.Default;

        /// <summary>Vertices around the tube, range [3, 64] (the paper shows 8, 16, 32). Default 12.</summary>
        public int RadialSegments { get => radialSegments; set => radialSegments = RopeParameters.Check(value, RopeParameters.RadialSegments.Row); }

        /// <summary>
        /// How far the adaptive rings (<see cref="AdaptiveRings"/>) let the drawn surface leave the smooth tube along the
        /// rope, as a multiple of the polygon's own depth around it, R·(1 − cos π/<see cref="RadialSegments"/>); range
        /// [1, 16], default 1 (as round along as around). The ring count of a bent segment goes as 1/sqrt(RingTolerance): 2
        /// draws about 30 % fewer rings, 4 half as many (never fewer than one per segment), for scenes with many ropes whose
        /// mesh costs more than their physics. Read at every build: a new value (e.g. set each frame from the rope's distance
        /// to the camera) allocates nothing and needs no new buffers; the ring budget takes more rings at once and gives
        /// them back after a calm spell, as for any change of need. Not used when AdaptiveRings is off, nor for a Zone
        /// neck's stations.
        /// </summary>
        public float RingTolerance { get => ringTolerance; set => ringTolerance = RopeParameters.Check(value, RopeParameters.RingTolerance.Row); }

        /// <summary>Rings per rope segment along the smooth curve when <see cref="AdaptiveRings"/> is off, range [1, 64]. Default 4.</summary>
        public int RingsPerSegment { get => ringsPerSegment; set => ringsPerSegment = RopeParameters.Check(value, RopeParameters.RingsPerSegment.Row); }

        /// <summary>
        /// Place the rings by need (default true): one per segment where the rope is straight, up to 16 where it bends
        /// within a ring budget of 8 per segment on average over each unbroken piece (a rope that wants more has its rings
        /// redistributed within it; Documentation~/radius-and-mesh.md, "Ring budget"), and a Zone neck's stations while it necks, so that the drawn surface stays within 1 − cos(π/RadialSegments) of
        /// the drawn radius of the smooth tube (the polygon's own error around the tube: 1.9 % at 16 sides). Off:
        /// <see cref="RingsPerSegment"/> rings in every segment (and the neck's stations in Zone mode).
        /// </summary>
        public bool AdaptiveRings { get; set; } = RopeParameters.AdaptiveRings.Default;

        /// <summary>Texture v per metre of rest arc length (1/m), range (0, 10000]; the texture stretches with the material. Default 10.</summary>
        public float VPerMetre { get => vPerMetre; set => vPerMetre = RopeParameters.Check(value, RopeParameters.VPerMetre.Row); }

        /// <summary>Close the two intact ends of the rope with flat caps (the intact mesh is then watertight). Default true. Broken ends are always closed.</summary>
        public bool CapEnds { get; set; } = RopeParameters.CapEnds.Default;

        /// <summary>Burr strands at broken ends.</summary>
        public BurrSettings Burr { get; } = new BurrSettings();
    }
}
