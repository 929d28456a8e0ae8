using System;
using System.Collections;
using System.Collections.Generic;
using Object = UnityEngine.Object;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: reads and writes a value along a <see cref="SerializedPath"/> in a snapshot or in the real
    /// object. Writes go back up the path, so structs (Vector3 components, [Serializable] structs) and resized
    /// arrays are stored into their parents. Missing intermediate objects of the real object (a null class, array
    /// or list) are created on write, as Unity's serializer never leaves them null.
    /// </summary>
    internal static class SerializedValues
    {
        /// <summary>True when every step of <paramref name="steps"/> exists in <paramref name="root"/> (array indices in range).</summary>
        internal static bool Exists(object root, IReadOnlyList<SerializedStep> steps)
        {
            object current = root;
            for (int i = 0; i < steps.Count; i++)
            {
                var step = steps[i];
                if (step.Kind == SerializedStep.StepKind.Element && (current == null || step.Index >= Count(current))) return false;
                if (i + 1 < steps.Count) current = Get(current, step);
            }
            return true;
        }

        /// <summary>The value at the end of <paramref name="steps"/>.</summary>
        internal static object Get(object root, IReadOnlyList<SerializedStep> steps)
        {
            object current = root;
            for (int i = 0; i < steps.Count; i++) current = Get(current, steps[i]);
            return current;
        }

        /// <summary>Writes <paramref name="value"/> at the end of <paramref name="steps"/> into <paramref name="root"/>.</summary>
        internal static void Set(object root, IReadOnlyList<SerializedStep> steps, object value) => SetFrom(root, steps, 0, value);

        static object SetFrom(object container, IReadOnlyList<SerializedStep> steps, int i, object value)
        {
            var step = steps[i];
            if (i + 1 == steps.Count) return SetStep(container, step, value);
            object child = Get(container, step) ?? CreateMissing(container, step);
            return SetStep(container, step, SetFrom(child, steps, i + 1, value));
        }

        static object Get(object container, SerializedStep step)
        {
            switch (step.Kind)
            {
                case SerializedStep.StepKind.Member:
                    return container is SerializedSnapshot snapshot ? snapshot.Values[snapshot.IndexOf(step.Member)] : step.Member.Field.GetValue(container);
                case SerializedStep.StepKind.Element:
                    return container is Array array ? array.GetValue(step.Index) : ((IList)container)[step.Index];
                case SerializedStep.StepKind.Size:
                    return container == null ? 0 : Count(container);
                default:
                    return UnityStructs.Get(container, step.Index);
            }
        }

        static object SetStep(object container, SerializedStep step, object value)
        {
            switch (step.Kind)
            {
                case SerializedStep.StepKind.Member:
                    if (container is SerializedSnapshot snapshot) snapshot.Values[snapshot.IndexOf(step.Member)] = value;
                    else step.Member.Field.SetValue(container, value);
                    return container;
                case SerializedStep.StepKind.Element:
                    if (container is Array array) array.SetValue(value, step.Index);
                    else ((IList)container)[step.Index] = value;
                    return container;
                case SerializedStep.StepKind.Size:
                    return Resize(container, (int)value);
                default:
                    return UnityStructs.With(container, step.Index, (float)value);
            }
        }

        static object CreateMissing(object container, SerializedStep step)
        {
            if (step.Kind != SerializedStep.StepKind.Member) throw new InvalidOperationException("no value at a property path step");
            var type = step.Member.Type;
            return type.IsArray ? Array.CreateInstance(type.GetElementType(), 0) : SerializedInstances.Create(type);
        }

        static int Count(object collection) => collection is Array array ? array.Length : ((IList)collection).Count;

        /// <summary>
        /// A collection of <paramref name="size"/> elements: truncated, or grown with copies of the last element
        /// (default values when it was empty). Arrays are replaced, lists resized in place.
        /// </summary>
        static object Resize(object collection, int size)
        {
            if (size < 0) throw new ArgumentOutOfRangeException(nameof(size), size, "array size must be in [0, +inf)");
            if (collection is Array array)
            {
                var elementType = array.GetType().GetElementType();
                var resized = Array.CreateInstance(elementType, size);
                for (int i = 0; i < size; i++)
                    resized.SetValue(i < array.Length ? array.GetValue(i) : NewElement(array.Length > 0 ? array.GetValue(array.Length - 1) : null, array.Length > 0, elementType), i);
                return resized;
            }
            var list = (IList)collection;
            var listElement = list.GetType().GetGenericArguments()[0];
            while (list.Count > size) list.RemoveAt(list.Count - 1);
            while (list.Count < size) list.Add(NewElement(list.Count > 0 ? list[list.Count - 1] : null, list.Count > 0, listElement));
            return list;
        }

        static object NewElement(object last, bool hasLast, Type elementType)
        {
            if (hasLast) return SerializedCopy.CopyValue(last, elementType);
            if (elementType == typeof(string)) return "";
            var kind = SerializedTypes.KindOf(elementType);
            if (kind == SerializedKind.Composite) return SerializedInstances.Create(elementType);
            return elementType.IsValueType ? Activator.CreateInstance(elementType) : null;
        }

        /// <summary>Deep equality of two serialized values of <paramref name="type"/> (references by identity).</summary>
        internal static bool DeepEquals(object a, object b, Type type)
        {
            if (a is null || b is null) return a is null && b is null || IsEmpty(a ?? b);
            switch (SerializedTypes.KindOf(type))
            {
                case SerializedKind.ObjectReference:
                    return ReferenceEquals(a, b) || (a is Object x && b is Object y && x == null && y == null);
                case SerializedKind.Array:
                case SerializedKind.List:
                {
                    var elementType = SerializedTypes.ElementType(type);
                    var left = (IList)a;
                    var right = (IList)b;
                    if (left.Count != right.Count) return false;
                    for (int i = 0; i < left.Count; i++)
                        if (!DeepEquals(left[i], right[i], elementType)) return false;
                    return true;
                }
                case SerializedKind.Composite:
                    foreach (var member in SerializedLayout.Of(type).Members)
                        if (!DeepEquals(member.Field.GetValue(a), member.Field.GetValue(b), member.Type)) return false;
                    return true;
                default:
                    return a.Equals(b);
            }
        }

        static bool IsEmpty(object o) => o is IList list && list.Count == 0 || o is string s && s.Length == 0;
    }
}
