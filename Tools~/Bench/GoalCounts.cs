using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;

namespace HookeRope.Bench
{
    /// <summary>
    /// The instruction count of the goal frame that Tools~/Kernels/goal-count.sh recorded (callgrind, native code, one
    /// worker, the bench's window): instructions per frame, per segment-substep (step + mesh, and the step alone) and
    /// per tube vertex. <c>bench goal</c> shows it on the rows of the counted configuration when it was counted of the
    /// code being measured (the same Runtime/Core, probe and scene, committed and uncommitted), and compares it with the
    /// baseline's.
    /// </summary>
    internal sealed class GoalCounts
    {
        private readonly Dictionary<string, string> values;

        private GoalCounts(Dictionary<string, string> values) => this.values = values;

        /// <summary>Lanyards of the counted world.</summary>
        public int Ropes => int.Parse(values["ropes"], CultureInfo.InvariantCulture);

        /// <summary>Segments per lanyard.</summary>
        public int Segments => int.Parse(values["segments"], CultureInfo.InvariantCulture);

        /// <summary>Frames counted, e.g. "45-74".</summary>
        public string Window => values["window"];

        /// <summary>What was counted: "aot ISA WINDOW" (a baseline's counts compare only with the same).</summary>
        public string Source => "aot " + values["isa"] + " " + Window;

        /// <summary>Commit the count was made at (10 digits; the count holds while the code it depends on is unchanged).</summary>
        public string Commit => values["commit"].Substring(0, Math.Min(10, values["commit"].Length));

        /// <summary>True when the count was made of code with hashes <paramref name="code"/> and <paramref name="changes"/> (<see cref="TreeOf"/>).</summary>
        public bool CountedAt(string code, string changes) => values["code"] == code && values["changes"] == changes;

        /// <summary>Number <paramref name="key"/> of the file.</summary>
        public double this[string key] => double.Parse(values[key], CultureInfo.InvariantCulture);

        /// <summary>The default file: $KERNELS_OUT/goal-count.txt, else count.sh's default directory.</summary>
        public static string DefaultPath()
        {
            string dir = Environment.GetEnvironmentVariable("KERNELS_OUT");
            if (string.IsNullOrEmpty(dir)) dir = "/tmp/hookerope-kernels-" + UserId();
            return Path.Combine(dir, "goal-count.txt");
        }

        /// <summary>The counts in <paramref name="path"/>, or null when the file is missing or incomplete.</summary>
        public static GoalCounts Load(string path)
        {
            var values = ReadCountFile(path, "ropes", "segments", "window", "instructions_per_frame",
                "instructions_per_unit", "step_instructions_per_unit", "mesh_instructions_per_vertex");
            return values == null ? null : new GoalCounts(values);
        }

        /// <summary>
        /// The key=value lines of a count file the Kernels scripts write (goal-count.sh, kernel-count.sh), or null when the
        /// file is missing or lacks the provenance keys (commit, code, changes, isa) or any of <paramref name="keys"/>.
        /// </summary>
        public static Dictionary<string, string> ReadCountFile(string path, params string[] keys)
        {
            if (!File.Exists(path)) return null;
            var values = new Dictionary<string, string>();
            foreach (string line in File.ReadAllLines(path))
            {
                int eq = line.IndexOf('=');
                if (eq > 0) values[line.Substring(0, eq)] = line.Substring(eq + 1).Trim();
            }
            foreach (string key in new[] { "commit", "code", "changes", "isa" })
                if (!values.ContainsKey(key)) return null;
            foreach (string key in keys)
                if (!values.ContainsKey(key)) return null;
            return values;
        }

        /// <summary>Writes the counts onto <paramref name="row"/> when it is the counted configuration (any worker count).</summary>
        public void ApplyTo(GoalRow row)
        {
            // the probe counts the goal scene, whose meshes draw at ring tolerance 1 whatever their distance
            if (row.Ropes != Ropes || row.Segments != Segments || row.Window != Window || row.RingTolerance != 1f || row.DetailDistance != 0f || !row.Tangents) return;
            row.InstructionsPerUnit = this["instructions_per_unit"];
            row.InstructionsPerFrame = this["instructions_per_frame"];
            row.StepInstructionsPerUnit = this["step_instructions_per_unit"];
            row.MeshInstructionsPerVertex = this["mesh_instructions_per_vertex"];
            row.InstructionSource = Source;
        }

        /// <summary>The code a count depends on (goal-count.sh hashes the same paths the same way).</summary>
        private static readonly string CountedPaths = "Runtime/Core Tools~/Kernels Tools~/Bench/GoalScene.cs";

        /// <summary>
        /// The hashes goal-count.sh records for the code in <paramref name="root"/>: of the committed trees of
        /// <see cref="CountedPaths"/> (<c>git rev-parse HEAD:path …</c>) and of their uncommitted changes
        /// (<c>git diff HEAD -- paths</c>), 12 hex digits of SHA-1 each; nulls when git is not available.
        /// </summary>
        public static (string Code, string Changes) TreeOf(string root)
        {
            string trees = Git(root, "rev-parse HEAD:" + CountedPaths.Replace(" ", " HEAD:"));
            string diff = Git(root, "diff HEAD -- " + CountedPaths);
            return trees == null || diff == null ? (null, null) : (Sha1(trees), Sha1(diff));
        }

        private static string Sha1(string text)
        {
            using (var sha = System.Security.Cryptography.SHA1.Create())
            {
                byte[] hash = sha.ComputeHash(System.Text.Encoding.UTF8.GetBytes(text));
                return BitConverter.ToString(hash).Replace("-", "").ToLowerInvariant().Substring(0, 12);
            }
        }

        private static string Git(string root, string arguments)
        {
            try
            {
                var info = new ProcessStartInfo("git", "-C \"" + root + "\" " + arguments)
                {
                    RedirectStandardOutput = true,
                    RedirectStandardError = true,
                    UseShellExecute = false,
                };
                using (var process = Process.Start(info))
                {
                    process.StandardError.ReadToEndAsync();
                    string text = process.StandardOutput.ReadToEnd();
                    process.WaitForExit();
                    return process.ExitCode == 0 ? text : null;
                }
            }
            catch (Exception)
            {
                return null;
            }
        }

        /// <summary>The user id (as count.sh's default directory names it), from /proc/self/status.</summary>
        private static string UserId()
        {
            try
            {
                foreach (string line in File.ReadAllLines("/proc/self/status"))
                    if (line.StartsWith("Uid:", StringComparison.Ordinal))
                        return line.Substring(4).Trim().Split('\t', ' ')[0];
            }
            catch (Exception)
            {
                // no /proc: fall through
            }
            return "0";
        }
    }
}
