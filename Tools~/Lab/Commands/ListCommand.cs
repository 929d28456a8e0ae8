using HookeRope.Lab.Scenarios;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary><c>list</c>: the built-in scenarios and what they check.</summary>
    public static class ListCommand
    {
        /// <summary>Prints the table; returns 0.</summary>
        public static int Execute(IAnsiConsole console)
        {
            var table = new Table().Border(TableBorder.Rounded);
            table.AddColumn("scenario");
            table.AddColumn("check");
            table.AddColumn("description");
            foreach (var s in BuiltInScenarios.All())
                table.AddRow(Markup.Escape(s.Name), Markup.Escape(s.Expect.Check), Markup.Escape(s.Description));
            console.Write(table);
            return 0;
        }
    }
}
