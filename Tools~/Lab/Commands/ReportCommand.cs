using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary><c>report</c>: error against run time.</summary>
    public static class ReportCommand
    {
        /// <summary>Runs the report.</summary>
        public static int Execute(IAnsiConsole console, string outDir, bool quick, int repeats)
        {
            console.MarkupLine("[red]report needs the solver[/]");
            return 5;
        }
    }
}
