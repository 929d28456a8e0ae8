using System;
using System.Collections.Generic;
using System.Globalization;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: a SerializedProperty path resolved against a script type, with Unity's naming: fields by
    /// name, nested fields "m_Start.m_Point", arrays and lists "m_Colliders.Array", "m_Colliders.Array.size" and
    /// "m_Colliders.Array.data[0]", and the float components of Vector3/Quaternion/Color ("m_Gravity.x").
    /// </summary>
    internal sealed class SerializedPath
    {
        SerializedPath(string path, string name, List<SerializedStep> steps, SerializedSlotType slot, SerializedRole role)
        {
            Path = path;
            Name = name;
            Steps = steps;
            Slot = slot;
            Role = role;
        }

        /// <summary>The property path.</summary>
        internal string Path { get; }

        /// <summary>The last path segment (Unity's SerializedProperty.name; "data" for array elements).</summary>
        internal string Name { get; }

        /// <summary>How to reach the value from the object.</summary>
        internal IReadOnlyList<SerializedStep> Steps { get; }

        /// <summary>The type of the value (int for Array.size).</summary>
        internal SerializedSlotType Slot { get; }

        internal SerializedRole Role { get; }

        /// <summary>The path <paramref name="path"/> on a script of <paramref name="rootType"/>, or null when no such property exists.</summary>
        internal static SerializedPath Resolve(Type rootType, string path)
        {
            if (string.IsNullOrEmpty(path)) return null;
            var segments = path.Split('.');
            var steps = new List<SerializedStep>();
            Type current = rootType;
            bool root = true;
            var role = SerializedRole.Value;
            string name = null;
            for (int i = 0; i < segments.Length; i++)
            {
                string segment = segments[i];
                name = segment;
                role = SerializedRole.Value;
                var kind = root ? SerializedKind.Composite : SerializedTypes.KindOf(current);
                if (kind == SerializedKind.Composite)
                {
                    var member = SerializedLayout.Of(current).Find(segment);
                    if (member == null) return null;
                    steps.Add(SerializedStep.Field(member));
                    current = member.Type;
                    root = false;
                    continue;
                }
                if (kind == SerializedKind.Array || kind == SerializedKind.List)
                {
                    if (segment != "Array") return null;
                    if (i + 1 == segments.Length) { role = SerializedRole.ArrayWrapper; break; }
                    string next = segments[++i];
                    name = next;
                    if (next == "size")
                    {
                        if (i + 1 != segments.Length) return null;
                        steps.Add(SerializedStep.Size);
                        current = typeof(int);
                        role = SerializedRole.ArraySize;
                        break;
                    }
                    if (!next.StartsWith("data[", StringComparison.Ordinal) || !next.EndsWith("]", StringComparison.Ordinal)) return null;
                    if (!int.TryParse(next.Substring(5, next.Length - 6), NumberStyles.None, CultureInfo.InvariantCulture, out int index)) return null;
                    steps.Add(SerializedStep.Element(index));
                    current = SerializedTypes.ElementType(current);
                    name = "data";
                    continue;
                }
                var components = UnityStructs.FloatComponents(current);
                int component = components != null ? Array.IndexOf(components, segment) : -1;
                if (component < 0) return null;
                steps.Add(SerializedStep.Component(component));
                current = typeof(float);
            }
            return new SerializedPath(path, name, steps, new SerializedSlotType(current), role);
        }
    }
}
