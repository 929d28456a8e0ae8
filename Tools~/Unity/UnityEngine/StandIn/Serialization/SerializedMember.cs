using System;
using System.Reflection;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: one field Unity serializes, with how its value (and, for collections, each element) is stored.</summary>
    internal sealed class SerializedMember
    {
        internal SerializedMember(FieldInfo field)
        {
            Field = field;
            Kind = SerializedTypes.KindOf(field.FieldType);
            ElementType = SerializedTypes.ElementType(field.FieldType);
            ElementKind = ElementType != null ? SerializedTypes.KindOf(ElementType) : SerializedKind.None;
        }

        /// <summary>The C# field.</summary>
        internal FieldInfo Field { get; }

        /// <summary>The serialized name: the field's name, as Unity writes it in YAML and property paths.</summary>
        internal string Name => Field.Name;

        /// <summary>The field's declared type.</summary>
        internal Type Type => Field.FieldType;

        /// <summary>How the value is stored.</summary>
        internal SerializedKind Kind { get; }

        /// <summary>Element type of an array or list field, else null.</summary>
        internal Type ElementType { get; }

        /// <summary>How each element is stored (arrays and lists), else None.</summary>
        internal SerializedKind ElementKind { get; }

        /// <inheritdoc/>
        public override string ToString() => Field.DeclaringType?.Name + "." + Name + " (" + Kind + ")";
    }
}
