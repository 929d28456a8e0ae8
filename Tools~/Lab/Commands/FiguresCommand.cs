using System.Collections.Generic;
using System.Globalization;
using System.IO;
using HookeRope.Lab.Figures;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary>
    /// <c>figures [--out dir]</c>: renders the manual's harness-rig figures from the core's tube mesh of real simulations
    /// (Documentation~/images is where the committed copies live) and prints size, rope coverage and the quoted numbers.
    /// </summary>
    public static class FiguresCommand
    {
        /// <summary>Writes every figure into <paramref name="outDir"/>; returns 0.</summary>
        public static int Execute(IAnsiConsole console, string outDir)
        {
            Directory.CreateDirectory(outDir);
            var table = new Table().Border(TableBorder.Rounded);
            table.AddColumn("file");
            table.AddColumn("size");
            table.AddColumn(new TableColumn("KB").RightAligned());
            table.AddColumn(new TableColumn("rope coverage").RightAligned());
            table.AddColumn("numbers quoted");
            foreach (var figure in HarnessRigFigures.All())
            {
                var stats = FigureWriter.Write(figure, Path.Combine(outDir, figure.FileName));
                table.AddRow(
                    Markup.Escape(figure.FileName),
                    stats.Width + "×" + stats.Height,
                    (stats.Bytes / 1024.0).ToString("F1", CultureInfo.InvariantCulture),
                    stats.Coverage.ToString("P1", CultureInfo.InvariantCulture),
                    Markup.Escape(Numbers(figure.Numbers)));
            }
            console.Write(table);
            console.MarkupLine(Markup.Escape("rope coverage = rope pixels visible / projected area of the rope mesh's front faces (occlusion and self-overlap lower it)"));
            return 0;
        }

        static string Numbers(Dictionary<string, double> numbers)
        {
            var parts = new List<string>();
            foreach (var pair in numbers) parts.Add(pair.Key + " " + pair.Value.ToString("G4", CultureInfo.InvariantCulture));
            return string.Join("; ", parts);
        }
    }
}
