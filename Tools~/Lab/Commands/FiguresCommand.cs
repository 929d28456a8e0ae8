using System.Collections.Generic;
using System.Globalization;
using System.IO;
using HookeRope.Lab.Figures;
using HookeRope.Lab.Figures.Diagnostics;
using HookeRope.Lab.Figures.Paper;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary>
    /// <c>figures [harness|paper|folds|all] [--out dir]</c>: renders figures from the core's tube mesh of real simulations
    /// (Documentation~/images is where the committed copies live) and prints size, rope coverage and the quoted numbers.
    /// "harness": the manual's harness-rig diagrams; "paper": the seed paper's Figs. 5, 6, 7, 8 and 9a, their captions
    /// (<see cref="FigureCaptions.MarkdownFile"/>, <see cref="FigureCaptions.JsonFile"/>) and the package's burr texture;
    /// "folds": the diagnostic picture of slack folds after a break (<see cref="SlackFoldFigure"/>); "all": every set.
    /// </summary>
    public static class FiguresCommand
    {
        /// <summary>Set name of the harness-rig figures (the default).</summary>
        public const string Harness = "harness";
        /// <summary>Set name of the paper's figures.</summary>
        public const string Paper = "paper";
        /// <summary>Set name of the diagnostic slack-fold figure.</summary>
        public const string Folds = "folds";
        /// <summary>Every set.</summary>
        public const string All = "all";

        /// <summary>Writes the figures of <paramref name="set"/> into <paramref name="outDir"/>; returns 0.</summary>
        public static int Execute(IAnsiConsole console, string outDir, string set = Harness)
        {
            OutputFolder.Ensure(outDir);
            var table = new Table().Border(TableBorder.Rounded);
            table.AddColumn("file");
            table.AddColumn("size");
            table.AddColumn(new TableColumn("KB").RightAligned());
            table.AddColumn(new TableColumn("rope coverage").RightAligned());
            table.AddColumn("numbers quoted");
            var figures = new List<DocumentationFigure>();
            if (set == Harness || set == All) figures.AddRange(HarnessRigFigures.All());
            int paperStart = figures.Count;
            if (set == Paper || set == All) figures.AddRange(PaperFigures.All());
            int paperEnd = figures.Count;
            if (set == Folds || set == All) figures.Add(SlackFoldFigure.Build());
            var written = new List<(DocumentationFigure, FigureStats)>();
            foreach (var figure in figures)
            {
                var stats = FigureWriter.Write(figure, Path.Combine(outDir, figure.FileName));
                written.Add((figure, stats));
                table.AddRow(
                    Markup.Escape(figure.FileName),
                    stats.Width + "×" + stats.Height,
                    (stats.Bytes / 1024.0).ToString("F1", CultureInfo.InvariantCulture),
                    stats.ProjectedRopeArea > 0 ? stats.Coverage.ToString("P1", CultureInfo.InvariantCulture) : "–",
                    Markup.Escape(Numbers(figure.Numbers)));
            }
            console.Write(table);
            console.MarkupLine(Markup.Escape("rope coverage = rope pixels visible / projected area of the rope mesh's front faces (occlusion and self-overlap lower it)"));
            if (set == Paper || set == All)
            {
                var paper = written.GetRange(paperStart, paperEnd - paperStart);
                FigureCaptions.Write(outDir, paper);
                var texture = BurrTexturePng.Write(Path.Combine(outDir, BurrTexturePng.FileName));
                console.MarkupLine(Markup.Escape("captions: " + FigureCaptions.MarkdownFile + ", " + FigureCaptions.JsonFile + "; burr texture: " + BurrTexturePng.FileName +
                    " (" + FigureTexture.BurrWidth + "×" + FigureTexture.BurrHeight + ", " + (texture / 1024.0).ToString("F1", CultureInfo.InvariantCulture) + " KB)"));
            }
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
