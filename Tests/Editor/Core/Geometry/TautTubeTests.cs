using System;
using HookeRope.Geometry;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// Issue 17: the slack-fold repair (fold tips, crossing and cone limits, strip normals, the Hermite tangent clamp) is
    /// idle on a rope that bends no tighter than its radius, so its tube is drawn as before. Measured when it was added:
    /// every float and index of <see cref="TautTubeScenes"/> bit-identical to main df29480's builder (dumped from both).
    /// Here each scene's vertex and index counts must be those of then, its weighted sums of positions, normals, tangents
    /// and uv within 1e-6 of their sum of magnitudes (a margin for a runtime whose float rounding differs), and none of
    /// its rings repaired.
    /// </summary>
    public sealed class TautTubeTests
    {
        /// <summary>Per scene (<see cref="TautTubeScenes.Names"/>): vertices, indices, Σ(x + 2y + 3z) of positions, normals, tangents, Σ(u + 2v), Σ index·(i mod 7).</summary>
        private static readonly double[][] Before =
        {
            new double[] { 765, 4128, 538.3339812448248, 85.99574965843922, 196.99999910593033, 7726.50002771616, 4729228 },
            new double[] { 891, 4656, 627.7968172244728, 193.99595642678358, 326.99999928474426, 9193.500098392367, 6216581 },
            new double[] { 3084, 6492, 2322.2330007931487, 92.51566262257398, 267.99996052560164, 12114.000028073788, 29908230 },
            new double[] { 9471, 54720, 6416.934675912373, 960.1655625700951, -311.6651320731962, 192901.4999921322, 777304147 },
            new double[] { 4325, 13500, 332.9424083996564, 179.6828643099143, 348.6635153743555, 19677.29966124147, 94282280 },
            new double[] { 871, 4680, 395.30188167549204, 210.25954975039167, -21.736055202782154, 7221.500000841916, 6105282 },
        };

        private static readonly int[] Scenes = { 0, 1, 2, 3, 4, 5 };

        /// <summary>The weighted sums of a mesh and, in <paramref name="magnitudes"/>, the sums of the terms' magnitudes.</summary>
        internal static double[] Sums(TubeVertex[] vertices, int[] indices, TubeMeshUpdate update, out double[] magnitudes)
        {
            var sums = new double[7];
            magnitudes = new double[7];
            sums[0] = update.VertexCount;
            sums[1] = update.IndexCount;
            for (int i = 0; i < update.VertexCount; i++)
            {
                TubeVertex v = vertices[i];
                Add(sums, magnitudes, 2, v.PX + 2.0 * v.PY + 3.0 * v.PZ, Math.Abs(v.PX) + 2.0 * Math.Abs(v.PY) + 3.0 * Math.Abs(v.PZ));
                Add(sums, magnitudes, 3, v.NX + 2.0 * v.NY + 3.0 * v.NZ, Math.Abs(v.NX) + 2.0 * Math.Abs(v.NY) + 3.0 * Math.Abs(v.NZ));
                Add(sums, magnitudes, 4, v.TX + 2.0 * v.TY + 3.0 * v.TZ, Math.Abs(v.TX) + 2.0 * Math.Abs(v.TY) + 3.0 * Math.Abs(v.TZ));
                Add(sums, magnitudes, 5, v.U + 2.0 * v.V, Math.Abs(v.U) + 2.0 * Math.Abs(v.V));
            }
            for (int k = 0; k < update.IndexCount; k++) sums[6] += (double)indices[k] * (k % 7);
            return sums;
        }

        private static void Add(double[] sums, double[] magnitudes, int slot, double value, double magnitude)
        {
            sums[slot] += value;
            magnitudes[slot] += magnitude;
        }

        [TestCaseSource(nameof(Scenes))]
        public void TheTubeOfATautRopeIsDrawnAsBefore(int scene)
        {
            var update = TautTubeScenes.Draw(scene, out var vertices, out var indices, out var builder);
            double[] sums = Sums(vertices, indices, update, out double[] magnitudes);
            builder.FoldCounts(out int tips, out int thinned, out int strips);
            TestContext.WriteLine($"{TautTubeScenes.Names[scene]}: {{ {string.Join(", ", Array.ConvertAll(sums, v => v.ToString("R")))} }}; fold tips {tips}, thinned {thinned}, strip normals {strips}");
            Assert.That(tips, Is.EqualTo(0), "no fold tip");
            Assert.That(thinned, Is.EqualTo(0), "no ring drawn thinner than its radius");
            Assert.That(strips, Is.EqualTo(0), "the tube's own normals everywhere");
            double[] before = Before[scene];
            Assert.That(sums[0], Is.EqualTo(before[0]), "vertices");
            Assert.That(sums[1], Is.EqualTo(before[1]), "indices");
            Assert.That(sums[6], Is.EqualTo(before[6]), "the triangles");
            for (int slot = 2; slot <= 5; slot++)
                Assert.That(sums[slot], Is.EqualTo(before[slot]).Within(1e-6 * magnitudes[slot]), "sum " + slot);
        }
    }
}
