using System;
using HookeRope.Fracture;

namespace HookeRope.Lab.Figures
{
    /// <summary>
    /// An RGBA32 colour map for textured figure triangles, sampled like the package's runtime texture: bilinear within a
    /// level, trilinear between the mip levels the core generates (<see cref="BurrTextureGenerator.GenerateMipChain"/>,
    /// what RopeDefaultMaterial.CreateBurrTexture uploads), repeat wrap, row 0 = v = 0 (the order of
    /// <see cref="BurrTextureGenerator"/> and Unity's LoadRawTextureData). Alpha is ignored, as by the package's opaque
    /// burr material.
    /// </summary>
    public sealed class FigureTexture
    {
        /// <summary>Package burr texture width (px), as RopeDefaultMaterial.CreateBurrTexture makes it.</summary>
        public const int BurrWidth = 256;
        /// <summary>Package burr texture height (px).</summary>
        public const int BurrHeight = 64;
        /// <summary>Triangles in the package burr texture.</summary>
        public const int BurrTriangles = 16;

        readonly byte[] rgba;
        readonly int[] offsets;

        /// <summary>Width in pixels (level 0).</summary>
        public int Width { get; }
        /// <summary>Height in pixels (level 0).</summary>
        public int Height { get; }
        /// <summary>Mip levels held (1 = level 0 only: no mipmaps).</summary>
        public int Levels => offsets.Length;
        /// <summary>The texels of level 0, RGBA32, row 0 first (v = 0).</summary>
        public ReadOnlySpan<byte> Rgba => rgba.AsSpan(0, Width * Height * 4);

        /// <summary>A texture over <paramref name="rgba"/> (width·height·4 bytes of level 0, then <paramref name="levels"/> − 1 smaller levels as the core lays them out).</summary>
        public FigureTexture(int width, int height, byte[] rgba, int levels = 1)
        {
            if (width < 1 || height < 1) throw new ArgumentOutOfRangeException(nameof(width), "a texture needs at least one texel");
            if (levels < 1 || levels > BurrTextureGenerator.MipCount(width, height))
                throw new ArgumentOutOfRangeException(nameof(levels), levels, "levels must be in [1, the full chain]");
            int needed = BurrTextureGenerator.MipOffset(width, height, levels);
            if (rgba == null || rgba.Length < needed) throw new ArgumentException("rgba must hold the " + levels + " levels (" + needed + " bytes)", nameof(rgba));
            Width = width;
            Height = height;
            this.rgba = rgba;
            offsets = new int[levels];
            for (int m = 0; m < levels; m++) offsets[m] = BurrTextureGenerator.MipOffset(width, height, m);
        }

        /// <summary>
        /// The package's burr texture (256 × 64, 16 triangles, seed 1, polyamide beige) from the core's generator: with its
        /// mip chain (9 levels, as the runtime uploads it), or level 0 alone (<paramref name="mipmaps"/> false: the runtime
        /// texture before issue 17).
        /// </summary>
        public static FigureTexture PackageBurr(bool mipmaps = true)
        {
            var chain = new byte[BurrTextureGenerator.MipChainByteCount(BurrWidth, BurrHeight)];
            BurrTextureGenerator.GenerateMipChain(BurrWidth, BurrHeight, BurrTriangles, 1u, 214, 200, 160, chain);
            return new FigureTexture(BurrWidth, BurrHeight, chain, mipmaps ? BurrTextureGenerator.MipCount(BurrWidth, BurrHeight) : 1);
        }

        /// <summary>Bilinear sample of level 0 at (u, v) with repeat wrap: red, green, blue in [0, 1].</summary>
        public (float R, float G, float B) Sample(float u, float v) => SampleLevel(0, u, v);

        /// <summary>
        /// Trilinear sample at (u, v) for the level of detail <paramref name="lod"/> = log2(texels per pixel) (≤ 0: level 0;
        /// past the last level: the last), as a GPU does with mipmaps; without mipmaps always level 0.
        /// </summary>
        public (float R, float G, float B) Sample(float u, float v, float lod)
        {
            if (!(lod > 0f) || Levels == 1) return SampleLevel(0, u, v);
            int last = Levels - 1;
            if (lod >= last) return SampleLevel(last, u, v);
            int m = (int)lod;
            float f = lod - m;
            var (r0, g0, b0) = SampleLevel(m, u, v);
            var (r1, g1, b1) = SampleLevel(m + 1, u, v);
            return (r0 + (r1 - r0) * f, g0 + (g1 - g0) * f, b0 + (b1 - b0) * f);
        }

        /// <summary>Texels of level 0 covered by a triangle of uv area <paramref name="uvArea"/> (unitless, uv units²).</summary>
        public float TexelArea(float uvArea) => uvArea * Width * Height;

        (float R, float G, float B) SampleLevel(int level, float u, float v)
        {
            int w = BurrTextureGenerator.MipWidth(Width, level), h = BurrTextureGenerator.MipHeight(Height, level), o0 = offsets[level];
            float x = u * w - 0.5f, y = v * h - 0.5f;
            int x0 = (int)MathF.Floor(x), y0 = (int)MathF.Floor(y);
            float fx = x - x0, fy = y - y0;
            float r = 0f, g = 0f, b = 0f;
            for (int j = 0; j < 2; j++)
            {
                for (int i = 0; i < 2; i++)
                {
                    float weight = (i == 0 ? 1f - fx : fx) * (j == 0 ? 1f - fy : fy);
                    int o = o0 + (Wrap(y0 + j, h) * w + Wrap(x0 + i, w)) * 4;
                    r += weight * rgba[o];
                    g += weight * rgba[o + 1];
                    b += weight * rgba[o + 2];
                }
            }
            return (r / 255f, g / 255f, b / 255f);
        }

        static int Wrap(int i, int n) => ((i % n) + n) % n;
    }
}
