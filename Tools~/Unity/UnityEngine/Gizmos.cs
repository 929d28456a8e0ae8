using HookeRope.StandIn;

namespace UnityEngine
{
    /// <summary>
    /// Stand-in of UnityEngine.Gizmos: nothing is drawn; each draw call is recorded with the current colour in
    /// HookeRope.StandIn.GizmoLog, so tests can assert what a gizmo method drew. The colour starts white.
    /// </summary>
    public sealed class Gizmos
    {
        /// <summary>Sets the Color of the gizmos that are drawn next.</summary>
        public static Color color
        {
            get => GizmoLog.Color;
            set => GizmoLog.Color = value;
        }

        /// <summary>Draws a line starting at from towards to.</summary>
        public static void DrawLine(Vector3 from, Vector3 to) => GizmoLog.Add(new GizmoCommand(GizmoShape.Line, GizmoLog.Color, from, to, 0f));

        /// <summary>Draws a wireframe sphere with center and radius.</summary>
        public static void DrawWireSphere(Vector3 center, float radius) => GizmoLog.Add(new GizmoCommand(GizmoShape.WireSphere, GizmoLog.Color, center, center, radius));

        /// <summary>Draws a solid sphere with center and radius.</summary>
        public static void DrawSphere(Vector3 center, float radius) => GizmoLog.Add(new GizmoCommand(GizmoShape.Sphere, GizmoLog.Color, center, center, radius));
    }
}
