using System;
using System.Collections.Generic;
using UnityEngine;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: which types Unity's serializer can store, and how (Scripting Reference "SerializeField",
    /// 2022.3: UnityEngine.Object references; primitive types; enums (not 64-bit: EnumDataUtility marks long/ulong
    /// enums unserializable); string; Unity's built-in value types; [Serializable] classes and structs by value;
    /// one-dimensional arrays and List&lt;T&gt; of those, but not arrays of arrays or lists of lists).
    /// Classification is cached per type. A UnityEngine type the stand-in does not know how to store throws
    /// instead of being skipped, so a new Unity field type fails loudly.
    /// </summary>
    internal static class SerializedTypes
    {
        static readonly Dictionary<Type, SerializedKind> s_Kinds = new Dictionary<Type, SerializedKind>();

        /// <summary>Unity value types the stand-in stores (their YAML and property layout is in <see cref="UnityStructs"/>).</summary>
        internal static bool IsUnityStruct(Type type) =>
            type == typeof(Vector3) || type == typeof(Quaternion) || type == typeof(Color) || type == typeof(LayerMask) || type == typeof(Bounds);

        /// <summary>How a value of <paramref name="type"/> is stored, or <see cref="SerializedKind.None"/>.</summary>
        internal static SerializedKind KindOf(Type type)
        {
            lock (s_Kinds)
            {
                if (s_Kinds.TryGetValue(type, out var cached)) return cached;
            }
            var kind = Classify(type);
            lock (s_Kinds) s_Kinds[type] = kind;
            return kind;
        }

        /// <summary>Element type of an array or List&lt;T&gt;; null for other kinds.</summary>
        internal static Type ElementType(Type collection)
        {
            if (collection.IsArray) return collection.GetElementType();
            if (collection.IsGenericType && collection.GetGenericTypeDefinition() == typeof(List<>)) return collection.GetGenericArguments()[0];
            return null;
        }

        static SerializedKind Classify(Type type)
        {
            if (type == typeof(bool)) return SerializedKind.Boolean;
            if (type == typeof(sbyte) || type == typeof(byte) || type == typeof(short) || type == typeof(ushort) ||
                type == typeof(int) || type == typeof(uint) || type == typeof(long) || type == typeof(ulong))
                return SerializedKind.Integer;
            if (type == typeof(char)) return SerializedKind.Character;
            if (type == typeof(float) || type == typeof(double)) return SerializedKind.Float;
            if (type == typeof(string)) return SerializedKind.String;
            if (type.IsEnum)
            {
                var underlying = Enum.GetUnderlyingType(type);
                return underlying == typeof(long) || underlying == typeof(ulong) ? SerializedKind.None : SerializedKind.Enum;
            }
            if (typeof(Object).IsAssignableFrom(type)) return SerializedKind.ObjectReference;
            if (IsUnityStruct(type)) return SerializedKind.UnityStruct;
            if (type.IsArray)
                return type.GetArrayRank() == 1 && IsElementType(type.GetElementType()) ? SerializedKind.Array : SerializedKind.None;
            if (type.IsGenericType && type.GetGenericTypeDefinition() == typeof(List<>))
                return IsElementType(type.GetGenericArguments()[0]) ? SerializedKind.List : SerializedKind.None;
            if (type.IsPointer || type.IsInterface || type.IsAbstract || type.ContainsGenericParameters || typeof(Delegate).IsAssignableFrom(type))
                return SerializedKind.None;
            if (type.Assembly == typeof(object).Assembly || (type.Namespace ?? "").StartsWith("System", StringComparison.Ordinal))
                return SerializedKind.None;
            if (type.IsSerializable && (type.IsClass || type.IsValueType)) return SerializedKind.Composite;
            if (type.Assembly == typeof(Object).Assembly)
                throw StandInError.Unsupported("serialization of fields of type " + type.FullName);
            return SerializedKind.None;
        }

        static bool IsElementType(Type element)
        {
            var kind = KindOf(element);
            return kind != SerializedKind.None && kind != SerializedKind.Array && kind != SerializedKind.List;
        }
    }
}
