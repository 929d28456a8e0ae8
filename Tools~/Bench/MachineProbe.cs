using System;
using System.Diagnostics;
using System.Threading;

namespace HookeRope.Bench
{
    /// <summary>
    /// Two figures of the machine itself, with no package code in them, printed above the goal table and stored with its
    /// rows: how long one core takes to write the goal frame's tube vertices (<see cref="GoalVertexBytes"/>, a plain fill
    /// of that many bytes, best of several) and the latency of a dependent load in a buffer of
    /// <see cref="ChaseBytes"/> (a random cycle, so neither the prefetcher nor the private L2 serves it: a shared L3 does,
    /// or memory). The goal frame's mesh writes every vertex once per frame, so the fill is a floor under the mesh's time on
    /// this machine; and a machine whose L3 is taken by other tenants shows it in the chase. Two runs on different machines
    /// (or days) compare by these first.
    /// </summary>
    internal static class MachineProbe
    {
        /// <summary>Bytes of tube vertices one goal frame writes: 100 ropes × 4 403 vertices (the settled budget of the window) × 48 bytes.</summary>
        public const int GoalVertexBytes = 100 * 4403 * HookeRope.Geometry.TubeVertex.SizeInBytes;

        /// <summary>Buffer of the dependent-load chase: 4 MiB, four times a core's L2 here and far inside the L3.</summary>
        public const int ChaseBytes = 4 << 20;

        /// <summary>Best time (ms) of one core writing <see cref="GoalVertexBytes"/> bytes.</summary>
        public static double FillMilliseconds()
        {
            var buffer = new byte[GoalVertexBytes];
            Span<byte> span = buffer;
            span.Fill(1);
            double best = double.MaxValue;
            var watch = new Stopwatch();
            for (int r = 0; r < 12; r++)
            {
                watch.Restart();
                span.Fill((byte)r);
                watch.Stop();
                best = Math.Min(best, watch.Elapsed.TotalMilliseconds);
            }
            return best;
        }

        /// <summary>Mean latency (ns) of a dependent load in a random cycle over <see cref="ChaseBytes"/> bytes.</summary>
        public static double ChaseNanoseconds()
        {
            int n = ChaseBytes / sizeof(int);
            var next = new int[n];
            // Sattolo's algorithm: one cycle through every slot in a random order (fixed seed: the same cycle every run)
            for (int i = 0; i < n; i++) next[i] = i;
            var random = new Random(18);
            for (int i = n - 1; i > 0; i--)
            {
                int j = random.Next(i);
                (next[i], next[j]) = (next[j], next[i]);
            }
            const int Steps = 4_000_000;
            int at = 0;
            for (int s = 0; s < n; s++) at = next[at];
            var watch = Stopwatch.StartNew();
            for (int s = 0; s < Steps; s++) at = next[at];
            watch.Stop();
            Volatile.Write(ref sink, at);
            return watch.Elapsed.TotalMilliseconds * 1e6 / Steps;
        }

        private static int sink;
    }
}
