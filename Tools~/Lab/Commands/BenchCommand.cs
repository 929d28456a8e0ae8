using System.Globalization;
using HookeRope.Lab.Bench;
using HookeRope.Lab.Report;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary><c>bench</c>: Stopwatch micro-benchmarks (medians of 5 timed repeats after a warm-up).</summary>
    public static class BenchCommand
    {
        /// <summary>Runs and prints the benchmarks; returns 0.</summary>
        public static int Execute(IAnsiConsole console, bool quick)
        {
            var c = CultureInfo.InvariantCulture;
            console.MarkupLine("[bold]HookeRope lab · bench[/]  " + Markup.Escape(MachineInfo.Describe()));
            var sizes = MicroBench.Scaling(quick, null);
            var table = new Table().Border(TableBorder.Rounded).Title("scaling (hanging rope, 1 kg load)");
            table.AddColumn(new TableColumn("segments").RightAligned());
            table.AddColumn(new TableColumn("GS ns / projection").RightAligned());
            table.AddColumn(new TableColumn("exact ns / segment-iteration").RightAligned());
            table.AddColumn(new TableColumn("exact µs / step (4 sub)").RightAligned());
            table.AddColumn(new TableColumn("mesh ns / vertex").RightAligned());
            table.AddColumn(new TableColumn("bytes / step").RightAligned());
            foreach (var s in sizes)
                table.AddRow(s.Segments.ToString(c), s.NsPerProjection.ToString("F1", c), s.NsPerSegmentIteration.ToString("F1", c),
                    s.MicrosecondsPerStep.ToString("F1", c), s.NsPerVertex.ToString("F1", c), s.BytesPerStep.ToString("F0", c));
            console.Write(table);
            console.MarkupLine("fitted scaling exponent (exact chain, time per step ∝ segments^p): p = " +
                MicroBench.ScalingExponent(sizes).ToString("F2", c));
            var features = new Table().Border(TableBorder.Rounded).Title("optional features at 256 segments");
            features.AddColumn("feature");
            features.AddColumn(new TableColumn("µs / step").RightAligned());
            foreach (var f in MicroBench.Features(quick))
                features.AddRow(Markup.Escape(f.Name), f.MicrosecondsPerStep.ToString("F1", c));
            console.Write(features);
            console.MarkupLine("[grey]A feature that is off skips its work: compare the 'off' rows with the baseline (differences within timing noise).[/]");
            return 0;
        }
    }
}
