using System;
using System.IO;
using System.Runtime.InteropServices;

namespace HookeRope.Lab.Report
{
    /// <summary>One line describing the machine timings were taken on.</summary>
    public static class MachineInfo
    {
        /// <summary>CPU model, logical cores, OS, runtime.</summary>
        public static string Describe()
        {
            return $"{Cpu()} · {Environment.ProcessorCount} logical cores · {RuntimeInformation.OSDescription} " +
                   $"{RuntimeInformation.OSArchitecture} · {RuntimeInformation.FrameworkDescription}" +
#if DEBUG
                   " · DEBUG build (timings not representative)";
#else
                   " · Release build";
#endif
        }

        /// <summary>The load average over 1, 5 and 15 minutes ("1.23, 0.75, 0.38", from /proc/loadavg), or "n/a": how busy the shared machine was while timing.</summary>
        public static string LoadAverage()
        {
            try
            {
                if (File.Exists("/proc/loadavg"))
                {
                    var parts = File.ReadAllText("/proc/loadavg").Split(' ');
                    if (parts.Length >= 3) return parts[0] + ", " + parts[1] + ", " + parts[2];
                }
            }
            catch (IOException)
            {
            }
            catch (UnauthorizedAccessException)
            {
            }
            return "n/a";
        }

        static string Cpu()
        {
            try
            {
                if (File.Exists("/proc/cpuinfo"))
                    foreach (var line in File.ReadLines("/proc/cpuinfo"))
                        if (line.StartsWith("model name", StringComparison.Ordinal))
                            return line.Substring(line.IndexOf(':') + 1).Trim();
            }
            catch (IOException)
            {
            }
            return RuntimeInformation.ProcessArchitecture.ToString();
        }
    }
}
