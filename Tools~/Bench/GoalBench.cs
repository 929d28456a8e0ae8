using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;

namespace HookeRope.Bench
{
    /// <summary>
    /// Stopwatch measurement of <see cref="GoalScene"/> worlds: the goal rows (100 × 64, 1 and 2 workers) and the cost
    /// curves against rope count and segment count. Every frame is timed on its own; the row keeps the median and the
    /// fastest frame. Timings are printed, never asserted.
    /// </summary>
    internal static class GoalBench
    {
        /// <summary>Measures one configuration for about <paramref name="seconds"/> of frames (at least 15).</summary>
        public static GoalRow Measure(string id, int ropes, int segments, int workers, double seconds)
        {
            var row = new GoalRow { Id = id, Ropes = ropes, Segments = segments, Substeps = GoalScene.Substeps, MeshSides = GoalScene.MeshSides, Workers = workers };
            using (var world = GoalScene.Build(ropes, segments, workers))
            {
                var watch = new Stopwatch();
                var samples = new List<double>();
                var process = Process.GetCurrentProcess();
                process.Refresh();
                TimeSpan cpuBefore = process.TotalProcessorTime;
                var total = Stopwatch.StartNew();
                double step = 0.0, mesh = 0.0, vertices = 0.0;
                while (samples.Count < 15 || total.Elapsed.TotalSeconds < seconds)
                {
                    watch.Restart();
                    world.StepAndFillMeshes(GoalScene.Frame);
                    watch.Stop();
                    samples.Add(watch.Elapsed.TotalMilliseconds);
                    for (int i = 0; i < world.Count; i++)
                    {
                        step += world.GetLastStepMilliseconds(i);
                        mesh += world.GetLastFillMilliseconds(i);
                    }
                    vertices += MeanVertices(world);
                    if (samples.Count >= 2000) break;
                }
                row.StepMsPerFrame = step / samples.Count;
                row.MeshMsPerFrame = mesh / samples.Count;
                process.Refresh();
                row.CpuMsPerFrame = (process.TotalProcessorTime - cpuBefore).TotalMilliseconds / samples.Count;
                row.VerticesPerRope = vertices / samples.Count;
                row.LastFrame = GoalScene.WarmUpFrames + samples.Count;
                samples.Sort();
                row.MsPerFrame = samples[samples.Count / 2];
                row.MinMsPerFrame = samples[0];
            }
            row.NsPerUnit = row.MsPerFrame * 1e6 / row.UnitsPerFrame;
            row.LoadAverage = LoadAverage();
            return row;
        }

        /// <summary>
        /// Runs a 100 × 64 goal world on 2 workers for at least <paramref name="seconds"/> (and 60 frames) before the table,
        /// so that no row is measured while the tiered JIT still compiles on a background thread (which took the second
        /// core from the first rows).
        /// </summary>
        public static void WarmUp(double seconds)
        {
            using (var world = GoalScene.Build(100, 64, 2))
            {
                var total = Stopwatch.StartNew();
                for (int frames = 0; frames < 60 || total.Elapsed.TotalSeconds < seconds; frames++) world.StepAndFillMeshes(GoalScene.Frame);
            }
        }

        /// <summary>Mean vertex count of the world's mesh slots after their last fill.</summary>
        public static double MeanVertices(HookeRope.World.RopeWorld world)
        {
            double sum = 0.0;
            for (int i = 0; i < world.Count; i++) sum += world.GetMeshSlot(i).Update.VertexCount;
            return world.Count > 0 ? sum / world.Count : 0.0;
        }

        /// <summary>The rows of the table: goal at 1 and 2 workers, then rope counts 1 … 500 and segment counts 16 … 1 024 at 2 workers.</summary>
        public static List<(string Id, int Ropes, int Segments, int Workers)> Plan(bool quick)
        {
            var plan = new List<(string, int, int, int)> { ("goal 100x64 w1", 100, 64, 1), ("goal 100x64 w2", 100, 64, 2) };
            int[] ropeCounts = quick ? new[] { 1, 10, 100, 500 } : new[] { 1, 2, 5, 10, 20, 50, 100, 200, 500 };
            foreach (int r in ropeCounts) plan.Add(($"ropes {r}x64 w2", r, 64, 2));
            int[] segmentCounts = quick ? new[] { 16, 256 } : new[] { 16, 32, 64, 128, 256, 1024 };
            foreach (int s in segmentCounts) plan.Add(($"segments 10x{s} w2", 10, s, 2));
            return plan;
        }

        /// <summary>1-minute load average from /proc/loadavg, or −1 where it is not available.</summary>
        public static double LoadAverage()
        {
            try
            {
                string text = File.ReadAllText("/proc/loadavg");
                return double.Parse(text.Split(' ')[0], System.Globalization.CultureInfo.InvariantCulture);
            }
            catch (Exception)
            {
                return -1;
            }
        }
    }
}
