namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.SerializedObject: SerializedObject and SerializedProperty are classes for editing serialized fields on Unity objects.</summary>
    public class SerializedObject
    {
        /// <summary>Create SerializedObject for inspected object.</summary>
        public SerializedObject(UnityEngine.Object obj) => throw Shim.NotRun;

        /// <summary>Does the serialized object represents multiple objects due to multi-object editing? (Read Only)</summary>
        public bool isEditingMultipleObjects => throw Shim.NotRun;

        /// <summary>Update serialized object's representation.</summary>
        public void Update() => throw Shim.NotRun;

        /// <summary>Apply property modifications.</summary>
        public bool ApplyModifiedProperties() => throw Shim.NotRun;

        /// <summary>Find serialized property by name.</summary>
        public SerializedProperty FindProperty(string propertyPath) => throw Shim.NotRun;
    }
}
