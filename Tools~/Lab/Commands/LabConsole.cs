using System.IO;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary>Creates Spectre consoles: the real terminal, or a plain writer for tests and redirected output.</summary>
    public static class LabConsole
    {
        /// <summary>Columns of a console whose output is redirected (a file or a pipe): tables are laid out full width instead of wrapping at 80.</summary>
        public const int RedirectedWidth = 200;

        /// <summary>The process console; when <paramref name="redirected"/>, at least <see cref="RedirectedWidth"/> columns wide.</summary>
        public static IAnsiConsole ForProcess(IAnsiConsole console, bool redirected)
        {
            if (redirected && console.Profile.Width < RedirectedWidth) console.Profile.Width = RedirectedWidth;
            return console;
        }

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
