using System;
using HookeRope.Fracture;

namespace HookeRope.Lab.Figures
{
    /// <summary>
    /// An RGBA32 colour map for textured figure triangles, sampled like the package's runtime texture: bilinear,
    /// repeat wrap, row 0 = v = 0 (the order of <see cref="BurrTextureGenerator"/> and Unity's LoadRawTextureData).
    /// Alpha is ignored, as by the package's opaque burr material.
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

        /// <summary>Width in pixels.</summary>
        public int Width { get; }
        /// <summary>Height in pixels.</summary>
        public int Height { get; }
        /// <summary>The texels, RGBA32, row 0 first (v = 0).</summary>
        public ReadOnlySpan<byte> Rgba => rgba;

        /// <summary>A texture over <paramref name="rgba"/> (width·height·4 bytes).</summary>
        public FigureTexture(int width, int height, byte[] rgba)
        {
            if (width < 1 || height < 1) throw new ArgumentOutOfRangeException(nameof(width), "a texture needs at least one texel");
            if (rgba == null || rgba.Length < width * height * 4) throw new ArgumentException("rgba must hold width·height·4 bytes", nameof(rgba));
            Width = width;
            Height = height;
            this.rgba = rgba;
        }

        /// <summary>The package's burr texture (256 × 64, 16 triangles, seed 1, polyamide beige) from the core's generator.</summary>
        public static FigureTexture PackageBurr()
        {
            var pixels = new byte[BurrTextureGenerator.ByteCount(BurrWidth, BurrHeight)];
            BurrTextureGenerator.Generate(BurrWidth, BurrHeight, BurrTriangles, 1u, 214, 200, 160, pixels);
            return new FigureTexture(BurrWidth, BurrHeight, pixels);
        }

        /// <summary>Bilinear sample at (u, v) with repeat wrap: red, green, blue in [0, 1].</summary>
        public (float R, float G, float B) Sample(float u, float v)
        {
            float x = u * Width - 0.5f, y = v * Height - 0.5f;
            int x0 = (int)MathF.Floor(x), y0 = (int)MathF.Floor(y);
            float fx = x - x0, fy = y - y0;
            float r = 0f, g = 0f, b = 0f;
            for (int j = 0; j < 2; j++)
            {
                for (int i = 0; i < 2; i++)
                {
                    float w = (i == 0 ? 1f - fx : fx) * (j == 0 ? 1f - fy : fy);
                    int o = (Wrap(y0 + j, Height) * Width + Wrap(x0 + i, Width)) * 4;
                    r += w * rgba[o];
                    g += w * rgba[o + 1];
                    b += w * rgba[o + 2];
                }
            }
            return (r / 255f, g / 255f, b / 255f);
        }

        static int Wrap(int i, int n) => ((i % n) + n) % n;
    }
}
