using System;
using System.CommandLine;
using System.IO;
using HookeRope.Lab.Scenarios;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary>The lab's command line (System.CommandLine): run, list, report, stability, bench.</summary>
    public static class LabCli
    {
        /// <summary>Exit code for an invalid scenario or argument.</summary>
        public const int InvalidInput = 2;

        /// <summary>Builds the command tree writing through <paramref name="console"/> (errors to <paramref name="error"/>).</summary>
        public static RootCommand Build(IAnsiConsole console, TextWriter error)
        {
            var root = new RootCommand(
                "HookeRope headless rope lab: runs rope scenarios with the engine-free core and writes CSV, plots and reports.");

            var scenario = new Argument<string>("scenario")
            {
                Description = "Built-in scenario name or path to a scenario JSON file (default: fall-arrest). See `list`.",
                Arity = ArgumentArity.ZeroOrOne,
                DefaultValueFactory = _ => BuiltInScenarios.Default,
            };
            var runOut = OutOption();
            var svg = new Option<bool>("--svg") { Description = "Also write the plots as SVG." };
            var gltf = new Option<bool>("--gltf") { Description = "Export the tube mesh at outputs.gltfTimes as .glb." };
            var strict = new Option<bool>("--check") { Description = "Exit non-zero when a physics check of the scenario fails." };
            var run = new Command("run", "Run a scenario: CSV time series, force and radius plots, one-screen summary.")
            {
                scenario, runOut, svg, gltf, strict,
            };
            run.SetAction(p => Guard(console, error, () =>
                RunCommand.Execute(console, p.GetValue(scenario), p.GetValue(runOut), p.GetValue(svg), p.GetValue(gltf), p.GetValue(strict))));
            root.Subcommands.Add(run);

            var list = new Command("list", "List the built-in scenarios.");
            list.SetAction(p => Guard(console, error, () => ListCommand.Execute(console)));
            root.Subcommands.Add(list);

            var reportOut = OutOption();
            var reportQuick = new Option<bool>("--quick") { Description = "Reduced grid and one repeat (a smoke run, not for numbers)." };
            var repeats = new Option<int>("--repeats") { Description = "Timed repeats per configuration (median is reported).", DefaultValueFactory = _ => 5 };
            var report = new Command("report", "Error against run time for reference scenarios and solver configurations: Markdown + Pareto plot.")
            {
                reportOut, reportQuick, repeats,
            };
            report.SetAction(p => Guard(console, error, () =>
                ReportCommand.Execute(console, p.GetValue(reportOut), p.GetValue(reportQuick), p.GetValue(repeats))));
            root.Subcommands.Add(report);

            var stabilityOut = OutOption();
            var stabilityQuick = new Option<bool>("--quick") { Description = "Reduced sweep for CI." };
            var stabilityFull = new Option<bool>("--full") { Description = "The integrator grid (1 356 cases, both integrators, both tension models, with and without a collider) after the scenario sweep." };
            var stabilityGrid = new Option<bool>("--grid") { Description = "The CI subset of the integrator grid (--full runs all of it)." };
            var stability = new Command("stability", "Sweep of stiff and extreme cases; exit code 1 if any case fails.")
            {
                stabilityOut, stabilityQuick, stabilityFull, stabilityGrid,
            };
            stability.SetAction(p => Guard(console, error, () =>
                p.GetValue(stabilityFull) || p.GetValue(stabilityGrid)
                    ? GridCommand.Execute(console, p.GetValue(stabilityOut), full: p.GetValue(stabilityFull))
                    : StabilityCommand.Execute(console, p.GetValue(stabilityOut), p.GetValue(stabilityQuick))));
            root.Subcommands.Add(stability);

            var benchQuick = new Option<bool>("--quick") { Description = "Fewer sizes and shorter timings." };
            var bench = new Command("bench", "Stopwatch micro-benchmarks: ns per projection, per segment-iteration, per mesh vertex; bytes per step; feature costs.")
            {
                benchQuick,
            };
            bench.SetAction(p => Guard(console, error, () => BenchCommand.Execute(console, p.GetValue(benchQuick))));
            root.Subcommands.Add(bench);
            return root;
        }

        static Option<string> OutOption() => new Option<string>("--out", "-o")
        {
            Description = "Output folder (created if missing).",
            DefaultValueFactory = _ => "lab-out~",
        };

        /// <summary>Runs a command body; invalid input becomes a one-line message and exit code 2, never a stack trace.</summary>
        static int Guard(IAnsiConsole console, TextWriter error, Func<int> body)
        {
            try
            {
                return body();
            }
            catch (ScenarioException e)
            {
                error.WriteLine("error: invalid scenario: " + e.Message);
                return InvalidInput;
            }
            catch (ArgumentException e)
            {
                error.WriteLine("error: " + e.Message);
                return InvalidInput;
            }
            catch (IOException e)
            {
                error.WriteLine("error: " + e.Message);
                return 1;
            }
            catch (UnauthorizedAccessException e)
            {
                error.WriteLine("error: " + e.Message);
                return 1;
            }
            catch (Exception e) when (Environment.GetEnvironmentVariable("HOOKEROPE_LAB_TRACE") == null)
            {
                error.WriteLine("internal error: " + e.GetType().Name + ": " + e.Message + " (set HOOKEROPE_LAB_TRACE=1 for the stack trace)");
                return 1;
            }
        }

        /// <summary>Parses and runs <paramref name="args"/>; returns the exit code.</summary>
        public static int Invoke(string[] args, IAnsiConsole console, TextWriter output, TextWriter error)
        {
            var root = Build(console, error);
            var parse = root.Parse(args);
            return parse.Invoke(new InvocationConfiguration { Output = output, Error = error });
        }
    }
}
