namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.EditorGUI: these work pretty much like the normal GUI functions - and also have matching implementations in EditorGUILayout.</summary>
    public sealed class EditorGUI
    {
        /// <summary>The indent level of the field labels.</summary>
        public static int indentLevel { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Create a group of controls that can be disabled.</summary>
        public static void BeginDisabledGroup(bool disabled) => throw Shim.NotRun;

        /// <summary>Ends a disabled group started with BeginDisabledGroup.</summary>
        public static void EndDisabledGroup() => throw Shim.NotRun;
    }
}
