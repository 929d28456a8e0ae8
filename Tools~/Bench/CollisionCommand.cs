using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.Linq;
using HookeRope.Solver;

namespace HookeRope.Bench
{
    /// <summary>
    /// <c>collisions [--quick] [--instructions]</c>: the cost of colliders per host step on the <see cref="CollisionScene"/>
    /// cases, with the broad phase and with the brute-force pass it replaced (every particle against every collider), as
    /// µs per step (medians of rounds that visit every rope in turn) and, with <c>--instructions</c>, callgrind instructions
    /// per step (the load-independent figure, by the recipe in solver.md), each with its overhead over the same rope without
    /// colliders. <c>collide CASE N [W] [brute]</c> builds a case, steps it W + N times and exits (what callgrind runs).
    /// </summary>
    internal static class CollisionCommand
    {
        private const int ShortSteps = 20, LongSteps = 120;

        /// <summary>Runs the command; returns 0.</summary>
        public static int Execute(string[] args)
        {
            bool quick = args.Contains("--quick"), instructions = args.Contains("--instructions");
            var c = CultureInfo.InvariantCulture;
            Console.WriteLine($"HookeRope bench · collisions  {CollisionScene.Segments} segments, {LegacySettings.Substeps} substeps x 1 iteration, exact chain, " +
                              $"load average {GoalBench.LoadAverage().ToString("F2", c)}, {System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription}");
            if (instructions) Console.WriteLine("instructions: callgrind, tiered compilation off (the recipe in solver.md), (Ir(120 steps) - Ir(20 steps)) / 100");
            string[] cases = CollisionScene.Cases;
            var ropes = new List<Rope>();
            var near = new List<int>();
            foreach (string name in cases)
            {
                ropes.Add(CollisionScene.Build(name, false));
                ropes.Add(CollisionScene.Build(name, true));
                near.Add(NearParticles(ropes[ropes.Count - 1]));
            }
            double[] micro = Time(ropes, quick ? 3 : 9, quick ? 50 : 200);
            var counts = new double[ropes.Count];
            if (instructions)
                for (int k = 0; k < ropes.Count; k++)
                    counts[k] = k % 2 == 1 && cases[k / 2] == "none" ? counts[k - 1] : InstructionsPerStep(cases[k / 2], k % 2 == 1);
            string header = string.Format(c, "{0,-11} {1,-6} {2,5} {3,9} {4,10} {5,14} {6,10}  {7}", "case", "path", "near", "µs/step", "overhead", "instr/step", "overhead", "what");
            Console.WriteLine(header);
            Console.WriteLine(new string('-', header.Length + 40));
            int none = Array.IndexOf(cases, "none") * 2;
            for (int k = 0; k < ropes.Count; k++)
            {
                string name = cases[k / 2];
                bool brute = k % 2 == 1;
                if (name == "none" && brute) continue;
                // the draped rope against the same rope without its bar (bar-bare); the rest against the hanging rope without colliders
                int reference = name == "bar" ? Array.IndexOf(cases, "bar-bare") * 2 : none;
                bool isReference = name == "none" || name == "bar-bare";
                if (name == "bar-bare" && brute) continue;
                Console.WriteLine(string.Format(c, "{0,-11} {1,-6} {2,5} {3,9:F1} {4,10} {5,14} {6,10}  {7}", name, isReference ? "" : brute ? "brute" : "broad",
                    near[k / 2], micro[k], isReference ? "" : Percent(micro[k], micro[reference]),
                    instructions ? counts[k].ToString("N0", c) : "-", !instructions || isReference ? "" : Percent(counts[k], counts[reference]),
                    brute ? "" : CollisionScene.Describe(name)));
            }
            Console.WriteLine("near = particles within radius + contact margin of a collider after the warm-up; broad = the broad phase, brute = every particle against every collider;");
            Console.WriteLine("overhead against 'none' (bar: against 'bar-bare'). Wall-clock figures are medians on whatever load the machine has; compare instruction counts for ratios.");
            return 0;
        }

        /// <summary>Builds case args[1], steps it args[3] (default 0) + args[2] times and exits; "brute" as args[4] uses the brute-force pass.</summary>
        public static int Collide(string[] args)
        {
            var rope = CollisionScene.Build(args[1], args.Length > 4 && args[4] == "brute");
            int steps = int.Parse(args[2], CultureInfo.InvariantCulture) + (args.Length > 3 ? int.Parse(args[3], CultureInfo.InvariantCulture) : 0);
            for (int i = 0; i < steps; i++) rope.Step(CollisionScene.Step);
            return 0;
        }

        private static string Percent(double value, double reference) =>
            reference > 0 && value > 0 ? ((value / reference - 1.0) * 100.0).ToString("+0.00;-0.00", CultureInfo.InvariantCulture) + " %" : "-";

        /// <summary>Instructions per host step: (Ir(long) − Ir(short)) / (long − short) under callgrind, or 0 when it did not run.</summary>
        private static double InstructionsPerStep(string name, bool brute)
        {
            var c = CultureInfo.InvariantCulture;
            string path = brute ? "brute" : "broad";
            long a = InstructionCounter.Collected(new[] { "collide", name, ShortSteps.ToString(c), "0", path }, m => Console.Error.WriteLine(m));
            long b = InstructionCounter.Collected(new[] { "collide", name, LongSteps.ToString(c), "0", path }, m => Console.Error.WriteLine(m));
            return a > 0 && b > a ? (b - a) / (double)(LongSteps - ShortSteps) : 0;
        }

        /// <summary>Median µs per step of each rope, rounds visiting every rope in turn so a slow spell hits all alike.</summary>
        private static double[] Time(List<Rope> ropes, int rounds, int steps)
        {
            var samples = new List<double>[ropes.Count];
            for (int k = 0; k < ropes.Count; k++)
            {
                samples[k] = new List<double>();
                var warm = Stopwatch.StartNew();
                while (warm.ElapsedMilliseconds < 250) ropes[k].Step(CollisionScene.Step);
            }
            for (int r = 0; r < rounds; r++)
                for (int k = 0; k < ropes.Count; k++)
                {
                    var watch = Stopwatch.StartNew();
                    for (int i = 0; i < steps; i++) ropes[k].Step(CollisionScene.Step);
                    samples[k].Add(watch.Elapsed.TotalMilliseconds * 1e3 / steps);
                }
            return samples.Select(s => { var o = s.OrderBy(v => v).ToList(); return o[o.Count / 2]; }).ToArray();
        }

        /// <summary>Particles within their radius plus the contact margin of some collider.</summary>
        private static int NearParticles(Rope rope)
        {
            int near = 0;
            for (int i = 0; i < rope.ParticleCount; i++)
            {
                float reach = rope.ParticleRadius[i] * (1f + CollisionSet.ContactMarginFraction);
                for (int k = 0; k < rope.ColliderCount; k++)
                    if (rope.ColliderDistance(k, rope.GetPosition(i)) <= reach) { near++; break; }
            }
            return near;
        }
    }
}
