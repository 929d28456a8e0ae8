using System;
using UnityEngine;

namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.CustomEditor: tells an Editor class which run-time type it's an editor for.</summary>
    public class CustomEditor : Attribute
    {
        /// <summary>Defines which object type the custom editor class can edit.</summary>
        public CustomEditor(Type inspectedType) : this(inspectedType, false) { }

        /// <summary>Defines which object type the custom editor class can edit, and whether it also edits child classes.</summary>
        public CustomEditor(Type inspectedType, bool editorForChildClasses)
        {
            if (inspectedType == null) Debug.LogError("Failed to load CustomEditor inspected type");
            m_InspectedType = inspectedType;
            m_EditorForChildClasses = editorForChildClasses;
        }

        internal Type m_InspectedType;
        internal bool m_EditorForChildClasses;

        /// <summary>If true, match this editor only if all non-fallback editors do not match.</summary>
        public bool isFallback { get; set; }
    }
}
