using HookeRope.Mathematics;

namespace HookeRope.Lab.Figures
{
    /// <summary>What a triangle of a figure belongs to (the rasterizer's id buffer records it per pixel).</summary>
    public enum SurfaceKind : byte
    {
        /// <summary>No surface (background).</summary>
        None = 0,
        /// <summary>The rope's tube mesh from the core.</summary>
        Rope = 1,
        /// <summary>Any other object (beam, floor, worker, D-ring, anchor).</summary>
        Prop = 2,
    }

    /// <summary>One flat-shaded triangle of a figure: corners and outward normal in world metres, base colour, kind.</summary>
    public readonly struct SceneTriangle
    {
        /// <summary>First corner (m).</summary>
        public readonly Float3 A;
        /// <summary>Second corner (m).</summary>
        public readonly Float3 B;
        /// <summary>Third corner (m).</summary>
        public readonly Float3 C;
        /// <summary>Outward unit normal (decides facing and shading).</summary>
        public readonly Float3 Normal;
        /// <summary>Base colour as 0xRRGGBB.</summary>
        public readonly uint Color;
        /// <summary>What the triangle belongs to.</summary>
        public readonly SurfaceKind Kind;

        /// <summary>A triangle; <paramref name="normal"/> is normalised here.</summary>
        public SceneTriangle(Float3 a, Float3 b, Float3 c, Float3 normal, uint color, SurfaceKind kind)
        {
            A = a;
            B = b;
            C = c;
            Normal = normal.NormalizedOr(Float3.Cross(b - a, c - a).NormalizedOr(new Float3(0f, 1f, 0f)));
            Color = color;
            Kind = kind;
        }
    }
}
