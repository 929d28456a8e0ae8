using System;
using System.Collections.Generic;
using System.Reflection;
using UnityEngine;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: the fields Unity serializes on a type, in Unity's order (base class first, then declaration
    /// order), reflected once and cached. A field is serialized when it is public or marked [SerializeField], is not
    /// static, const, readonly or [NonSerialized], and its type is serializable (<see cref="SerializedTypes"/>);
    /// Scripting Reference "SerializeField" (2022.3). For scripts (MonoBehaviour, ScriptableObject) only the fields of
    /// the script classes count: Unity's own base classes keep their data natively.
    /// </summary>
    internal sealed class SerializedLayout
    {
        /// <summary>Unity's limit on nesting serializable classes inside each other (deeper levels are not stored).</summary>
        internal const int MaxDepth = 10;

        static readonly Dictionary<Type, SerializedLayout> s_Cache = new Dictionary<Type, SerializedLayout>();
        readonly Dictionary<string, SerializedMember> m_ByName = new Dictionary<string, SerializedMember>(StringComparer.Ordinal);

        SerializedLayout(Type type, SerializedMember[] members)
        {
            Type = type;
            Members = members;
            foreach (var member in members) m_ByName[member.Name] = member;
        }

        /// <summary>The reflected type.</summary>
        internal Type Type { get; }

        /// <summary>The serialized fields in Unity's order.</summary>
        internal IReadOnlyList<SerializedMember> Members { get; }

        /// <summary>The serialized field named <paramref name="name"/>, or null.</summary>
        internal SerializedMember Find(string name) => m_ByName.TryGetValue(name, out var member) ? member : null;

        /// <summary>The layout of <paramref name="type"/> (cached).</summary>
        internal static SerializedLayout Of(Type type)
        {
            lock (s_Cache)
            {
                if (s_Cache.TryGetValue(type, out var cached)) return cached;
            }
            var layout = new SerializedLayout(type, Reflect(type));
            lock (s_Cache) s_Cache[type] = layout;
            return layout;
        }

        /// <summary>True when Unity would serialize <paramref name="field"/>.</summary>
        internal static bool IsSerialized(FieldInfo field)
        {
            if (field.IsStatic || field.IsLiteral || field.IsInitOnly || field.IsNotSerialized) return false;
            if (!field.IsPublic && !Attribute.IsDefined(field, typeof(SerializeField), false)) return false;
            return SerializedTypes.KindOf(field.FieldType) != SerializedKind.None;
        }

        static SerializedMember[] Reflect(Type type)
        {
            var chain = new List<Type>();
            bool script = typeof(Object).IsAssignableFrom(type);
            for (var t = type; t != null && t != typeof(object); t = t.BaseType)
            {
                if (script && IsEngineType(t)) break;
                chain.Add(t);
            }
            var members = new List<SerializedMember>();
            const BindingFlags Declared = BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly;
            for (int i = chain.Count - 1; i >= 0; i--)
            {
                var fields = chain[i].GetFields(Declared);
                Array.Sort(fields, (a, b) => a.MetadataToken.CompareTo(b.MetadataToken));
                foreach (var field in fields)
                    if (IsSerialized(field)) members.Add(new SerializedMember(field));
            }
            return members.ToArray();
        }

        /// <summary>Unity's own classes (the stand-in's UnityEngine and UnityEditor assemblies).</summary>
        static bool IsEngineType(Type t)
        {
            var name = t.Assembly.GetName().Name;
            return name == "UnityEngine" || name == "UnityEditor";
        }
    }
}
