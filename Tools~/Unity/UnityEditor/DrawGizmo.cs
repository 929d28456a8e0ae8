using System;

namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.DrawGizmo: the DrawGizmo attribute allows you to supply a gizmo renderer for any Component.</summary>
    [AttributeUsage(AttributeTargets.Method)]
    public sealed class DrawGizmo : Attribute
    {
        /// <summary>Flags to denote when the gizmo should be drawn.</summary>
        public GizmoType drawOptions;

        /// <summary>The type of object for which the gizmo should be drawn.</summary>
        public Type drawnType;

        /// <summary>Defines when the gizmo should be invoked for drawing.</summary>
        public DrawGizmo(GizmoType gizmo) => drawOptions = gizmo;

        /// <summary>Same as above. drawnGizmoType determines of what type the object we are drawing the gizmo of has to be.</summary>
        public DrawGizmo(GizmoType gizmo, Type drawnGizmoType)
        {
            drawnType = drawnGizmoType;
            drawOptions = gizmo;
        }
    }
}
