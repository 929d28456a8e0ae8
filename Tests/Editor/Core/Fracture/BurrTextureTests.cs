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
    }
}
