using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;

namespace HookeRope.Bench
{
    /// <summary>
    /// Stopwatch measurement of <see cref="GoalScene"/> worlds: the goal rows (100 × 64, 1 and 2 workers) and the cost
    /// curves against rope count and segment count. Every row measures the same frames of the scene
    /// (<see cref="GoalScene.Window"/>, after <see cref="GoalScene.WarmUpFrames"/> warm-up frames) on freshly built
    /// worlds, repeated until a time budget is spent; every frame is timed on its own and the row keeps the median and
    /// the fastest frame, the fastest repeat's mean, and per frame the process CPU time, the ropes' step and mesh
    /// thread time and the workers' idle time. Timings are printed, never asserted.
    /// </summary>
    internal static class GoalBench
    {
        /// <summary>
        /// Measures the configuration of <paramref name="row"/> (its id, ropes, segments, workers, ring tolerance, detail
        /// distance and tangents; <see cref="Plan"/>) and writes the figures into it: at least <paramref name="minRepeats"/>
        /// repeats of the window, more while the repeats so far took less than <paramref name="seconds"/> (at most 50).
        /// </summary>
        public static GoalRow Measure(GoalRow row, double seconds, int minRepeats)
        {
            int ropes = row.Ropes, segments = row.Segments, workers = row.Workers;
            float ringTolerance = row.RingTolerance, detailDistance = row.DetailDistance;
            row.Substeps = GoalScene.Substeps;
            row.MeshSides = GoalScene.MeshSides;
            row.Window = GoalScene.Window;
            var samples = new List<double>();
            var watch = new Stopwatch();
            var window = new Stopwatch();
            var process = Process.GetCurrentProcess();
            var total = Stopwatch.StartNew();
            double step = 0.0, mesh = 0.0, vertices = 0.0, idle = 0.0, wake = 0.0, cpu = 0.0, bestWindow = double.MaxValue;
            int repeats = 0;
            while (repeats < minRepeats || (total.Elapsed.TotalSeconds < seconds && repeats < 50))
            {
                using (var world = GoalScene.Build(ropes, segments, workers, warmUpFrames: GoalScene.WarmUpFrames, ringTolerance: ringTolerance,
                           detailDistance: detailDistance, tangents: row.Tangents))
                {
                    process.Refresh();
                    TimeSpan cpuBefore = process.TotalProcessorTime;
                    window.Restart();
                    for (int f = 0; f < GoalScene.WindowFrames; f++)
                    {
                        watch.Restart();
                        // the main thread's share of a view-distance detail, timed with the frame
                        if (detailDistance > 0f) GoalScene.ApplyViewDetail(world, ringTolerance, detailDistance);
                        world.StepAndFillMeshes(GoalScene.Frame);
                        watch.Stop();
                        samples.Add(watch.Elapsed.TotalMilliseconds);
                        for (int i = 0; i < world.Count; i++)
                        {
                            step += world.GetLastStepMilliseconds(i);
                            mesh += world.GetLastFillMilliseconds(i);
                        }
                        double latest = 0.0;
                        for (int w = 0; w < world.WorkerCount; w++)
                        {
                            idle += world.LastIdleMilliseconds(w);
                            latest = Math.Max(latest, world.LastWakeMilliseconds(w));
                        }
                        wake += latest;
                        vertices += MeanVertices(world);
                    }
                    window.Stop();
                    process.Refresh();
                    cpu += (process.TotalProcessorTime - cpuBefore).TotalMilliseconds;
                    bestWindow = Math.Min(bestWindow, window.Elapsed.TotalMilliseconds / GoalScene.WindowFrames);
                }
                repeats++;
            }
            int frames = samples.Count;
            row.Repeats = repeats;
            row.StepMsPerFrame = step / frames;
            row.MeshMsPerFrame = mesh / frames;
            row.IdleMsPerFrame = workers > 1 ? idle / frames : 0.0;
            row.WakeMsPerFrame = workers > 1 ? wake / frames : 0.0;
            row.CpuMsPerFrame = cpu / frames;
            row.VerticesPerRope = vertices / frames;
            row.BestWindowMsPerFrame = bestWindow;
            samples.Sort();
            row.MsPerFrame = samples[frames / 2];
            row.MinMsPerFrame = samples[0];
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

        /// <summary>
        /// The rows of the table, unmeasured: goal at 1 and 2 workers, and at 2 workers with the meshes' ring tolerance 2, with
        /// the view-distance detail and without tangents, then rope counts 1 … 500 and segment counts 16 … 1 024 at 2 workers.
        /// </summary>
        public static List<GoalRow> Plan(bool quick)
        {
            var plan = new List<GoalRow>
            {
                Row("goal 100x64 w1", 100, 64, 1), Row("goal 100x64 w2", 100, 64, 2),
                // the goal scene with TubeMeshSettings.RingTolerance 2 (not the goal: its meshes' along-rope tolerance is doubled)
                Row("goal 100x64 w2 tol2", 100, 64, 2, ringTolerance: 2f),
                // the goal scene seen from GoalScene.Viewer with a detail distance of 2 m (not the goal: the far ropes draw
                // coarser along, by ViewDetail, the same angle of error as a rope at 2 m)
                Row("goal 100x64 w2 view2m", 100, 64, 2, detailDistance: 2f),
                // the goal scene's meshes without tangents (the same surface, 32-byte vertices: for materials without a normal map)
                Row("goal 100x64 w2 lean", 100, 64, 2, tangents: false),
            };
            int[] ropeCounts = quick ? new[] { 1, 10, 100, 500 } : new[] { 1, 2, 5, 10, 20, 50, 100, 200, 500 };
            foreach (int r in ropeCounts) plan.Add(Row($"ropes {r}x64 w2", r, 64, 2));
            int[] segmentCounts = quick ? new[] { 16, 256 } : new[] { 16, 32, 64, 128, 256, 1024 };
            foreach (int s in segmentCounts) plan.Add(Row($"segments 10x{s} w2", 10, s, 2));
            return plan;
        }

        private static GoalRow Row(string id, int ropes, int segments, int workers, float ringTolerance = 1f, float detailDistance = 0f, bool tangents = true) =>
            new GoalRow { Id = id, Ropes = ropes, Segments = segments, Workers = workers, RingTolerance = ringTolerance, DetailDistance = detailDistance, Tangents = tangents };

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
