using System;
using System.Diagnostics;
using System.Globalization;
using System.Text.RegularExpressions;

namespace HookeRope.Bench
{
    /// <summary>
    /// Instruction counts from callgrind of this (JIT-compiled) tool, for the mesh and collision commands: runs one of
    /// its modes under <c>valgrind --tool=callgrind</c> (tiered compilation off) and returns the instructions collected
    /// (all threads); callers count a short and a long run and divide the difference by the difference in work, so
    /// start-up, JIT and scene building cancel out. The goal table's counts come from the native probe instead
    /// (Tools~/Kernels/goal-count.sh, <see cref="GoalCounts"/>).
    /// </summary>
    internal static class InstructionCounter
    {
        /// <summary>
        /// Instructions callgrind collected (all threads) while this tool ran with <paramref name="toolArguments"/>
        /// (tiered compilation off), or −1 when valgrind is missing or fails.
        /// </summary>
        public static long Collected(string[] toolArguments, Action<string> log)
        {
            string dll = typeof(Program).Assembly.Location;
            var info = new ProcessStartInfo("valgrind")
            {
                RedirectStandardError = true,
                RedirectStandardOutput = true,
                UseShellExecute = false,
            };
            foreach (string arg in new[] { "--tool=callgrind", "--callgrind-out-file=/dev/null", "dotnet", dll })
                info.ArgumentList.Add(arg);
            foreach (string arg in toolArguments) info.ArgumentList.Add(arg);
            info.Environment["DOTNET_TieredCompilation"] = "0";
            try
            {
                using (var process = Process.Start(info))
                {
                    process.StandardOutput.ReadToEndAsync();
                    string errors = process.StandardError.ReadToEnd();
                    process.WaitForExit();
                    Match m = Regex.Match(errors, @"Collected\s*:\s*(\d+)");
                    long collected = m.Success ? long.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture) : -1;
                    log?.Invoke("callgrind " + string.Join(" ", toolArguments) + ": " + collected + " instructions");
                    return collected;
                }
            }
            catch (Exception e)
            {
                log?.Invoke("callgrind not run: " + e.Message);
                return -1;
            }
        }
    }
}
