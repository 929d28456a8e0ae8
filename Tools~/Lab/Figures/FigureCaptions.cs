using System.Collections.Generic;
using System.IO;
using System.Text;
using System.Text.Json;

namespace HookeRope.Lab.Figures
{
    /// <summary>Writes the captions of written figures as Markdown (one section per image) and JSON (file, caption, size, numbers).</summary>
    public static class FigureCaptions
    {
        /// <summary>Markdown file name inside the output folder.</summary>
        public const string MarkdownFile = "figure-captions.md";
        /// <summary>JSON file name inside the output folder.</summary>
        public const string JsonFile = "figure-captions.json";

        /// <summary>Writes both files into <paramref name="outDir"/>.</summary>
        public static void Write(string outDir, IReadOnlyList<(DocumentationFigure Figure, FigureStats Stats)> figures)
        {
            var md = new StringBuilder();
            md.AppendLine("# Figures of the seed paper, redrawn by `lab figures paper`");
            md.AppendLine();
            var entries = new List<Dictionary<string, object>>();
            foreach (var (figure, stats) in figures)
            {
                string caption = (figure.Caption ?? "").Replace("\n", " ");
                md.AppendLine("## " + figure.FileName);
                md.AppendLine();
                md.AppendLine("![" + figure.FileName + "](" + figure.FileName + ")");
                md.AppendLine();
                md.AppendLine(caption);
                md.AppendLine();
                entries.Add(new Dictionary<string, object>
                {
                    ["file"] = figure.FileName,
                    ["caption"] = caption,
                    ["width"] = stats.Width,
                    ["height"] = stats.Height,
                    ["bytes"] = stats.Bytes,
                    ["numbers"] = figure.Numbers,
                });
            }
            File.WriteAllText(Path.Combine(outDir, MarkdownFile), md.ToString());
            File.WriteAllText(Path.Combine(outDir, JsonFile), JsonSerializer.Serialize(entries, new JsonSerializerOptions { WriteIndented = true }) + "\n");
        }
    }
}
