using System;

namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.CustomEditor: tells an Editor class which run-time type it's an editor for.</summary>
    public class CustomEditor : Attribute
    {
        /// <summary>Defines which object type the custom editor class can edit.</summary>
        public CustomEditor(Type inspectedType) { }
    }
}
