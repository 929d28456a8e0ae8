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
