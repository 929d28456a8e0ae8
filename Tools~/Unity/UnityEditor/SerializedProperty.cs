namespace UnityEditor
{
    /// <summary>Shim of UnityEditor.SerializedProperty: SerializedProperty and SerializedObject are classes for editing properties on objects in a completely generic way.</summary>
    public class SerializedProperty
    {
        internal SerializedProperty() { }

        /// <summary>Value of a float property.</summary>
        public float floatValue { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Value of an integer property.</summary>
        public int intValue { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Value of a boolean property.</summary>
        public bool boolValue { get => throw Shim.NotRun; set => throw Shim.NotRun; }

        /// <summary>Does this property represent multiple different values due to multi-object editing? (Read Only)</summary>
        public bool hasMultipleDifferentValues => throw Shim.NotRun;
    }
}
