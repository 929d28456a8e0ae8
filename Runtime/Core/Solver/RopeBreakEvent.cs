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
        /// <summary>Elastic energy in joules the segment stored when it broke, ½·C²/α (0 for a slack or inextensible segment).</summary>
        public readonly double StoredEnergy;
        /// <summary>
        /// Kinetic energy in joules the recoil gave the two ends (<see cref="Rope.BreakSegment"/>): <see cref="StoredEnergy"/>,
        /// less what a substep too coarse for the recoil cannot carry (h &gt; L/c), 0 when both ends are kinematic.
        /// </summary>
        public readonly double RecoilEnergy;

        /// <summary>Creates an event (time s, position m, segment index, tension N); no stored or recoil energy.</summary>
        public RopeBreakEvent(double time, Float3 position, int segment, float tension)
            : this(time, position, segment, tension, 0.0, 0.0)
        {
        }

        /// <summary>Creates an event (time s, position m, segment index, tension N, stored and recoil energy J).</summary>
        public RopeBreakEvent(double time, Float3 position, int segment, float tension, double storedEnergy, double recoilEnergy)
        {
            Time = time;
            Position = position;
            Segment = segment;
            Tension = tension;
            StoredEnergy = storedEnergy;
            RecoilEnergy = recoilEnergy;
        }
    }
}
