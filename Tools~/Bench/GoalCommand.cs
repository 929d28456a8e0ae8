using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;

namespace HookeRope.Bench
{
    /// <summary>
    /// <c>goal [--quick] [--match TEXT] [--instructions] [--counts FILE] [--save]</c>: prints issue 18's goal table (ropes, segments,
    /// substeps, mesh sides, workers, repeats, ms per frame, ns per unit, instructions per unit where counted, mean tube
    /// vertices per rope, the workers' idle time, load average), every row measured over the same frames of the scene
    /// (<see cref="GoalScene.Window"/>) on freshly built worlds, and compares every row with Tools~/Bench/baseline.json,
    /// flagging rises over 10 %. The instruction figures come from the file Tools~/Kernels/goal-count.sh writes
    /// (<see cref="GoalCounts"/>; <c>--instructions</c> runs the script first, 2–4 minutes; <c>--counts</c> names
    /// another file); <c>--match</c> keeps the rows whose name contains TEXT (e.g. "goal"); <c>--save</c> stores the
    /// rows as the new baseline. Without <c>--match</c> it ends with the kernel figures of issue 18 items 1 and 2 against
    /// the issue's (<see cref="KernelFigures"/>; their instructions from kernel-count.sh's file next to the goal count's,
    /// which <c>--instructions</c> also runs). <c>frames R S W N</c> steps the goal scene N frames and exits.
    /// </summary>
    internal static class GoalCommand
    {
        /// <summary>Runs the command; returns the process exit code (0, or 1 when a row regressed).</summary>
        public static int Execute(string[] args)
        {
            bool quick = args.Contains("--quick"), save = args.Contains("--save"), instructions = args.Contains("--instructions");
            int countsAt = Array.IndexOf(args, "--counts"), matchAt = Array.IndexOf(args, "--match");
            string match = matchAt >= 0 && matchAt + 1 < args.Length ? args[matchAt + 1] : null;
            var c = CultureInfo.InvariantCulture;
            string root = PackageRoot();
            string baselinePath = Baseline.PathInRepository(root);
            var stored = Baseline.Load(baselinePath);
            string countsPath = countsAt >= 0 && countsAt + 1 < args.Length ? args[countsAt + 1] : GoalCounts.DefaultPath();
            if (instructions)
            {
                RunCountScript(root, "goal-count.sh", countsPath, "100");
                RunCountScript(root, "kernel-count.sh", countsPath);
            }
            GoalCounts counts = CurrentCounts(root, countsPath);
            Console.WriteLine($"HookeRope bench · goal  {Environment.ProcessorCount} logical processors, load average {GoalBench.LoadAverage().ToString("F2", c)}, " +
                              $"{System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription}");
            Console.WriteLine("frame = one 1/90 s RopeWorld.StepAndFillMeshes: step + 16-sided tube mesh of every rope; unit = segment-substep;");
            Console.WriteLine($"every row times frames {GoalScene.Window} of the scene ({GoalScene.WarmUpFrames} warm-up frames, then {GoalScene.WindowFrames} timed) on freshly built worlds, 'reps' times;");
            Console.WriteLine("ms/frame = median frame, min = fastest frame, best = the fastest repeat's mean frame; cpu = process CPU per timed frame;");
            Console.WriteLine("step / mesh = thread time of the ropes' steps / mesh fills per frame, summed over the ropes (all workers);");
            Console.WriteLine("idle = per frame, summed over the workers, the time a worker was not on its share (wake-up + waiting for the others); wake = the pool thread's start lag");
            Console.WriteLine();
            GoalBench.WarmUp(quick ? 1.0 : 3.0);
            double fill = MachineProbe.FillMilliseconds(), chase = MachineProbe.ChaseNanoseconds();
            Console.WriteLine(string.Format(c, "machine: one core writes a goal frame's {0:F1} MB of tube vertices in {1:F2} ms at best ({2:F1} GB/s; the mesh's floor on one core), " +
                "a dependent load in {3} MiB takes {4:F0} ns", MachineProbe.GoalVertexBytes / 1e6, fill, MachineProbe.GoalVertexBytes / (fill * 1e6), MachineProbe.ChaseBytes >> 20, chase));
            Console.WriteLine();
            const string format = "{0,-20} {1,5} {2,8} {3,8} {4,5} {5,7} {6,4} {7,9} {8,8} {9,8} {10,8} {11,8} {12,8} {13,7} {14,7} {15,8} {16,10} {17,10} {18,6}  {19}";
            string header = string.Format(c, format, "row", "ropes", "segments", "substeps", "sides", "workers", "reps", "ms/frame", "min ms", "best ms",
                "cpu ms", "step ms", "mesh ms", "idle ms", "wake ms", "ns/unit", "instr/unit", "verts/rope", "load", "against baseline");
            Console.WriteLine(header);
            Console.WriteLine(new string('-', header.Length + 10));
            var rows = new List<GoalRow>();
            int regressions = 0;
            foreach (GoalRow planned in GoalBench.Plan(quick))
            {
                if (match != null && !planned.Id.Contains(match, StringComparison.Ordinal)) continue;
                bool goal = planned.Id.StartsWith("goal", StringComparison.Ordinal);
                var row = GoalBench.Measure(planned, goal ? (quick ? 1.0 : 4.0) : (quick ? 0.3 : 2.0), goal || !quick ? 3 : 1);
                counts?.ApplyTo(row);
                row.FillProbeMs = fill;
                row.ChaseProbeNs = chase;
                string verdict = Baseline.Compare(row, stored);
                if (verdict.StartsWith("REGRESSION", StringComparison.Ordinal)) regressions++;
                rows.Add(row);
                Console.WriteLine(string.Format(c, format, row.Id, row.Ropes, row.Segments, row.Substeps, row.MeshSides, row.Workers, row.Repeats,
                    row.MsPerFrame.ToString("F3", c), row.MinMsPerFrame.ToString("F3", c), row.BestWindowMsPerFrame.ToString("F3", c),
                    row.CpuMsPerFrame.ToString("F3", c), row.StepMsPerFrame.ToString("F3", c), row.MeshMsPerFrame.ToString("F3", c),
                    row.IdleMsPerFrame.ToString("F3", c), row.WakeMsPerFrame.ToString("F3", c), row.NsPerUnit.ToString("F1", c),
                    row.InstructionsPerUnit > 0 ? row.InstructionsPerUnit.ToString("F0", c) : "-", row.VerticesPerRope.ToString("F0", c),
                    row.LoadAverage.ToString("F2", c), verdict));
            }
            var one = rows.Find(r => r.Id == "goal 100x64 w1");
            var two = rows.Find(r => r.Id == "goal 100x64 w2");
            Console.WriteLine();
            if (one != null && two != null)
                Console.WriteLine(string.Format(c, "goal 100 x 64 + 16-sided mesh: {0:F3} ms (1 worker) -> {1:F3} ms (2 workers), speed-up {2:F2}x; target <= 2.8 ms: {3}",
                one.MsPerFrame, two.MsPerFrame, one.MsPerFrame / two.MsPerFrame, two.MsPerFrame <= 2.8 ? "met" : "NOT met"));
            if (one != null && one.InstructionsPerUnit > 0)
                Console.WriteLine(string.Format(c, "instructions ({0}, 1 worker, counted at {1}): {2:F0} per frame = step {3:F0} per segment-substep + mesh {4:F1} per vertex; {5:F0} per segment-substep in all",
                    one.InstructionSource, counts.Commit, one.InstructionsPerFrame, one.StepInstructionsPerUnit, one.MeshInstructionsPerVertex, one.InstructionsPerUnit));
            Console.WriteLine("wall-clock rows are medians on whatever load the machine has (see 'load'); compare instruction counts for ratios.");
            Console.WriteLine(MachineAgainstBaseline(stored, fill, chase));
            if (match == null) KernelFigures.Print(root, Path.Combine(Path.GetDirectoryName(Path.GetFullPath(countsPath)), "kernel-count.txt"), quick, one);
            if (save)
            {
                Baseline.Save(baselinePath, rows);
                Console.WriteLine("baseline written: " + baselinePath);
            }
            if (regressions > 0) Console.WriteLine(regressions + " row(s) regressed by more than 10 %.");
            return regressions > 0 ? 1 : 0;
        }

        /// <summary>The machine probes now against the baseline's (from its first row that has them): a slower machine, not slower code, when a wall-clock or CPU "regression" comes with them.</summary>
        private static string MachineAgainstBaseline(Dictionary<string, GoalRow> stored, double fill, double chase)
        {
            foreach (var row in stored.Values)
            {
                if (!(row.FillProbeMs > 0 && row.ChaseProbeNs > 0)) continue;
                return string.Format(CultureInfo.InvariantCulture,
                    "machine against the baseline's: vertex fill {0:F2} ms against {1:F2} ms ({2:F2}x), dependent load {3:F0} ns against {4:F0} ns ({5:F2}x); " +
                    "CPU-time verdicts above are of the code only where these are near 1x", fill, row.FillProbeMs, fill / row.FillProbeMs, chase, row.ChaseProbeNs, chase / row.ChaseProbeNs);
            }
            return "machine against the baseline's: the baseline has no machine probe (saved before it existed; --save records one), so a CPU-time verdict above may be the machine's";
        }

        /// <summary>The counts in <paramref name="path"/> when they were made of the code in <paramref name="root"/> as it is now, else null (saying why).</summary>
        private static GoalCounts CurrentCounts(string root, string path)
        {
            GoalCounts counts = GoalCounts.Load(path);
            if (counts == null)
            {
                Console.WriteLine("instructions: no count at " + path + " (bash \"Tools~/Kernels/goal-count.sh\" writes it, or pass --instructions)");
                return null;
            }
            var (code, changes) = GoalCounts.TreeOf(root);
            if (!counts.CountedAt(code, changes))
            {
                Console.WriteLine("instructions: the count at " + path + " (commit " + counts.Commit + ") is of other code than this tree's: not shown; rerun goal-count.sh");
                return null;
            }
            Console.WriteLine("instructions: " + path + " (" + counts.Source + ", " + counts.Ropes + " x " + counts.Segments + ", commit " + counts.Commit + ")");
            return counts;
        }

        /// <summary>Runs Tools~/Kernels/<paramref name="script"/> with <paramref name="arguments"/>, writing <paramref name="path"/>'s directory (its KERNELS_OUT).</summary>
        private static void RunCountScript(string root, string script, string path, params string[] arguments)
        {
            var info = new ProcessStartInfo("bash") { UseShellExecute = false };
            info.ArgumentList.Add(Path.Combine(root, "Tools~", "Kernels", script));
            foreach (string argument in arguments) info.ArgumentList.Add(argument);
            info.Environment["KERNELS_OUT"] = Path.GetDirectoryName(Path.GetFullPath(path));
            using (var process = Process.Start(info)) process.WaitForExit();
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
