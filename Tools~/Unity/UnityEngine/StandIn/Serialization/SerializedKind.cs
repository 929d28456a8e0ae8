namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: how Unity's serializer stores a value of a field's type.</summary>
    internal enum SerializedKind
    {
        /// <summary>Not serialized (Unity skips the field silently).</summary>
        None,
        /// <summary>bool.</summary>
        Boolean,
        /// <summary>sbyte, byte, short, ushort, int, uint, long, ulong.</summary>
        Integer,
        /// <summary>char (stored as its UTF-16 code).</summary>
        Character,
        /// <summary>float, double.</summary>
        Float,
        /// <summary>string.</summary>
        String,
        /// <summary>An enum whose underlying type is not 64-bit (stored as its integer value).</summary>
        Enum,
        /// <summary>A Unity value type with a native layout: Vector3, Quaternion, Color, LayerMask, Bounds.</summary>
        UnityStruct,
        /// <summary>A reference to a UnityEngine.Object (stored as a reference, never by value).</summary>
        ObjectReference,
        /// <summary>A [Serializable] class or struct: its serialized fields stored by value, inline.</summary>
        Composite,
        /// <summary>A one-dimensional array of a serializable element type.</summary>
        Array,
        /// <summary>A System.Collections.Generic.List&lt;T&gt; of a serializable element type.</summary>
        List,
    }
}
