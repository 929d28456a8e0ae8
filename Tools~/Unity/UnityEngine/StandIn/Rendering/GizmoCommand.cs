using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: one recorded Gizmos draw call.</summary>
    internal readonly struct GizmoCommand
    {
        /// <summary>Records a draw call.</summary>
        internal GizmoCommand(GizmoShape shape, Color color, Vector3 from, Vector3 to, float radius)
        {
            Shape = shape;
            Color = color;
            From = from;
            To = to;
            Radius = radius;
        }

        /// <summary>Which Gizmos method was called.</summary>
        internal GizmoShape Shape { get; }

        /// <summary>Gizmos.color at the call.</summary>
        internal Color Color { get; }

        /// <summary>Line start, or sphere centre.</summary>
        internal Vector3 From { get; }

        /// <summary>Line end (sphere centre for spheres).</summary>
        internal Vector3 To { get; }

        /// <summary>Sphere radius (0 for lines).</summary>
        internal float Radius { get; }

        /// <summary>"Shape color from→to r".</summary>
        public override string ToString() => Shape + " " + Color + " " + From + "→" + To + " r=" + Radius;
    }
}
