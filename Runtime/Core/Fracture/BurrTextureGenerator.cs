using System;

namespace HookeRope.Fracture
{
    /// <summary>
    /// Procedural burr texture: a row of inverted triangles (base along the top edge v = 1, apex pointing down
    /// toward v = 0, where the burr strands have their tips), one per strand, with seeded heights, apex offsets
    /// and fibre streaks; outside the triangles the alpha is 0 (only an alpha-clipped material reads it; the generated
    /// burr material is opaque and uses the colour as fibre streaks). Output is RGBA32, row 0
    /// first = v = 0 = the bottom row (the order of Unity's Texture2D.LoadRawTextureData).
    /// </summary>
    public static class BurrTextureGenerator
    {
        /// <summary>Largest width or height in pixels.</summary>
        public const int MaxSize = 4096;

        /// <summary>Bytes needed for a texture of the given size (4 per pixel).</summary>
        public static int ByteCount(int width, int height)
        {
            CheckSize(width, height);
            return width * height * 4;
        }

        /// <summary>
        /// Writes a <paramref name="width"/>×<paramref name="height"/> RGBA32 burr texture (each 1 … 4096 px) with
        /// <paramref name="triangleCount"/> triangles (1 … width) into <paramref name="rgba"/> (at least
        /// <see cref="ByteCount"/> bytes), fibre colour (<paramref name="red"/>, <paramref name="green"/>,
        /// <paramref name="blue"/>). Deterministic for a seed; allocation-free.
        /// </summary>
        public static void Generate(int width, int height, int triangleCount, uint seed, byte red, byte green, byte blue, Span<byte> rgba)
        {
            CheckSize(width, height);
            if (triangleCount < 1 || triangleCount > width)
                throw new ArgumentOutOfRangeException(nameof(triangleCount), triangleCount, "triangleCount must be in [1, width].");
            if (rgba.Length < width * height * 4)
                throw new ArgumentException("rgba must hold at least width·height·4 = " + (width * height * 4) + " bytes.", nameof(rgba));
            float cell = (float)width / triangleCount;
            for (int y = 0; y < height; y++)
            {
                float v = (y + 0.5f) / height;
                for (int x = 0; x < width; x++)
                {
                    float px = x + 0.5f;
                    int c = (int)(px / cell);
                    if (c >= triangleCount) c = triangleCount - 1;
                    float apexHeight = 0.55f + 0.45f * SeededRandom.Unit(seed, c, 0);
                    float apexX = (c + 0.5f + 0.3f * (SeededRandom.Unit(seed, c, 1) - 0.5f)) * cell;
                    float left = c * cell;
                    float right = (c + 1) * cell;
                    float along = (1f - v) / apexHeight;
                    float coverage = 0f;
                    if (along < 1f)
                    {
                        float halfLeft = (apexX - left) * (1f - along);
                        float halfRight = (right - apexX) * (1f - along);
                        float d = px < apexX ? (px - (apexX - halfLeft)) : ((apexX + halfRight) - px);
                        coverage = d >= 1f ? 1f : (d > 0f ? d : 0f);
                    }
                    float streak = 0.7f + 0.3f * SeededRandom.Unit(seed, x, 2);
                    float shade = streak * (1f - 0.35f * along);
                    if (shade < 0f) shade = 0f;
                    int o = (y * width + x) * 4;
                    rgba[o] = (byte)(red * shade + 0.5f);
                    rgba[o + 1] = (byte)(green * shade + 0.5f);
                    rgba[o + 2] = (byte)(blue * shade + 0.5f);
                    rgba[o + 3] = (byte)(255f * coverage + 0.5f);
                }
            }
        }

        /// <summary>Mip levels of a full chain down to 1×1 (as Unity's Texture2D with mipChain: 1 + ⌊log2 max(w, h)⌋).</summary>
        public static int MipCount(int width, int height)
        {
            CheckSize(width, height);
            int levels = 1;
            for (int size = Math.Max(width, height); size > 1; size >>= 1) levels++;
            return levels;
        }

        /// <summary>Width in pixels of mip level <paramref name="level"/>: max(1, width ≫ level).</summary>
        public static int MipWidth(int width, int level) => Math.Max(1, width >> level);

        /// <summary>Height in pixels of mip level <paramref name="level"/>: max(1, height ≫ level).</summary>
        public static int MipHeight(int height, int level) => Math.Max(1, height >> level);

        /// <summary>Byte offset of mip level <paramref name="level"/> in a chain of <see cref="MipChainByteCount"/> bytes (levels one after the other, level 0 first).</summary>
        public static int MipOffset(int width, int height, int level)
        {
            int levels = MipCount(width, height);
            if (level < 0 || level > levels)
                throw new ArgumentOutOfRangeException(nameof(level), level, "level must be in [0, " + levels + "].");
            int offset = 0;
            for (int m = 0; m < level; m++) offset += MipWidth(width, m) * MipHeight(height, m) * 4;
            return offset;
        }

        /// <summary>Bytes of the whole mip chain of a width × height RGBA32 texture (every level, 4 bytes per pixel).</summary>
        public static int MipChainByteCount(int width, int height) => MipOffset(width, height, MipCount(width, height));

        /// <summary>
        /// <see cref="Generate"/> level 0 into the start of <paramref name="chain"/> (at least <see cref="MipChainByteCount"/>
        /// bytes) and every smaller level after it, each the 2 × 2 box average of the level above (rounded to nearest; a
        /// side already 1 px wide averages the two along the other side), for Texture2D.SetPixelData(chain, level,
        /// MipOffset(level)). Minified on a fibre (the whole texture over a few pixels at 1 m in a headset) the sampler then
        /// reads an average instead of skipping over the triangles: the strands do not shimmer. Allocation-free.
        /// </summary>
        public static void GenerateMipChain(int width, int height, int triangleCount, uint seed, byte red, byte green, byte blue, Span<byte> chain)
        {
            int total = MipChainByteCount(width, height);
            if (chain.Length < total)
                throw new ArgumentException("chain must hold at least MipChainByteCount = " + total + " bytes.", nameof(chain));
            Generate(width, height, triangleCount, seed, red, green, blue, chain);
            int levels = MipCount(width, height);
            int source = 0;
            for (int level = 1; level < levels; level++)
            {
                int pw = MipWidth(width, level - 1), ph = MipHeight(height, level - 1);
                int w = MipWidth(width, level), h = MipHeight(height, level);
                int target = source + pw * ph * 4;
                for (int y = 0; y < h; y++)
                {
                    int y0 = Math.Min(2 * y, ph - 1), y1 = Math.Min(2 * y + 1, ph - 1);
                    for (int x = 0; x < w; x++)
                    {
                        int x0 = Math.Min(2 * x, pw - 1), x1 = Math.Min(2 * x + 1, pw - 1);
                        int a = source + (y0 * pw + x0) * 4, b = source + (y0 * pw + x1) * 4;
                        int c = source + (y1 * pw + x0) * 4, d = source + (y1 * pw + x1) * 4;
                        int o = target + (y * w + x) * 4;
                        for (int channel = 0; channel < 4; channel++)
                            chain[o + channel] = (byte)((chain[a + channel] + chain[b + channel] + chain[c + channel] + chain[d + channel] + 2) >> 2);
                    }
                }
                source = target;
            }
        }

        private static void CheckSize(int width, int height)
        {
            Require.InRange(width, 1, MaxSize, nameof(width), "px");
            Require.InRange(height, 1, MaxSize, nameof(height), "px");
        }
    }
}
