using System.Collections.Generic;
using System.Globalization;
using System.IO;
using HookeRope.Lab.Output;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Simulation;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary><c>run [scenario|file.json]</c>: CSV, force plot, radius plot, optional glTF, summary.</summary>
    public static class RunCommand
    {
        /// <summary>Exit code of a diverged run (NaN, a particle flung away, energy created, strain errors beyond the rope's length).</summary>
        public const int Diverged = 3;
        /// <summary>Exit code of <c>run --check</c> when the run is unconverged or a physics check failed.</summary>
        public const int CheckFailed = 4;

        /// <summary>What <c>run</c> prints.</summary>
        public enum Mode
        {
            /// <summary>The one-screen summary table.</summary>
            Summary,
            /// <summary>Only the verdict line (and what to change).</summary>
            Quiet,
            /// <summary>Only the JSON summary.</summary>
            Json,
        }

        /// <summary>Runs the scenario and writes its outputs to <paramref name="outDir"/>; returns the exit code. <paramref name="progress"/> gets periodic lines with an ETA when the console is not interactive (null: none).</summary>
        public static int Execute(IAnsiConsole console, string scenario, string outDir, bool svg, bool gltf, bool strict,
            Mode mode = Mode.Summary, TextWriter progress = null)
        {
            var spec = BuiltInScenarios.Resolve(scenario);
            OutputFolder.Ensure(outDir);
            RunResult result = null;
            var options = new RunOptions();
            if (mode == Mode.Summary && console.Profile.Capabilities.Interactive && spec.StepCount > 2000)
            {
                console.Progress().Start(ctx =>
                {
                    var task = ctx.AddTask(spec.Name, maxValue: spec.StepCount);
                    options.Progress = k => { if ((k & 63) == 0) task.Value = k; };
                    result = ScenarioRunner.Run(spec, options);
                    task.Value = spec.StepCount;
                });
            }
            else
            {
                if (progress != null)
                {
                    var lines = new ProgressLines(spec.Name + " (simulated time)", spec.StepCount, progress);
                    options.Progress = k => { if ((k & 63) == 0) lines.Report(k); };
                }
                result = ScenarioRunner.Run(spec, options);
            }
            var files = new List<string>();
            string stem = Path.Combine(outDir, spec.Name);
            CsvWriter.Write(result, stem + ".csv");
            files.Add(stem + ".csv");
            var checks = PhysicsChecks.Evaluate(result);
            var verdict = ConvergenceVerdict.Judge(result);
            files.AddRange(Plots.WriteAll(result, verdict, checks, stem, svg));
            if (result.Profiles.Count + result.KeyProfiles.Count > 0)
            {
                CsvWriter.WriteRadiusProfiles(result, stem + "-radius.csv");
                files.Add(stem + "-radius.csv");
            }
            if (gltf)
            {
                foreach (var mesh in result.Meshes)
                {
                    string path = stem + "-t" + mesh.Time.ToString("F3", CultureInfo.InvariantCulture) + ".glb";
                    GltfExport.Write(mesh, spec.Name, path);
                    files.Add(path);
                }
                if (result.Meshes.Count == 0)
                    console.MarkupLine("[yellow]no mesh captured: set outputs.gltfTimes in the scenario (or the mesh builder is not available)[/]");
            }
            string summaryPath = stem + "-summary.json";
            files.Add(summaryPath);
            string summary = JsonSummary.Text(result, verdict, checks, files);
            File.WriteAllText(summaryPath, summary);
            switch (mode)
            {
                case Mode.Json:
                    console.Profile.Out.Writer.WriteLine(summary);
                    break;
                case Mode.Quiet:
                    console.MarkupLine(SummaryView.VerdictLine(verdict));
                    if (!verdict.Converged) console.MarkupLine("[bold]what to change:[/] " + Markup.Escape(verdict.Advice));
                    break;
                default:
                    SummaryView.Print(console, result, verdict, checks, files);
                    break;
            }
            return ExitCode(verdict, checks, strict);
        }

        /// <summary>Exit code of a run: 3 diverged (NaN included); with <paramref name="strict"/>, 4 when unconverged or a physics check failed; else 0.</summary>
        public static int ExitCode(ConvergenceVerdict verdict, IList<CheckResult> checks, bool strict)
        {
            if (verdict.Kind == Convergence.Diverged) return Diverged;
            if (!strict) return 0;
            if (verdict.Kind == Convergence.Unconverged) return CheckFailed;
            foreach (var check in checks)
                if (!check.Passed) return CheckFailed;
            return 0;
        }
    }
}
