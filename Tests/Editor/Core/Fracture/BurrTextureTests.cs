using System;
using HookeRope.Fracture;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Fracture
{
    public sealed class BurrTextureTests
    {
        private const int W = 128, H = 64, Triangles = 8;

        private static byte[] Make(uint seed)
        {
            var rgba = new byte[BurrTextureGenerator.ByteCount(W, H)];
            BurrTextureGenerator.Generate(W, H, Triangles, seed, 200, 180, 140, rgba);
            return rgba;
        }

        private static int OpaqueInRow(byte[] rgba, int row)
        {
            int count = 0;
            for (int x = 0; x < W; x++) if (rgba[(row * W + x) * 4 + 3] >= 128) count++;
            return count;
        }

        [Test]
        public void TrianglesNarrowFromTheBaseToTheTips()
        {
            byte[] rgba = Make(3u);
            // Inverted triangles: base along the top row (v = 1), apexes pointing down toward v = 0.
            Assert.That(OpaqueInRow(rgba, H - 1), Is.GreaterThanOrEqualTo(W - 2 * Triangles)); // the base row is nearly full
            Assert.That(OpaqueInRow(rgba, 0), Is.EqualTo(0)); // every apex is above v = 0
            for (int y = 1; y < H; y++)
                Assert.That(OpaqueInRow(rgba, y), Is.GreaterThanOrEqualTo(OpaqueInRow(rgba, y - 1)), "row " + y);
            // A third of the way down from the base, the opaque pixels form one run per triangle.
            int row = H - 1 - H / 3, runs = 0;
            for (int x = 0; x < W; x++)
            {
                bool on = rgba[(row * W + x) * 4 + 3] >= 128;
                bool before = x > 0 && rgba[(row * W + x - 1) * 4 + 3] >= 128;
                if (on && !before) runs++;
            }
            Assert.That(runs, Is.EqualTo(Triangles));
        }

        [Test]
        public void SameSeedSameTextureDifferentSeedDifferent()
        {
            Assert.That(Make(11u), Is.EqualTo(Make(11u)));
            Assert.That(Make(11u), Is.Not.EqualTo(Make(12u)));
        }

        [Test]
        public void BadArgumentsThrowNamingTheRange()
        {
            var rgba = new byte[16];
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => BurrTextureGenerator.Generate(0, 2, 1, 0u, 0, 0, 0, rgba)).Message, Does.Contain("[1, 4096]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => BurrTextureGenerator.Generate(2, 2, 3, 0u, 0, 0, 0, rgba)).ParamName, Is.EqualTo("triangleCount"));
            Assert.That(Assert.Throws<ArgumentException>(() => BurrTextureGenerator.Generate(4, 4, 1, 0u, 0, 0, 0, rgba)).ParamName, Is.EqualTo("rgba"));
        }

        [TestCase(256, 64)]
        [TestCase(128, 64)]
        [TestCase(5, 3)]
        public void MipLevelsAreTheBoxAverageOfTheLevelAbove(int width, int height)
        {
            // the package's texture (256 × 64) has 9 levels (256 … 1, as Unity's mipChain); each texel of level m is the
            // rounded mean of its 2 × 2 parents of level m − 1 (a 1 px side averages two)
            int levels = BurrTextureGenerator.MipCount(width, height);
            var chain = new byte[BurrTextureGenerator.MipChainByteCount(width, height)];
            BurrTextureGenerator.GenerateMipChain(width, height, Math.Min(16, width), 1u, 214, 200, 160, chain);
            var level0 = new byte[BurrTextureGenerator.ByteCount(width, height)];
            BurrTextureGenerator.Generate(width, height, Math.Min(16, width), 1u, 214, 200, 160, level0);
            Assert.That(chain.AsSpan(0, level0.Length).SequenceEqual(level0), Is.True, "level 0 is the texture itself");
            int expectedLevels = 1;
            for (int size = Math.Max(width, height); size > 1; size /= 2) expectedLevels++;
            Assert.That(levels, Is.EqualTo(expectedLevels));
            for (int m = 1; m < levels; m++)
            {
                int pw = Math.Max(1, width >> (m - 1)), ph = Math.Max(1, height >> (m - 1));
                int w = Math.Max(1, width >> m), h = Math.Max(1, height >> m);
                int parent = BurrTextureGenerator.MipOffset(width, height, m - 1), own = BurrTextureGenerator.MipOffset(width, height, m);
                Assert.That(own - parent, Is.EqualTo(pw * ph * 4));
                for (int y = 0; y < h; y++)
                for (int x = 0; x < w; x++)
                for (int c = 0; c < 4; c++)
                {
                    int sum = 0;
                    for (int dy = 0; dy < 2; dy++)
                    for (int dx = 0; dx < 2; dx++)
                        sum += chain[parent + (Math.Min(2 * y + dy, ph - 1) * pw + Math.Min(2 * x + dx, pw - 1)) * 4 + c];
                    Assert.That(chain[own + (y * w + x) * 4 + c], Is.EqualTo((sum + 2) / 4), "level " + m + " texel " + x + "," + y + " channel " + c);
                }
            }
            // the last level (1 × 1) is the texture's mean colour within the rounding of the levels (½ per level), where no
            // level drops an odd row or column (powers of two)
            if ((width & (width - 1)) != 0 || (height & (height - 1)) != 0) return;
            int last = BurrTextureGenerator.MipOffset(width, height, levels - 1);
            for (int c = 0; c < 4; c++)
            {
                double mean = 0.0;
                for (int p = 0; p < width * height; p++) mean += level0[p * 4 + c];
                mean /= width * height;
                Assert.That(chain[last + c], Is.EqualTo(mean).Within(0.5 * levels + 1.0), "channel " + c);
            }
        }

        [Test]
        public void MipChainRejectsASmallBuffer()
        {
            var ex = Assert.Throws<ArgumentException>(() => BurrTextureGenerator.GenerateMipChain(256, 64, 16, 1u, 1, 2, 3, new byte[256 * 64 * 4]));
            Assert.That(ex.ParamName, Is.EqualTo("chain"));
            Assert.Throws<ArgumentOutOfRangeException>(() => BurrTextureGenerator.MipOffset(256, 64, 10));
        }
    }
}
