namespace UnityEditor
{
    /// <summary>Stand-in of UnityEditor.SerializedPropertyType: type of a SerializedProperty (values as in Unity 2022.3).</summary>
    public enum SerializedPropertyType
    {
        /// <summary>Struct, array or class that is serialized by value.</summary>
        Generic = -1,
        /// <summary>Integer property.</summary>
        Integer = 0,
        /// <summary>Boolean property.</summary>
        Boolean = 1,
        /// <summary>Float property.</summary>
        Float = 2,
        /// <summary>String property.</summary>
        String = 3,
        /// <summary>Color property.</summary>
        Color = 4,
        /// <summary>Reference to another object.</summary>
        ObjectReference = 5,
        /// <summary>LayerMask property.</summary>
        LayerMask = 6,
        /// <summary>Enumeration property.</summary>
        Enum = 7,
        /// <summary>2D vector property.</summary>
        Vector2 = 8,
        /// <summary>3D vector property.</summary>
        Vector3 = 9,
        /// <summary>4D vector property.</summary>
        Vector4 = 10,
        /// <summary>Rectangle property.</summary>
        Rect = 11,
        /// <summary>Array size property.</summary>
        ArraySize = 12,
        /// <summary>Character property.</summary>
        Character = 13,
        /// <summary>AnimationCurve property.</summary>
        AnimationCurve = 14,
        /// <summary>Bounds property.</summary>
        Bounds = 15,
        /// <summary>Gradient property.</summary>
        Gradient = 16,
        /// <summary>Quaternion property.</summary>
        Quaternion = 17,
        /// <summary>A reference to another Object in the Scene.</summary>
        ExposedReference = 18,
        /// <summary>Fixed buffer size property.</summary>
        FixedBufferSize = 19,
        /// <summary>2D integer vector property.</summary>
        Vector2Int = 20,
        /// <summary>3D integer vector property.</summary>
        Vector3Int = 21,
        /// <summary>Rectangle with Integer values property.</summary>
        RectInt = 22,
        /// <summary>Bounds with Integer values property.</summary>
        BoundsInt = 23,
        /// <summary>Property is a reference to an object in a managed reference.</summary>
        ManagedReference = 24,
        /// <summary>Hash128 property.</summary>
        Hash128 = 25,
    }
}
