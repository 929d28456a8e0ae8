using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary><c>bench</c>: micro-benchmarks.</summary>
    public static class BenchCommand
    {
        /// <summary>Runs the benchmarks.</summary>
        public static int Execute(IAnsiConsole console, bool quick)
        {
            console.MarkupLine("[red]bench needs the solver[/]");
            return 5;
        }
    }
}
