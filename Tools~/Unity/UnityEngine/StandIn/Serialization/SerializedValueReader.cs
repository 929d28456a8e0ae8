using System;
using System.Collections;
using System.Collections.Generic;
using System.Globalization;
using UnityEngine;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: writes the serialized values of a Unity YAML mapping into the fields of a script (or of a
    /// [Serializable] class inside it), as Unity deserializes: every key must name a serialized field of the class
    /// (anything else is an error naming the file, line and field — a renamed field fails instead of silently keeping
    /// its default), values are converted by the field's serialized kind (bool 0/1, integers, floats with
    /// Infinity/NaN, strings, enums by value, Vector3/Quaternion/Color/LayerMask/Bounds, object references,
    /// nested classes, arrays and lists). Fields the file does not mention keep their constructor values and are
    /// listed in <see cref="MissingFields"/>.
    /// </summary>
    internal sealed class SerializedValueReader
    {
        readonly string m_File;
        readonly Func<YamlMapping, Type, string, Object> m_Resolve;

        /// <param name="file">The file name used in errors.</param>
        /// <param name="resolve">Resolves a {fileID: …, guid: …} mapping to an object of the expected type (third argument: the field path, for errors).</param>
        internal SerializedValueReader(string file, Func<YamlMapping, Type, string, Object> resolve)
        {
            m_File = file;
            m_Resolve = resolve;
        }

        /// <summary>Serialized fields ("Type.path") the file did not mention; they keep their constructor values.</summary>
        internal List<string> MissingFields { get; } = new List<string>();

        /// <summary>Reads <paramref name="body"/> into the serialized fields of <paramref name="target"/>; keys in <paramref name="skip"/> are Unity's own header fields.</summary>
        internal void ReadFields(object target, YamlMapping body, ICollection<string> skip, string path)
        {
            ReadMembers(target, target.GetType(), body, skip, path, 0);
        }

        /// <summary>Reads one value of <paramref name="type"/> (any serializable kind) from <paramref name="node"/>.</summary>
        internal object ReadValue(YamlNode node, Type type, string path)
        {
            var kind = SerializedTypes.KindOf(type);
            var elementType = SerializedTypes.ElementType(type);
            var elementKind = elementType != null ? SerializedTypes.KindOf(elementType) : SerializedKind.None;
            return Read(node, type, kind, elementType, elementKind, null, path, 0);
        }

        void ReadMembers(object target, Type type, YamlMapping body, ICollection<string> skip, string path, int depth)
        {
            var layout = SerializedLayout.Of(type);
            foreach (var entry in body.Entries)
            {
                if (skip != null && skip.Contains(entry.Key)) continue;
                var member = layout.Find(entry.Key);
                if (member == null) throw UnknownField(type, entry, path);
                string fieldPath = path + "." + member.Name;
                object existing = member.Field.GetValue(target);
                member.Field.SetValue(target, Read(entry.Value, member.Type, member.Kind, member.ElementType, member.ElementKind, existing, fieldPath, depth));
            }
            foreach (var member in layout.Members)
                if (body.Find(member.Name) == null) MissingFields.Add(path + "." + member.Name);
        }

        FormatException UnknownField(Type type, YamlEntry entry, string path)
        {
            var field = type.GetField(entry.Key, System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.NonPublic);
            string why = field == null
                ? type.FullName + " has no field of that name (renamed or removed?)"
                : type.FullName + " has a field of that name but Unity does not serialize it (it must be public or [SerializeField], not static/readonly/[NonSerialized], of a serializable type)";
            return YamlError.At(m_File, entry.Line, "field '" + entry.Key + "' of " + path + " does not map: " + why);
        }

        object Read(YamlNode node, Type type, SerializedKind kind, Type elementType, SerializedKind elementKind, object existing, string path, int depth)
        {
            switch (kind)
            {
                case SerializedKind.Boolean:
                {
                    string text = Scalar(node, path, type);
                    if (text == "0") return false;
                    if (text == "1") return true;
                    throw Bad(node, path, type, "expected 0 or 1");
                }
                case SerializedKind.Integer: return Integer(node, path, type);
                case SerializedKind.Character: return (char)(ushort)Integer(node, path, typeof(ushort));
                case SerializedKind.Float:
                {
                    string text = Scalar(node, path, type);
                    if (!double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double value)) throw Bad(node, path, type, "not a number");
                    return type == typeof(float) ? (object)(float)value : value;
                }
                case SerializedKind.String: return Scalar(node, path, type);
                case SerializedKind.Enum:
                {
                    var underlying = Enum.GetUnderlyingType(type);
                    return Enum.ToObject(type, Integer(node, path, underlying));
                }
                case SerializedKind.UnityStruct: return UnityStruct(node, type, path);
                case SerializedKind.ObjectReference:
                {
                    var map = node as YamlMapping ?? throw Bad(node, path, type, "expected an object reference {fileID: …}");
                    return m_Resolve(map, type, path);
                }
                case SerializedKind.Composite:
                {
                    if (depth >= SerializedLayout.MaxDepth) return type.IsValueType ? Activator.CreateInstance(type) : null;
                    var map = node as YamlMapping;
                    if (map == null && !(node is YamlScalar empty && empty.Value.Length == 0 && !empty.Quoted))
                        throw Bad(node, path, type, "expected the fields of " + type.Name);
                    object target = existing != null && existing.GetType() == type ? existing : SerializedInstances.Create(type);
                    if (map != null) ReadMembers(target, type, map, null, path, depth + 1);
                    else foreach (var member in SerializedLayout.Of(type).Members) MissingFields.Add(path + "." + member.Name);
                    return target;
                }
                case SerializedKind.Array:
                case SerializedKind.List:
                    return Collection(node, type, elementType, elementKind, path, depth);
                default:
                    throw Bad(node, path, type, "type is not serialized");
            }
        }

        object Collection(YamlNode node, Type type, Type elementType, SerializedKind elementKind, string path, int depth)
        {
            var items = new List<object>();
            if (node is YamlSequence seq)
            {
                for (int i = 0; i < seq.Items.Count; i++)
                    items.Add(Read(seq.Items[i], elementType, elementKind, null, SerializedKind.None, null, path + ".Array.data[" + i + "]", depth));
            }
            else if (node is YamlScalar hex && !hex.Quoted && (elementType == typeof(byte) || elementType == typeof(sbyte)))
            {
                // Unity writes byte arrays as one hexadecimal string.
                string text = hex.Value;
                if (text.Length % 2 != 0) throw Bad(node, path, type, "odd-length hex byte string");
                for (int i = 0; i < text.Length; i += 2)
                {
                    if (!byte.TryParse(text.Substring(i, 2), NumberStyles.HexNumber, CultureInfo.InvariantCulture, out byte b)) throw Bad(node, path, type, "not a hex byte string");
                    items.Add(elementType == typeof(byte) ? (object)b : unchecked((sbyte)b));
                }
            }
            else throw Bad(node, path, type, "expected a sequence ([] or '- ' items)");
            if (type.IsArray)
            {
                var array = Array.CreateInstance(elementType, items.Count);
                for (int i = 0; i < items.Count; i++) array.SetValue(items[i], i);
                return array;
            }
            var list = (IList)Activator.CreateInstance(type);
            foreach (var item in items) list.Add(item);
            return list;
        }

        object UnityStruct(YamlNode node, Type type, string path)
        {
            var map = node as YamlMapping ?? throw Bad(node, path, type, "expected the fields of a " + type.Name);
            var names = UnityStructs.FloatComponents(type);
            if (names != null)
            {
                var values = new float[names.Length];
                for (int i = 0; i < names.Length; i++) values[i] = Component(map, names[i], path, type);
                ExpectOnly(map, path, type, names);
                return UnityStructs.FromFloats(type, values);
            }
            if (type == typeof(LayerMask))
            {
                ExpectOnly(map, path, type, "serializedVersion", "m_Bits");
                var bits = map.Find("m_Bits") ?? throw Bad(map, path, type, "missing m_Bits");
                return UnityStructs.Mask((uint)Integer(bits, path + ".m_Bits", typeof(uint)));
            }
            if (type == typeof(Bounds))
            {
                ExpectOnly(map, path, type, "m_Center", "m_Extent");
                var center = (Vector3)UnityStruct(map.Find("m_Center") ?? throw Bad(map, path, type, "missing m_Center"), typeof(Vector3), path + ".m_Center");
                var extent = (Vector3)UnityStruct(map.Find("m_Extent") ?? throw Bad(map, path, type, "missing m_Extent"), typeof(Vector3), path + ".m_Extent");
                return UnityStructs.BoundsOf(center, extent);
            }
            throw Bad(node, path, type, "no YAML layout for this Unity type");
        }

        float Component(YamlMapping map, string name, string path, Type type)
        {
            var node = map.Find(name) ?? throw Bad(map, path, type, "missing component '" + name + "'");
            string text = Scalar(node, path + "." + name, typeof(float));
            if (!double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double value)) throw Bad(node, path + "." + name, typeof(float), "not a number");
            return (float)value;
        }

        void ExpectOnly(YamlMapping map, string path, Type type, params string[] keys)
        {
            foreach (var entry in map.Entries)
                if (Array.IndexOf(keys, entry.Key) < 0)
                    throw YamlError.At(m_File, entry.Line, "field '" + entry.Key + "' of " + path + " does not map: a " + type.Name + " has only " + string.Join(", ", keys));
        }

        object Integer(YamlNode node, string path, Type type)
        {
            string text = Scalar(node, path, type);
            bool unsigned = type == typeof(byte) || type == typeof(ushort) || type == typeof(uint) || type == typeof(ulong);
            try
            {
                if (unsigned)
                {
                    ulong u = ulong.Parse(text, NumberStyles.Integer, CultureInfo.InvariantCulture);
                    return Convert.ChangeType(u, type, CultureInfo.InvariantCulture);
                }
                long l = long.Parse(text, NumberStyles.Integer, CultureInfo.InvariantCulture);
                return Convert.ChangeType(l, type, CultureInfo.InvariantCulture);
            }
            catch (Exception e) when (e is FormatException || e is OverflowException)
            {
                throw Bad(node, path, type, "not an integer in range");
            }
        }

        string Scalar(YamlNode node, string path, Type type) =>
            node is YamlScalar scalar ? scalar.Value : throw Bad(node, path, type, "expected a single value");

        FormatException Bad(YamlNode node, string path, Type type, string why) =>
            YamlError.At(m_File, node.Line, "value of " + path + " (" + type.Name + ") does not map: " + why);
    }
}
