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
        /// <summary>The burr strands of a broken end (the core's second submesh).</summary>
        Burr = 3,
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
        /// <summary>Colour map multiplied into <see cref="Color"/> (the burr texture), or null for a plain face.</summary>
        public readonly FigureTexture Texture;
        /// <summary>Texture coordinates (u, v) of A, B and C (unitless; used only with a <see cref="Texture"/>).</summary>
        public readonly float UA, VA, UB, VB, UC, VC;

        /// <summary>A triangle; <paramref name="normal"/> is normalised here.</summary>
        public SceneTriangle(Float3 a, Float3 b, Float3 c, Float3 normal, uint color, SurfaceKind kind)
        {
            A = a;
            B = b;
            C = c;
            Normal = normal.NormalizedOr(Float3.Cross(b - a, c - a).NormalizedOr(new Float3(0f, 1f, 0f)));
            Color = color;
            Kind = kind;
            Texture = null;
            UA = VA = UB = VB = UC = VC = 0f;
        }

        /// <summary>A textured triangle: <paramref name="texture"/> sampled at the interpolated (u, v) of the corners tints <paramref name="color"/>.</summary>
        public SceneTriangle(Float3 a, Float3 b, Float3 c, Float3 normal, uint color, SurfaceKind kind,
            FigureTexture texture, float ua, float va, float ub, float vb, float uc, float vc)
            : this(a, b, c, normal, color, kind)
        {
            Texture = texture;
            UA = ua; VA = va; UB = ub; VB = vb; UC = uc; VC = vc;
        }
    }
}
