using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>Not part of Unity: one line of a shader's ShaderLab Properties block (name, type, default, [MainTexture]/[MainColor]).</summary>
    internal sealed class ShaderPropertyInfo
    {
        ShaderPropertyInfo(string name, ShaderPropertyKind kind, float defaultFloat, Color defaultColor)
        {
            Name = name;
            Kind = kind;
            DefaultFloat = defaultFloat;
            DefaultColor = defaultColor;
        }

        /// <summary>Property name, e.g. "_BaseColor".</summary>
        internal string Name { get; }

        /// <summary>ShaderLab type.</summary>
        internal ShaderPropertyKind Kind { get; }

        /// <summary>Default of a Float / Range / Int property.</summary>
        internal float DefaultFloat { get; }

        /// <summary>Default of a Color / Vector property.</summary>
        internal Color DefaultColor { get; }

        /// <summary>Tagged [MainTexture]: Material.mainTexture maps to it.</summary>
        internal bool IsMainTexture { get; private set; }

        /// <summary>Tagged [MainColor]: Material.color maps to it.</summary>
        internal bool IsMainColor { get; private set; }

        /// <summary>True for Float, Range and Int properties.</summary>
        internal bool IsFloat => Kind == ShaderPropertyKind.Float || Kind == ShaderPropertyKind.Range || Kind == ShaderPropertyKind.Int;

        /// <summary>True for Color and Vector properties.</summary>
        internal bool IsColor => Kind == ShaderPropertyKind.Color || Kind == ShaderPropertyKind.Vector;

        /// <summary>A Float property.</summary>
        internal static ShaderPropertyInfo Float(string name, float value) => new ShaderPropertyInfo(name, ShaderPropertyKind.Float, value, default);

        /// <summary>A Range property.</summary>
        internal static ShaderPropertyInfo Range(string name, float value) => new ShaderPropertyInfo(name, ShaderPropertyKind.Range, value, default);

        /// <summary>An Int property.</summary>
        internal static ShaderPropertyInfo Int(string name, int value) => new ShaderPropertyInfo(name, ShaderPropertyKind.Int, value, default);

        /// <summary>A Color property; ShaderLab fills a missing alpha with 1.</summary>
        internal static ShaderPropertyInfo Color(string name, float r, float g, float b, float a = 1f) =>
            new ShaderPropertyInfo(name, ShaderPropertyKind.Color, 0f, new Color(r, g, b, a));

        /// <summary>A Vector property.</summary>
        internal static ShaderPropertyInfo Vector(string name, float x, float y, float z, float w) =>
            new ShaderPropertyInfo(name, ShaderPropertyKind.Vector, 0f, new Color(x, y, z, w));

        /// <summary>A texture property (its default texture reads back as null, as an unassigned slot does in Unity).</summary>
        internal static ShaderPropertyInfo Texture(string name) => new ShaderPropertyInfo(name, ShaderPropertyKind.Texture, 0f, default);

        /// <summary>Tags the property [MainTexture].</summary>
        internal ShaderPropertyInfo MainTexture()
        {
            IsMainTexture = true;
            return this;
        }

        /// <summary>Tags the property [MainColor].</summary>
        internal ShaderPropertyInfo MainColor()
        {
            IsMainColor = true;
            return this;
        }
    }
}
