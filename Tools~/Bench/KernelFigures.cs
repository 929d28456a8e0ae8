using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using HookeRope.Kernels;
using HookeRope.Solver;

namespace HookeRope.Bench
{
    /// <summary>
    /// The kernel figures of issue 18 item 1 printed by <c>bench goal</c> against the figures the issue quotes and its
    /// targets: Gauss–Seidel instructions per simulated second on the peer comparison's 16-segment chain against
    /// PositionBasedDynamics' 2.1 M (from kernel-count.sh's file while the code is unchanged), the exact solve's ns per
    /// segment-iteration on the resting hanging rope at 256, 1 024 and 10 000 segments (timed here, Tools~/Kernels'
    /// scene and timer) with its instructions per segment-substep, and the tube mesh's ns per vertex inside the goal
    /// world (the 1-worker goal row's mesh thread time over its vertices).
    /// </summary>
    internal static class KernelFigures
    {
        /// <summary>The peer kernel's instructions per simulated second (the figure: solve_DistanceConstraint, 16 segments, 8 × 1).</summary>
        public const double PeerPerSimulatedSecond = 2.1e6;

        /// <summary>Prints the table; <paramref name="goalOneWorker"/> is the measured 1-worker goal row (null when not run).</summary>
        public static void Print(string root, string countsPath, bool quick, GoalRow goalOneWorker)
        {
            var c = CultureInfo.InvariantCulture;
            Console.WriteLine();
            Console.WriteLine("kernels (issue 18 items 1 and 2) against the issue's figures:");
            Dictionary<string, string> counts = CurrentCounts(root, countsPath);
            const string format = "{0,-64} {1,-34} {2,-40} {3,-10} {4}";
            string header = string.Format(c, format, "kernel", "now", "issue's figure", "target", "");
            Console.WriteLine(header);
            Console.WriteLine(new string('-', header.Length + 8));
            if (counts != null)
            {
                double precise = Number(counts, "gs_be_chain16_per_simulated_second");
                double fused = Number(counts, "gs_fast_chain16_per_simulated_second");
                Console.WriteLine(string.Format(c, format, "Gauss-Seidel (default Precise), instructions / simulated s",
                    (precise / 1e6).ToString("F2", c) + " M = " + (precise / PeerPerSimulatedSecond).ToString("F2", c) + "x the peer",
                    "peer 2.1 M; ours 7.0 M (3.3x)", "<= 1.2x", Verdict(precise / PeerPerSimulatedSecond <= 1.2)));
                Console.WriteLine(string.Format(c, format, "Gauss-Seidel (opt-in FusedSingle), instructions / simulated s",
                    (fused / 1e6).ToString("F2", c) + " M = " + (fused / PeerPerSimulatedSecond).ToString("F2", c) + "x the peer",
                    "peer 2.1 M", "<= 1.2x", Verdict(fused / PeerPerSimulatedSecond <= 1.2)));
                Console.WriteLine(string.Format(c, format, "exact solve at rest, instructions / segment-substep 256 | 10 000",
                    Number(counts, "exact_rest_256_per_segment_substep").ToString("F0", c) + " | " + Number(counts, "exact_rest_10000_per_segment_substep").ToString("F0", c),
                    "-", "flat", ""));
            }
            int rounds = quick ? 3 : 7;
            double at256 = ExactNs(256, rounds), at1024 = ExactNs(1024, rounds), at10000 = ExactNs(10000, rounds);
            Console.WriteLine(string.Format(c, format, "exact solve at rest, ns / segment-iteration 256 | 1 024 | 10 000",
                at256.ToString("F1", c) + " | " + at1024.ToString("F1", c) + " | " + at10000.ToString("F1", c),
                "47-54 up to 1 024, 85 beyond", "<= 25 flat", Verdict(Math.Max(at256, Math.Max(at1024, at10000)) <= 25.0)));
            if (goalOneWorker != null && goalOneWorker.VerticesPerRope > 0)
            {
                double nsPerVertex = goalOneWorker.MeshMsPerFrame * 1e6 / (goalOneWorker.VerticesPerRope * goalOneWorker.Ropes);
                Console.WriteLine(string.Format(c, format, "tube mesh in the goal world (16 sides), ns / vertex",
                    nsPerVertex.ToString("F1", c), "26-33 (8 sides, alone)", "<= 8", Verdict(nsPerVertex <= 8.0)));
                Console.WriteLine(string.Format(c, format, "goal world mesh against step (thread ms per frame, 1 worker)",
                    goalOneWorker.MeshMsPerFrame.ToString("F2", c) + " against " + goalOneWorker.StepMsPerFrame.ToString("F2", c),
                    "1.5x the solve (256 segments, 8 sides)", "< step", Verdict(goalOneWorker.MeshMsPerFrame < goalOneWorker.StepMsPerFrame)));
            }
            Console.WriteLine("ns: Stopwatch on this machine now (8 substeps x 1 iteration, whole step, best of " + rounds + " rounds; `Kernels time` prints the full table);" +
                              " instructions: " + (counts != null ? "kernel-count.sh, ISA " + counts["isa"] + ", commit " + Short(counts["commit"]) : "none"));
        }

        /// <summary>ns per segment-iteration of the exact solve on the hanging rope at its static equilibrium (one linear solve per iteration).</summary>
        private static double ExactNs(int segments, int rounds) =>
            KernelTimer.Time(KernelTimer.Settled(KernelScene.Resting(ConstraintSolverKind.ExactChain, RopeSettings.DefaultIntegrator, segments, 8, 1)), rounds)
                .PerConfiguredIteration;

        /// <summary>The kernel counts at <paramref name="path"/> when made of this tree's code, else null (saying why).</summary>
        private static Dictionary<string, string> CurrentCounts(string root, string path)
        {
            var counts = GoalCounts.ReadCountFile(path, "gs_be_chain16_per_simulated_second", "gs_fast_chain16_per_simulated_second",
                "exact_rest_256_per_segment_substep", "exact_rest_10000_per_segment_substep");
            if (counts == null)
            {
                Console.WriteLine("kernel instructions: no count at " + path + " (bash \"Tools~/Kernels/kernel-count.sh\" writes it, or pass --instructions)");
                return null;
            }
            var (code, changes) = GoalCounts.TreeOf(root);
            if (counts["code"] != code || counts["changes"] != changes)
            {
                Console.WriteLine("kernel instructions: the count at " + path + " (commit " + Short(counts["commit"]) + ") is of other code than this tree's: not shown; rerun kernel-count.sh");
                return null;
            }
            return counts;
        }

        private static double Number(Dictionary<string, string> counts, string key) => double.Parse(counts[key], CultureInfo.InvariantCulture);

        private static string Short(string commit) => commit.Substring(0, Math.Min(10, commit.Length));

        private static string Verdict(bool met) => met ? "met" : "NOT met";
    }
}
