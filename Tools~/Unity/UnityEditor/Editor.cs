namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.Editor: derive from this base class to create a custom inspector or editor for your custom object.</summary>
    public class Editor : UnityEngine.ScriptableObject
    {
        /// <summary>The object being inspected.</summary>
        public UnityEngine.Object target { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>An array of all the object being inspected.</summary>
        public UnityEngine.Object[] targets => throw Shim.NotRun;

        /// <summary>A SerializedObject representing the object or objects being inspected.</summary>
        public SerializedObject serializedObject => throw Shim.NotRun;

        /// <summary>Implement this function to make a custom inspector.</summary>
        public virtual void OnInspectorGUI() => throw Shim.NotRun;

        /// <summary>Checks if this editor requires constant repaints in its current state.</summary>
        public virtual bool RequiresConstantRepaint() => throw Shim.NotRun;

        /// <summary>Redraw any inspectors that shows this editor.</summary>
        public void Repaint() => throw Shim.NotRun;
    }
}
