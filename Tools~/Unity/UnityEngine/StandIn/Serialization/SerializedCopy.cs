using System;
using System.Collections;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: copies the serialized state of one object onto another of the same type the way
    /// Object.Instantiate does (serialize, then deserialize into the clone): serialized fields only, by value —
    /// [Serializable] classes and structs, arrays and lists are deep-copied (a null class, array or list comes out as a
    /// new empty one, as Unity never stores null for them), UnityEngine.Object references go through
    /// <c>remap</c> (references into the cloned hierarchy become references to the clones). Fields Unity does not
    /// serialize keep whatever the target's constructor gave them.
    /// </summary>
    internal static class SerializedCopy
    {
        /// <summary>Copies the serialized fields of <paramref name="source"/> onto <paramref name="target"/> (same runtime type).</summary>
        internal static void CopyFields(object source, object target, Func<Object, Object> remap)
        {
            if (source.GetType() != target.GetType())
                throw new ArgumentException("cannot copy a " + source.GetType().Name + " onto a " + target.GetType().Name);
            CopyMembers(source.GetType(), source, target, remap, 0);
        }

        /// <summary>A deep copy of a serialized value of <paramref name="type"/> (references kept as they are).</summary>
        internal static object CopyValue(object value, Type type)
        {
            var kind = SerializedTypes.KindOf(type);
            var elementType = SerializedTypes.ElementType(type);
            var elementKind = elementType != null ? SerializedTypes.KindOf(elementType) : SerializedKind.None;
            return Copy(value, null, type, kind, elementType, elementKind, o => o, 0);
        }

        static void CopyMembers(Type layoutType, object source, object target, Func<Object, Object> remap, int depth)
        {
            foreach (var member in SerializedLayout.Of(layoutType).Members)
            {
                object value = member.Field.GetValue(source);
                object existing = member.Field.GetValue(target);
                member.Field.SetValue(target, Copy(value, existing, member.Type, member.Kind, member.ElementType, member.ElementKind, remap, depth));
            }
        }

        static object Copy(object value, object existing, Type type, SerializedKind kind, Type elementType, SerializedKind elementKind,
            Func<Object, Object> remap, int depth)
        {
            switch (kind)
            {
                case SerializedKind.ObjectReference:
                    return value is Object reference ? remap(reference) : null;
                case SerializedKind.Composite:
                    return CopyComposite(value, existing, type, remap, depth);
                case SerializedKind.Array:
                {
                    var source = value as Array;
                    int length = source?.Length ?? 0;
                    var copy = Array.CreateInstance(elementType, length);
                    for (int i = 0; i < length; i++)
                        copy.SetValue(Copy(source.GetValue(i), null, elementType, elementKind, null, SerializedKind.None, remap, depth), i);
                    return copy;
                }
                case SerializedKind.List:
                {
                    var copy = (IList)Activator.CreateInstance(type);
                    if (value is IList source)
                        for (int i = 0; i < source.Count; i++)
                            copy.Add(Copy(source[i], null, elementType, elementKind, null, SerializedKind.None, remap, depth));
                    return copy;
                }
                default:
                    return value; // primitives, strings (immutable), enums and Unity structs (copied by value)
            }
        }

        static object CopyComposite(object value, object existing, Type type, Func<Object, Object> remap, int depth)
        {
            if (depth >= SerializedLayout.MaxDepth) return type.IsValueType ? Activator.CreateInstance(type) : null;
            object target = existing != null && existing.GetType() == type && !ReferenceEquals(existing, value)
                ? existing
                : SerializedInstances.Create(type);
            if (value != null) CopyMembers(type, value, target, remap, depth + 1);
            return target;
        }
    }
}
