namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.GizmoType: determines how a gizmo is drawn or picked in the Unity editor.</summary>
    [System.Flags]
    public enum GizmoType
    {
        /// <summary>The gizmo can be picked in the editor.</summary>
        Pickable = 1,
        /// <summary>Draw the gizmo if it is not selected or child of the selection.</summary>
        NotInSelectionHierarchy = 2,
        /// <summary>Draw the gizmo if it is selected.</summary>
        Selected = 4,
        /// <summary>Draw the gizmo if it is active (shown in the inspector).</summary>
        Active = 8,
        /// <summary>Draw the gizmo if it is selected or a child of the selection.</summary>
        InSelectionHierarchy = 16,
        /// <summary>Draw the gizmo if it is not selected.</summary>
        NonSelected = 32,
    }
}
