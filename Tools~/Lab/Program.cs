using System;
using HookeRope.Lab.Commands;
using Spectre.Console;

namespace HookeRope.Lab
{
    /// <summary>Entry point of the lab: <c>dotnet run -c Release --project "Tools~/Lab" -- run</c>.</summary>
    public static class Program
    {
        /// <summary>Parses the command line and runs the chosen command; returns the process exit code.</summary>
        public static int Main(string[] args)
        {
            return LabCli.Invoke(args, LabConsole.ForProcess(AnsiConsole.Console, Console.IsOutputRedirected), Console.Out, Console.Error);
        }
    }
}
