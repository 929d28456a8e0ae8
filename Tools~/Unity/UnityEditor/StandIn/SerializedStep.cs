using System;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: one step of a property path — a field, an array element, the array size, or a float component of a Unity struct.</summary>
    internal sealed class SerializedStep
    {
        internal enum StepKind { Member, Element, Size, Component }

        SerializedStep(StepKind kind, SerializedMember member, int index)
        {
            Kind = kind;
            Member = member;
            Index = index;
        }

        internal StepKind Kind { get; }

        /// <summary>The field (Member steps).</summary>
        internal SerializedMember Member { get; }

        /// <summary>The element index (Element) or component index (Component).</summary>
        internal int Index { get; }

        internal static SerializedStep Field(SerializedMember member) => new SerializedStep(StepKind.Member, member, -1);
        internal static SerializedStep Element(int index) => new SerializedStep(StepKind.Element, null, index);
        internal static readonly SerializedStep Size = new SerializedStep(StepKind.Size, null, -1);
        internal static SerializedStep Component(int index) => new SerializedStep(StepKind.Component, null, index);
    }

    /// <summary>Not part of Unity: what a property path ends at.</summary>
    internal enum SerializedRole
    {
        /// <summary>A value (field, element or component).</summary>
        Value,
        /// <summary>The "Array" child of an array or list (the array itself, named "Array").</summary>
        ArrayWrapper,
        /// <summary>"Array.size".</summary>
        ArraySize,
    }

    /// <summary>Not part of Unity: the type information of the value a path ends at.</summary>
    internal readonly struct SerializedSlotType
    {
        internal SerializedSlotType(Type type)
        {
            Type = type;
            Kind = SerializedTypes.KindOf(type);
            ElementType = SerializedTypes.ElementType(type);
        }

        internal Type Type { get; }
        internal SerializedKind Kind { get; }
        internal Type ElementType { get; }
    }
}
