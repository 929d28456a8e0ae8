using System;

namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.DrawGizmo: the DrawGizmo attribute allows you to supply a gizmo renderer for any Component.</summary>
    public sealed class DrawGizmo : Attribute
    {
        /// <summary>Defines when the gizmo should be invoked for drawing.</summary>
        public DrawGizmo(GizmoType gizmo) { }

        /// <summary>Same as above. drawnGizmoType determines of what type the object we are drawing the gizmo of has to be.</summary>
        public DrawGizmo(GizmoType gizmo, Type drawnGizmoType) { }
    }
}
