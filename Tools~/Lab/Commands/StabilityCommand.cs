using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary><c>stability</c>: extreme-case sweep.</summary>
    public static class StabilityCommand
    {
        /// <summary>Runs the sweep.</summary>
        public static int Execute(IAnsiConsole console, string outDir, bool quick)
        {
            console.MarkupLine("[red]stability needs the solver[/]");
            return 5;
        }
    }
}
