using System;
using System.Globalization;

namespace HookeRope.Bench
{
    /// <summary>
    /// Instructions per tube vertex from callgrind (<see cref="InstructionCounter.Collected"/>): the <c>meshframes</c>
    /// workload for a short and a long run, so start-up, JIT and scene building cancel; in the moving mode the same
    /// two runs with the steps only are subtracted, so what is left is the fills' own instructions.
    /// </summary>
    internal static class MeshInstructions
    {
        private const int ShortFills = 20, LongFills = 220;

        /// <summary>Instructions per vertex written, or 0 when valgrind is missing or a run failed.</summary>
        public static double PerVertex(MeshBench.Scene scene, int sides, MeshBench.Layout layout, MeshBench.Mode mode, int vertices, Action<string> log)
        {
            double fills = Difference(scene, sides, layout, mode, false, log);
            if (fills <= 0) return 0;
            if (mode == MeshBench.Mode.Moving)
            {
                double steps = Difference(scene, sides, layout, mode, true, log);
                if (steps <= 0) return 0;
                fills -= steps;
            }
            return fills / ((double)(LongFills - ShortFills) * vertices);
        }

        private static double Difference(MeshBench.Scene scene, int sides, MeshBench.Layout layout, MeshBench.Mode mode, bool stepOnly, Action<string> log)
        {
            long a = InstructionCounter.Collected(Arguments(scene, sides, layout, mode, ShortFills, stepOnly), log);
            long b = InstructionCounter.Collected(Arguments(scene, sides, layout, mode, LongFills, stepOnly), log);
            return a > 0 && b > a ? b - a : 0;
        }

        private static string[] Arguments(MeshBench.Scene scene, int sides, MeshBench.Layout layout, MeshBench.Mode mode, int fills, bool stepOnly)
        {
            var c = CultureInfo.InvariantCulture;
            return stepOnly
                ? new[] { "meshframes", scene.ToString(), sides.ToString(c), layout.ToString(), mode.ToString(), fills.ToString(c), "stepOnly" }
                : new[] { "meshframes", scene.ToString(), sides.ToString(c), layout.ToString(), mode.ToString(), fills.ToString(c) };
        }
    }
}
