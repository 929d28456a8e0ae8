using System.IO;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary>Creates Spectre consoles: the real terminal, or a plain writer for tests and redirected output.</summary>
    public static class LabConsole
    {
        /// <summary>A console writing plain text (no colours, no live widgets) to <paramref name="writer"/>.</summary>
        public static IAnsiConsole Plain(TextWriter writer)
        {
            var console = AnsiConsole.Create(new AnsiConsoleSettings
            {
                Ansi = AnsiSupport.No,
                ColorSystem = ColorSystemSupport.NoColors,
                Interactive = InteractionSupport.No,
                Out = new AnsiConsoleOutput(writer),
            });
            console.Profile.Width = 140;
            return console;
        }
    }
}
