using System;
using HookeRope.StandIn;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.Editor: the base class of custom inspectors. <see cref="CreateEditor(Object)"/> picks
    /// the [CustomEditor] class, sets the targets, then sends the editor Awake and OnEnable (it is a
    /// ScriptableObject), so an inspector's OnEnable can find its properties. Drawing (OnInspectorGUI) needs IMGUI,
    /// which the stand-in does not have.
    /// </summary>
    public class Editor : ScriptableObject
    {
        Object[] m_Targets = Array.Empty<Object>();
        SerializedObject m_SerializedObject;

        /// <summary>The object being inspected.</summary>
        public Object target
        {
            get => m_Targets.Length > 0 ? m_Targets[0] : null;
            set => throw new InvalidOperationException("You can't set the target on an editor.");
        }

        /// <summary>An array of all the object being inspected.</summary>
        public Object[] targets => m_Targets;

        /// <summary>A SerializedObject representing the object or objects being inspected.</summary>
        public SerializedObject serializedObject => m_SerializedObject ??= new SerializedObject(m_Targets);

        /// <summary>Implement this function to make a custom inspector (the default inspector needs IMGUI).</summary>
        public virtual void OnInspectorGUI() => throw StandInError.Unsupported("Editor.OnInspectorGUI (the default inspector draws with IMGUI)");

        /// <summary>Checks if this editor requires constant repaints in its current state.</summary>
        public virtual bool RequiresConstantRepaint() => false;

        /// <summary>Redraw any inspectors that shows this editor (the stand-in shows none: nothing to do).</summary>
        public void Repaint() { }

        /// <summary>Make a custom editor for targetObject.</summary>
        public static Editor CreateEditor(Object targetObject) => CreateEditor(new[] { targetObject }, null);

        /// <summary>Make a custom editor of editorType (or the [CustomEditor] one when null) for targetObject.</summary>
        public static Editor CreateEditor(Object targetObject, Type editorType) => CreateEditor(new[] { targetObject }, editorType);

        /// <summary>Make a custom editor for targetObjects.</summary>
        public static Editor CreateEditor(Object[] targetObjects) => CreateEditor(targetObjects, null);

        /// <summary>Make a custom editor of editorType (or the [CustomEditor] one when null) for targetObjects.</summary>
        public static Editor CreateEditor(Object[] targetObjects, Type editorType)
        {
            if (editorType != null && !editorType.IsSubclassOf(typeof(Editor)))
                throw new ArgumentException($"Editor type '{editorType}' does not derive from UnityEditor.Editor", nameof(editorType));
            if (targetObjects == null || targetObjects.Length == 0 || targetObjects[0] == null) return null;
            var type = editorType ?? CustomEditors.For(targetObjects[0].GetType());
            var editor = (Editor)Construct(type);
            editor.m_Targets = (Object[])targetObjects.Clone();
            editor.SendCreateMessages();
            return editor;
        }
    }
}
