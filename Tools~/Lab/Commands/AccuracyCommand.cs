using System.IO;
using HookeRope.Lab.Report;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary><c>accuracy [--out dir]</c>: the defaults' error against analytic answers at 1/90 s, 1/60 s and 0.02 s (Markdown).</summary>
    public static class AccuracyCommand
    {
        /// <summary>The fixed steps compared (s).</summary>
        public static readonly double[] Steps = { FixedStepAccuracy.ValidatedStep, 1.0 / 60.0, FixedStepAccuracy.UnityDefaultStep };

        /// <summary>Measures, prints and writes <c>accuracy.md</c> into <paramref name="outDir"/>; returns 0.</summary>
        public static int Execute(IAnsiConsole console, string outDir)
        {
            OutputFolder.Ensure(outDir);
            string md = FixedStepAccuracy.Markdown(Steps);
            string path = Path.Combine(outDir, "accuracy.md");
            File.WriteAllText(path, md);
            console.WriteLine(md);
            console.MarkupLine("wrote " + Markup.Escape(path));
            return 0;
        }
    }
}
