using HookeRope.Mathematics;

namespace HookeRope.Solver
{
    /// <summary>Raised through <see cref="Rope.Broken"/> when a segment breaks.</summary>
    public readonly struct RopeBreakEvent
    {
        /// <summary>Simulated time of the break in seconds since the rope was created (see <see cref="Rope.Time"/>).</summary>
        public readonly double Time;
        /// <summary>World position of the broken segment's midpoint in metres.</summary>
        public readonly Float3 Position;
        /// <summary>Index of the broken segment (0 = the segment between particles 0 and 1).</summary>
        public readonly int Segment;
        /// <summary>Tension of the segment in newtons just before it broke (≥ 0 = pulling).</summary>
        public readonly float Tension;

        /// <summary>Creates an event (time s, position m, segment index, tension N).</summary>
        public RopeBreakEvent(double time, Float3 position, int segment, float tension)
        {
            Time = time;
            Position = position;
            Segment = segment;
            Tension = tension;
        }
    }
}
