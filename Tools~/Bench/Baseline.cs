using System.Collections.Generic;
using System.IO;
using System.Text.Json;

namespace HookeRope.Bench
{
    /// <summary>
    /// The stored numbers of the last release (Tools~/Bench/baseline.json, in the repository) and the comparison
    /// against them: a row is flagged when its instructions per unit (when both have them), else its processor time
    /// per frame (less sensitive to other processes than wall-clock), else its median ms per frame rose by more than
    /// <see cref="Tolerance"/>.
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

        /// <summary>"ok", "REGRESSION …" or "new" for <paramref name="row"/> against its stored row.</summary>
        public static string Compare(GoalRow row, Dictionary<string, GoalRow> stored)
        {
            if (!stored.TryGetValue(row.Id, out var before)) return "new";
            bool byInstructions = row.InstructionsPerUnit > 0 && before.InstructionsPerUnit > 0;
            bool byCpu = !byInstructions && row.CpuMsPerFrame > 0 && before.CpuMsPerFrame > 0;
            double now = byInstructions ? row.InstructionsPerUnit : byCpu ? row.CpuMsPerFrame : row.MsPerFrame;
            double then = byInstructions ? before.InstructionsPerUnit : byCpu ? before.CpuMsPerFrame : before.MsPerFrame;
            double change = now / then - 1.0;
            string what = (byInstructions ? "instr " : byCpu ? "cpu ms " : "ms ") + (change >= 0 ? "+" : "") + (change * 100).ToString("F1") + " %";
            return change > Tolerance ? "REGRESSION " + what : "ok " + what;
        }
    }
}
