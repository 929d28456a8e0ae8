using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>Raised through <see cref="Rope.Broken"/> when a segment breaks.</summary>
    public readonly struct RopeBreakEvent
    {
        /// <summary>Simulated time of the break in seconds since the rope was created (see <see cref="Rope.Time"/>).</summary>
        public readonly double Time;
        /// <summary>World position of the broken segment's midpoint in metres, where it parts (each side keeps half of it).</summary>
        public readonly Float3 Position;
        /// <summary>Index of the broken segment (0 = the segment between particles 0 and 1).</summary>
        public readonly int Segment;
        /// <summary>Tension of the segment in newtons just before it broke (≥ 0 = pulling).</summary>
        public readonly float Tension;
        /// <summary>
        /// Elastic energy in joules the segment stored when it broke (½·C²/α), released into the recoil of its two ends
        /// (see <see cref="Rope.BreakSegment"/>); 0 for a slack or inextensible segment.
        /// </summary>
        public readonly double ReleasedEnergy;

        /// <summary>Creates an event (time s, position m, segment index, tension N); no released energy.</summary>
        public RopeBreakEvent(double time, Float3 position, int segment, float tension)
            : this(time, position, segment, tension, 0.0)
        {
        }

        /// <summary>Creates an event (time s, position m, segment index, tension N, released elastic energy J).</summary>
        public RopeBreakEvent(double time, Float3 position, int segment, float tension, double releasedEnergy)
        {
            Time = time;
            Position = position;
            Segment = segment;
            Tension = tension;
            ReleasedEnergy = releasedEnergy;
        }
    }
}
