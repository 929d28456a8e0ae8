using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace HookeRope.Bench
{
    /// <summary>
    /// <c>goal [--quick] [--instructions] [--save]</c>: prints issue 18's goal table (ropes, segments, substeps, mesh
    /// sides, workers, ms per frame, ns per unit, instructions per unit where measured, mean tube vertices per rope,
    /// load average) and compares
    /// every row with Tools~/Bench/baseline.json, flagging rises over 10 %. <c>--instructions</c> adds callgrind
    /// counts for the goal rows (a few minutes); <c>--save</c> stores the rows as the new baseline.
    /// <c>frames R S W N</c> steps the goal scene N frames and exits (what callgrind runs).
    /// </summary>
    internal static class GoalCommand
    {
        /// <summary>Runs the command; returns the process exit code (0, or 1 when a row regressed).</summary>
        public static int Execute(string[] args)
        {
            bool quick = args.Contains("--quick"), save = args.Contains("--save"), instructions = args.Contains("--instructions");
            var c = CultureInfo.InvariantCulture;
            string baselinePath = Baseline.PathInRepository(PackageRoot());
            var stored = Baseline.Load(baselinePath);
            Console.WriteLine($"HookeRope bench · goal  {Environment.ProcessorCount} logical processors, load average {GoalBench.LoadAverage().ToString("F2", c)}, " +
                              $"{System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription}");
            Console.WriteLine("frame = one 1/90 s RopeWorld.StepAndFillMeshes: step + 16-sided tube mesh of every rope; unit = segment-substep;");
            Console.WriteLine("step ms / mesh ms = thread time of the ropes' steps / mesh fills per frame, summed over the ropes (all workers)");
            Console.WriteLine();
            GoalBench.WarmUp(quick ? 1.0 : 3.0);
            string header = string.Format(c, "{0,-20} {1,6} {2,8} {3,9} {4,5} {5,7} {6,10} {7,10} {8,10} {9,9} {10,9} {11,10} {12,11} {13,10} {14,6} {15,6}  {16}",
                "row", "ropes", "segments", "substeps", "sides", "workers", "ms/frame", "min ms", "cpu ms", "step ms", "mesh ms", "ns/unit", "instr/unit", "verts/rope", "frame", "load", "against baseline");
            Console.WriteLine(header);
            Console.WriteLine(new string('-', header.Length + 10));
            var rows = new List<GoalRow>();
            int regressions = 0;
            foreach (var (id, ropes, segments, workers) in GoalBench.Plan(quick))
            {
                var row = GoalBench.Measure(id, ropes, segments, workers, quick ? 0.5 : 2.0);
                if (instructions && id.StartsWith("goal", StringComparison.Ordinal))
                    row.InstructionsPerUnit = InstructionCounter.PerUnit(ropes, segments, workers, 3, 13, m => Console.Error.WriteLine(m));
                string verdict = Baseline.Compare(row, stored);
                if (verdict.StartsWith("REGRESSION", StringComparison.Ordinal)) regressions++;
                rows.Add(row);
                Console.WriteLine(string.Format(c, "{0,-20} {1,6} {2,8} {3,9} {4,5} {5,7} {6,10:F3} {7,10:F3} {8,10:F3} {9,9:F3} {10,9:F3} {11,10:F1} {12,11} {13,10:F0} {14,6} {15,6:F2}  {16}",
                    row.Id, row.Ropes, row.Segments, row.Substeps, row.MeshSides, row.Workers, row.MsPerFrame, row.MinMsPerFrame, row.CpuMsPerFrame,
                    row.StepMsPerFrame, row.MeshMsPerFrame, row.NsPerUnit,
                    row.InstructionsPerUnit > 0 ? row.InstructionsPerUnit.ToString("F0", c) : "-", row.VerticesPerRope, row.LastFrame, row.LoadAverage, verdict));
            }
            var one = rows.Find(r => r.Id == "goal 100x64 w1");
            var two = rows.Find(r => r.Id == "goal 100x64 w2");
            Console.WriteLine();
            Console.WriteLine(string.Format(c, "goal 100 x 64 + 16-sided mesh: {0:F3} ms (1 worker) -> {1:F3} ms (2 workers), speed-up {2:F2}x; target <= 2.8 ms: {3}",
                one.MsPerFrame, two.MsPerFrame, one.MsPerFrame / two.MsPerFrame, two.MsPerFrame <= 2.8 ? "met" : "NOT met"));
            if (one.InstructionsPerUnit > 0 && two.InstructionsPerUnit > 0)
                Console.WriteLine(string.Format(c, "instructions per unit, 2 workers / 1 worker: {0:F3} (threading overhead)", two.InstructionsPerUnit / one.InstructionsPerUnit));
            Console.WriteLine("wall-clock rows are medians on whatever load the machine has (see 'load'); compare instruction counts for ratios.");
            Console.WriteLine("verts/rope = mean over the measured frames; frame = the frame of the lanyards' drop the row ended at (rows that end at");
            Console.WriteLine("different frames draw different ring budgets: the mesh columns compare only between rows ending near the same frame).");
            if (save)
            {
                Baseline.Save(baselinePath, rows);
                Console.WriteLine("baseline written: " + baselinePath);
            }
            if (regressions > 0) Console.WriteLine(regressions + " row(s) regressed by more than 10 %.");
            return regressions > 0 ? 1 : 0;
        }

        /// <summary>Steps a goal scene of R ropes × S segments on W workers for N frames (callgrind's workload).</summary>
        public static int Frames(string[] args)
        {
            int ropes = int.Parse(args[1], CultureInfo.InvariantCulture), segments = int.Parse(args[2], CultureInfo.InvariantCulture);
            int workers = int.Parse(args[3], CultureInfo.InvariantCulture), frames = int.Parse(args[4], CultureInfo.InvariantCulture);
            using (var world = GoalScene.Build(ropes, segments, workers))
            {
                for (int i = 0; i < frames; i++) world.StepAndFillMeshes(GoalScene.Frame);
            }
            return 0;
        }

        /// <summary>The package root: the first folder upwards from the working directory, then from this tool, that holds package.json and Tools~.</summary>
        private static string PackageRoot()
        {
            foreach (string startDir in new[] { Directory.GetCurrentDirectory(), AppContext.BaseDirectory })
            {
                for (var dir = new DirectoryInfo(startDir); dir != null; dir = dir.Parent)
                    if (File.Exists(Path.Combine(dir.FullName, "package.json")) && Directory.Exists(Path.Combine(dir.FullName, "Tools~")))
                        return dir.FullName;
            }
            return Directory.GetCurrentDirectory();
        }
    }
}
