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

        private static void CheckSize(int width, int height)
        {
            Require.InRange(width, 1, MaxSize, nameof(width), "px");
            Require.InRange(height, 1, MaxSize, nameof(height), "px");
        }
    }
}
