using System;
using System.Globalization;
using System.Reflection;
using HookeRope.StandIn;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    /// <summary>
    /// Stand-in of UnityEditor.SerializedProperty: one serialized field (or array size, array element, or Vector3 /
    /// Quaternion / Color component) of a <see cref="SerializedObject"/>, with Unity's paths and names. Values are
    /// read from the first target's copy; setting one writes every target's copy (applied later by
    /// ApplyModifiedProperties). A value accessor of the wrong type logs Unity's "type is not a supported … value"
    /// error and returns the default, as Unity does.
    /// </summary>
    public class SerializedProperty
    {
        readonly SerializedObject m_Owner;
        readonly SerializedPath m_Path;

        internal SerializedProperty(SerializedObject owner, SerializedPath path)
        {
            m_Owner = owner;
            m_Path = path;
        }

        /// <summary>SerializedObject this property belongs to (Read Only).</summary>
        public SerializedObject serializedObject => m_Owner;

        /// <summary>Name of the property (Read Only).</summary>
        public string name => m_Path.Name;

        /// <summary>Full path of the property (Read Only).</summary>
        public string propertyPath => m_Path.Path;

        /// <summary>Nesting depth of the property (Read Only).</summary>
        public int depth => m_Path.Path.Split('.').Length - 1;

        /// <summary>Type of this property (Read Only).</summary>
        public SerializedPropertyType propertyType
        {
            get
            {
                if (m_Path.Role == SerializedRole.ArraySize) return SerializedPropertyType.ArraySize;
                var slot = m_Path.Slot;
                switch (slot.Kind)
                {
                    case SerializedKind.Boolean: return SerializedPropertyType.Boolean;
                    case SerializedKind.Integer: return SerializedPropertyType.Integer;
                    case SerializedKind.Character: return SerializedPropertyType.Character;
                    case SerializedKind.Float: return SerializedPropertyType.Float;
                    case SerializedKind.String: return SerializedPropertyType.String;
                    case SerializedKind.Enum: return SerializedPropertyType.Enum;
                    case SerializedKind.ObjectReference: return SerializedPropertyType.ObjectReference;
                    case SerializedKind.UnityStruct:
                        if (slot.Type == typeof(Vector3)) return SerializedPropertyType.Vector3;
                        if (slot.Type == typeof(Quaternion)) return SerializedPropertyType.Quaternion;
                        if (slot.Type == typeof(Color)) return SerializedPropertyType.Color;
                        if (slot.Type == typeof(LayerMask)) return SerializedPropertyType.LayerMask;
                        return SerializedPropertyType.Bounds;
                    default: return SerializedPropertyType.Generic;
                }
            }
        }

        /// <summary>Is this property an array? (Read Only; true for arrays, lists and, as in Unity, strings.)</summary>
        public bool isArray => IsCollection || (m_Path.Role == SerializedRole.Value && m_Path.Slot.Kind == SerializedKind.String);

        /// <summary>The number of elements in the array (the smallest count when editing several objects).</summary>
        public int arraySize
        {
            get
            {
                if (m_Path.Slot.Kind == SerializedKind.String && m_Path.Role == SerializedRole.Value) return stringValue.Length;
                if (!IsCollection) throw StandInError.Unsupported("SerializedProperty.arraySize of a non-array property '" + propertyPath + "'");
                var size = SizePath();
                int smallest = int.MaxValue;
                for (int i = 0; i < m_Owner.TargetCount; i++)
                    if (m_Owner.Has(size, i)) smallest = Math.Min(smallest, (int)m_Owner.Read(size, i));
                return smallest == int.MaxValue ? 0 : smallest;
            }
            set
            {
                if (!IsCollection) throw StandInError.Unsupported("SerializedProperty.arraySize of a non-array property '" + propertyPath + "'");
                m_Owner.Write(SizePath(), value);
            }
        }

        /// <summary>Does this property represent multiple different values due to multi-object editing? (Read Only)</summary>
        public bool hasMultipleDifferentValues
        {
            get
            {
                if (m_Owner.TargetCount < 2) return false;
                var first = m_Owner.Read(m_Path, 0);
                for (int i = 1; i < m_Owner.TargetCount; i++)
                    if (!m_Owner.Has(m_Path, i) || !SerializedValues.DeepEquals(first, m_Owner.Read(m_Path, i), m_Path.Slot.Type)) return true;
                return false;
            }
        }

        /// <summary>Value of an integer property (also enums, characters, array sizes and layer masks).</summary>
        public int intValue
        {
            get => (int)longValue;
            set => longValue = value;
        }

        /// <summary>Value of an integer property as a long.</summary>
        public long longValue
        {
            get
            {
                if (!IsInteger) return Mismatch<long>("int");
                var value = Value;
                if (value is LayerMask mask) return mask.value;
                if (value is char c) return c;
                return value is ulong u ? unchecked((long)u) : Convert.ToInt64(value, CultureInfo.InvariantCulture);
            }
            set
            {
                if (!IsInteger) { Mismatch<long>("int"); return; }
                var type = m_Path.Slot.Type;
                object boxed;
                if (m_Path.Role == SerializedRole.ArraySize) boxed = unchecked((int)value);
                else if (type == typeof(LayerMask)) boxed = (LayerMask)unchecked((int)value);
                else if (type.IsEnum) boxed = Enum.ToObject(type, value);
                else boxed = Narrow(value, type);
                m_Owner.Write(m_Path, boxed);
            }
        }

        /// <summary>Value of a boolean property.</summary>
        public bool boolValue
        {
            get => m_Path.Slot.Kind == SerializedKind.Boolean ? (bool)Value : Mismatch<bool>("bool");
            set
            {
                if (m_Path.Slot.Kind != SerializedKind.Boolean) { Mismatch<bool>("bool"); return; }
                m_Owner.Write(m_Path, value);
            }
        }

        /// <summary>Value of a float property.</summary>
        public float floatValue
        {
            get => (float)doubleValue;
            set => doubleValue = value;
        }

        /// <summary>Value of a float property as a double.</summary>
        public double doubleValue
        {
            get => m_Path.Slot.Kind == SerializedKind.Float ? Convert.ToDouble(Value, CultureInfo.InvariantCulture) : Mismatch<double>("float");
            set
            {
                if (m_Path.Slot.Kind != SerializedKind.Float) { Mismatch<double>("float"); return; }
                m_Owner.Write(m_Path, m_Path.Slot.Type == typeof(double) ? (object)value : (float)value);
            }
        }

        /// <summary>Value of a string property.</summary>
        public string stringValue
        {
            get => m_Path.Slot.Kind == SerializedKind.String ? (string)Value ?? "" : Mismatch<string>("string");
            set
            {
                if (m_Path.Slot.Kind != SerializedKind.String) { Mismatch<string>("string"); return; }
                m_Owner.Write(m_Path, value ?? "");
            }
        }

        /// <summary>Value of a color property.</summary>
        public Color colorValue
        {
            get => Struct<Color>("color");
            set => SetStruct(value, "color");
        }

        /// <summary>Value of a 3D vector property.</summary>
        public Vector3 vector3Value
        {
            get => Struct<Vector3>("Vector3");
            set => SetStruct(value, "Vector3");
        }

        /// <summary>Value of a quaternion rotation property.</summary>
        public Quaternion quaternionValue
        {
            get => Struct<Quaternion>("Quaternion");
            set => SetStruct(value, "Quaternion");
        }

        /// <summary>Value of an object reference property.</summary>
        public Object objectReferenceValue
        {
            get => m_Path.Slot.Kind == SerializedKind.ObjectReference ? (Object)Value : Mismatch<Object>("pptr");
            set
            {
                if (m_Path.Slot.Kind != SerializedKind.ObjectReference) { Mismatch<Object>("pptr"); return; }
                if (!(value is null) && !m_Path.Slot.Type.IsInstanceOfType(value))
                    throw StandInError.Unsupported("SerializedProperty.objectReferenceValue = a " + value.GetType().Name + " on the " +
                                                   m_Path.Slot.Type.Name + " property '" + propertyPath + "'");
                m_Owner.Write(m_Path, value);
            }
        }

        /// <summary>Enum index of an enum property (index among the enum's names in declaration order; -1 for a value without a name).</summary>
        public int enumValueIndex
        {
            get
            {
                if (m_Path.Slot.Kind != SerializedKind.Enum) return Mismatch<int>("enum");
                var values = EnumValues(m_Path.Slot.Type);
                return Array.IndexOf(values, Value);
            }
            set
            {
                if (m_Path.Slot.Kind != SerializedKind.Enum) { Mismatch<int>("enum"); return; }
                var values = EnumValues(m_Path.Slot.Type);
                if (value < 0 || value >= values.Length)
                    throw StandInError.Unsupported("SerializedProperty.enumValueIndex = " + value + " outside the " + values.Length + " names of " + m_Path.Slot.Type.Name);
                m_Owner.Write(m_Path, values[value]);
            }
        }

        /// <summary>Names of enumeration of an enum property (declaration order).</summary>
        public string[] enumNames
        {
            get
            {
                if (m_Path.Slot.Kind != SerializedKind.Enum) return Mismatch<string[]>("enum") ?? Array.Empty<string>();
                var values = EnumValues(m_Path.Slot.Type);
                var names = new string[values.Length];
                for (int i = 0; i < values.Length; i++) names[i] = values[i].ToString();
                return names;
            }
        }

        /// <summary>Returns a copy of the SerializedProperty iterator in its current state.</summary>
        public SerializedProperty Copy() => new SerializedProperty(m_Owner, m_Path);

        /// <summary>Retrieves the SerializedProperty at a relative path to the current property (null when there is none).</summary>
        public SerializedProperty FindPropertyRelative(string relativePropertyPath) => m_Owner.FindProperty(propertyPath + "." + relativePropertyPath);

        /// <summary>Returns the element at the specified index in the array (null when out of range or not an array).</summary>
        public SerializedProperty GetArrayElementAtIndex(int index) =>
            IsCollection && index >= 0 ? m_Owner.FindProperty(ArrayBasePath() + ".Array.data[" + index.ToString(CultureInfo.InvariantCulture) + "]") : null;

        // ---- stand-in internals -----------------------------------------------------------------------------
        object Value => m_Owner.Read(m_Path, 0);

        bool IsCollection => m_Path.Role != SerializedRole.ArraySize && (m_Path.Slot.Kind == SerializedKind.Array || m_Path.Slot.Kind == SerializedKind.List);

        bool IsInteger =>
            m_Path.Role == SerializedRole.ArraySize || m_Path.Slot.Kind == SerializedKind.Integer || m_Path.Slot.Kind == SerializedKind.Enum ||
            m_Path.Slot.Kind == SerializedKind.Character || m_Path.Slot.Type == typeof(LayerMask);

        string ArrayBasePath() => m_Path.Role == SerializedRole.ArrayWrapper ? propertyPath.Substring(0, propertyPath.Length - ".Array".Length) : propertyPath;

        SerializedPath SizePath() => m_Owner.Resolve(ArrayBasePath() + ".Array.size");

        T Struct<T>(string what) => m_Path.Slot.Type == typeof(T) ? (T)Value : Mismatch<T>(what);

        void SetStruct<T>(T value, string what)
        {
            if (m_Path.Slot.Type != typeof(T)) { Mismatch<T>(what); return; }
            m_Owner.Write(m_Path, value);
        }

        static T Mismatch<T>(string what)
        {
            Debug.LogError("type is not a supported " + what + " value");
            return default;
        }

        static object Narrow(long value, Type type)
        {
            unchecked
            {
                if (type == typeof(sbyte)) return (sbyte)value;
                if (type == typeof(byte)) return (byte)value;
                if (type == typeof(short)) return (short)value;
                if (type == typeof(ushort)) return (ushort)value;
                if (type == typeof(int)) return (int)value;
                if (type == typeof(uint)) return (uint)value;
                if (type == typeof(ulong)) return (ulong)value;
                if (type == typeof(char)) return (char)value;
                return value;
            }
        }

        static object[] EnumValues(Type enumType)
        {
            var fields = enumType.GetFields(BindingFlags.Public | BindingFlags.Static);
            Array.Sort(fields, (a, b) => a.MetadataToken.CompareTo(b.MetadataToken));
            var values = new object[fields.Length];
            for (int i = 0; i < fields.Length; i++) values[i] = fields[i].GetValue(null);
            return values;
        }
    }
}
