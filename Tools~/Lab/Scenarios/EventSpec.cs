using HookeRope.Mathematics;

namespace HookeRope.Lab.Scenarios
{
    /// <summary>What a timed event does.</summary>
    public enum EventKind
    {
        /// <summary>Moves a pinned end's target to <see cref="EventSpec.Vector"/> (m) at once.</summary>
        PinTarget,
        /// <summary>Moves a pinned end's target at <see cref="EventSpec.Vector"/> (m/s) from the event until <see cref="EventSpec.Until"/>.</summary>
        PinVelocity,
        /// <summary>Releases a pinned end (the particle keeps its velocity).</summary>
        ReleasePin,
        /// <summary>Adds the impulse <see cref="EventSpec.Vector"/> (N·s) to the particle nearest <see cref="EventSpec.At"/>.</summary>
        Impulse,
        /// <summary>Sets the XPBD constraint damping β to <see cref="EventSpec.Value"/> (s).</summary>
        Damping,
        /// <summary>Cuts the segment at <see cref="EventSpec.At"/> (fraction of the rest length from the start).</summary>
        Cut,
    }

    /// <summary>events[i] {…}: something that happens at a given simulated time (see Documentation~/lab.md).</summary>
    public sealed class EventSpec
    {
        /// <summary>Simulated time in s, in [0, duration].</summary>
        public double Time;
        /// <summary>What happens.</summary>
        public EventKind Kind;
        /// <summary>Which end (pin events): true = the start (particle 0), false = the end.</summary>
        public bool AtStart;
        /// <summary>Position (m), velocity (m/s) or impulse (N·s), by kind.</summary>
        public Float3 Vector;
        /// <summary>End of a velocity profile, s (the duration when not given).</summary>
        public double Until;
        /// <summary>Where along the rope (impulse, cut): fraction of the rest length from the start, 0…1.</summary>
        public double At = 1;
        /// <summary>Damping β in s.</summary>
        public double Value;
        /// <summary>The JSON type name.</summary>
        public string Type;

        /// <summary>A short description for the summary ("release the start pin").</summary>
        public string Describe()
        {
            string end = AtStart ? "start" : "end";
            string v = string.Format(System.Globalization.CultureInfo.InvariantCulture, "[{0:G4}, {1:G4}, {2:G4}]", Vector.X, Vector.Y, Vector.Z);
            switch (Kind)
            {
                case EventKind.PinTarget: return $"{end} pin target → {v} m";
                case EventKind.PinVelocity: return $"{end} pin moves at {v} m/s until {Until:G4} s";
                case EventKind.ReleasePin: return $"release the {end} pin";
                case EventKind.Impulse: return $"impulse {v} N·s at {At:G3} of the length";
                case EventKind.Damping: return $"damping β → {Value:G4} s";
                default: return $"cut at {At:G3} of the length";
            }
        }
    }
}
