using System.Collections.Generic;
using System.IO;
using System.Text.Json;

namespace HookeRope.Bench
{
    /// <summary>
    /// The stored numbers of the last release (Tools~/Bench/baseline.json, in the repository) and the comparison
    /// against them, like for like (<see cref="Compare"/>): a row of the same frame window is flagged when its
    /// instructions per unit (one worker, both counted the same way), else its processor time per frame (less
    /// sensitive to other processes than wall-clock) rose by more than <see cref="Tolerance"/>.
    /// </summary>
    internal static class Baseline
    {
        /// <summary>Relative rise that counts as a regression (10 %).</summary>
        public const double Tolerance = 0.10;

        /// <summary>Path of the baseline file next to this project's sources.</summary>
        public static string PathInRepository(string packageRoot) => Path.Combine(packageRoot, "Tools~", "Bench", "baseline.json");

        /// <summary>Rows of the stored file by id (empty when there is none).</summary>
        public static Dictionary<string, GoalRow> Load(string path)
        {
            var rows = new Dictionary<string, GoalRow>();
            if (!File.Exists(path)) return rows;
            foreach (var row in JsonSerializer.Deserialize<List<GoalRow>>(File.ReadAllText(path))) rows[row.Id] = row;
            return rows;
        }

        /// <summary>Writes <paramref name="rows"/> as the new baseline.</summary>
        public static void Save(string path, List<GoalRow> rows) =>
            File.WriteAllText(path, JsonSerializer.Serialize(rows, new JsonSerializerOptions { WriteIndented = true }) + "\n");

        /// <summary>
        /// "ok …", "REGRESSION …", "new" or "not compared …" for <paramref name="row"/> against its stored row. Only
        /// like-for-like figures compare: rows of the same frame window (<see cref="GoalRow.Window"/>), then on one
        /// worker instructions per unit when both have a count of the same source (<see cref="GoalRow.InstructionSource"/>:
        /// method, ISA, window), else CPU ms per frame (on two workers always CPU: the count is one worker's and does not
        /// see the hand-off).
        /// </summary>
        public static string Compare(GoalRow row, Dictionary<string, GoalRow> stored)
        {
            if (!stored.TryGetValue(row.Id, out var before)) return "new";
            if (before.Window != row.Window) return "not compared: baseline window " + (before.Window ?? "unrecorded") + " (re-save it)";
            bool byInstructions = row.Workers == 1 && row.InstructionsPerUnit > 0 && before.InstructionsPerUnit > 0 && row.InstructionSource == before.InstructionSource;
            if (!byInstructions && !(row.CpuMsPerFrame > 0 && before.CpuMsPerFrame > 0)) return "not compared: no CPU time";
            double now = byInstructions ? row.InstructionsPerUnit : row.CpuMsPerFrame;
            double then = byInstructions ? before.InstructionsPerUnit : before.CpuMsPerFrame;
            double change = now / then - 1.0;
            string what = (byInstructions ? "instr " : "cpu ms ") + (change >= 0 ? "+" : "") + (change * 100).ToString("F1", System.Globalization.CultureInfo.InvariantCulture) + " %";
            return change > Tolerance ? "REGRESSION " + what : "ok " + what;
        }
    }
}
