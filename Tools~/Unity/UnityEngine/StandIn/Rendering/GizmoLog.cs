using System.Collections.Generic;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: the recorded Gizmos draw calls and the current Gizmos.color; World.Reset clears them and resets the colour to white.</summary>
    internal static class GizmoLog
    {
        static readonly List<GizmoCommand> s_Commands = new List<GizmoCommand>();

        static GizmoLog() => World.WorldReset += Clear;

        /// <summary>Gizmos.color (white until set).</summary>
        internal static Color Color { get; set; } = Color.white;

        /// <summary>The draw calls since the last Clear, oldest first.</summary>
        internal static IReadOnlyList<GizmoCommand> Commands => s_Commands;

        /// <summary>Records a draw call.</summary>
        internal static void Add(GizmoCommand command) => s_Commands.Add(command);

        /// <summary>Forgets the recorded calls and resets the colour to white.</summary>
        internal static void Clear()
        {
            s_Commands.Clear();
            Color = Color.white;
        }
    }
}
