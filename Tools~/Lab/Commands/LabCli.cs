using System;
using System.Collections.Generic;
using System.CommandLine;
using System.CommandLine.Parsing;
using System.IO;
using HookeRope.Lab.Scenarios;
using Spectre.Console;

namespace HookeRope.Lab.Commands
{
    /// <summary>The lab's command line (System.CommandLine): run, list, report, stability, bench, figures, accuracy.</summary>
    public static class LabCli
    {
        /// <summary>Exit code for an invalid scenario, argument, option or output path.</summary>
        public const int InvalidInput = 2;
        /// <summary>Exit code for an I/O error while writing the outputs (and a failed stability case).</summary>
        public const int Failure = 1;

        /// <summary>Builds the command tree writing through <paramref name="console"/> (errors and progress lines to <paramref name="error"/>).</summary>
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
            var strict = new Option<bool>("--check") { Description = "Exit 4 when the run is unconverged or a physics check of the scenario fails." };
            var runQuiet = QuietOption();
            var json = new Option<bool>("--json") { Description = "Print the machine-readable summary (JSON) instead of the table; no progress." };
            var run = new Command("run", "Run a scenario: CSV time series, JSON summary, plots, one-screen summary with a convergence verdict.")
            {
                scenario, runOut, svg, gltf, strict, runQuiet, json,
            };
            run.SetAction(p => Guard(console, error, () =>
            {
                string chosen = p.GetValue(scenario);
                if (chosen != null && chosen.StartsWith("-") && !File.Exists(chosen))
                    throw new UsageException($"unknown option \"{chosen}\" for run" + Suggestions.DidYouMean(chosen, OptionNames(run))
                        + "; see `run --help` for the options");
                var mode = p.GetValue(json) ? RunCommand.Mode.Json : p.GetValue(runQuiet) ? RunCommand.Mode.Quiet : RunCommand.Mode.Summary;
                return RunCommand.Execute(console, p.GetValue(scenario), p.GetValue(runOut), p.GetValue(svg), p.GetValue(gltf), p.GetValue(strict),
                    mode, mode == RunCommand.Mode.Summary ? error : null);
            }));
            root.Subcommands.Add(run);

            var list = new Command("list", "List the built-in scenarios.");
            list.SetAction(p => Guard(console, error, () => ListCommand.Execute(console)));
            root.Subcommands.Add(list);

            var reportOut = OutOption();
            var reportQuick = new Option<bool>("--quick") { Description = "Reduced grid and one repeat (a smoke run, not for numbers)." };
            var repeats = new Option<int>("--repeats") { Description = "Timed rounds over the whole grid, 1–50 (each cell reports its best round).", DefaultValueFactory = _ => 5 };
            repeats.Validators.Add(r =>
            {
                if (r.Tokens.Count == 0 || !int.TryParse(r.Tokens[0].Value, out int n)) return;
                if (n < 1 || n > 50) r.AddError($"--repeats: {n} is out of range [1, 50]");
            });
            var reportQuiet = QuietOption();
            var headline = new Option<string[]>("--headline")
            {
                Description = "Also write the headline (table and recommendations) into this Markdown file between its \"lab report headline\" markers; repeatable (README.md, Documentation~/lab.md).",
            };
            var report = new Command("report", "Error against run time for reference scenarios and solver configurations: Markdown + Pareto plot.")
            {
                reportOut, reportQuick, repeats, reportQuiet, headline,
            };
            report.SetAction(p => Guard(console, error, () =>
                ReportCommand.Execute(console, p.GetValue(reportOut), p.GetValue(reportQuick), p.GetValue(repeats), p.GetValue(reportQuiet) ? null : error,
                    p.GetValue(headline))));
            root.Subcommands.Add(report);

            var stabilityOut = OutOption();
            var stabilityQuick = new Option<bool>("--quick") { Description = "Reduced sweep for CI." };
            var stabilityQuiet = QuietOption();
            var stabilityFull = new Option<bool>("--full") { Description = "The integrator stability grid (1 752 cases: both integrators, both tension models, with and without a collider, friction, settle, 1 km teleport); exit 1 on any failing case (the documented domain limits name known causes, they do not excuse a failure)." };
            var stabilityGrid = new Option<bool>("--grid") { Description = "The CI subset of the integrator grid (--full runs all of it)." };
            var stabilityMatch = new Option<string>("--match") { Description = "With --full or --grid: only the cases whose description contains this text (e.g. \"2 seg, stretch 10\"; alternatives separated by '|', one ending in '$' the whole description)." };
            var stability = new Command("stability", "Sweep of stiff and extreme cases; exit code 1 if any case fails.")
            {
                stabilityOut, stabilityQuick, stabilityQuiet, stabilityFull, stabilityGrid, stabilityMatch,
            };
            stability.SetAction(p => Guard(console, error, () =>
                p.GetValue(stabilityFull) || p.GetValue(stabilityGrid)
                    ? GridCommand.Execute(console, p.GetValue(stabilityOut), full: p.GetValue(stabilityFull), match: p.GetValue(stabilityMatch))
                    : StabilityCommand.Execute(console, p.GetValue(stabilityOut), p.GetValue(stabilityQuick), p.GetValue(stabilityQuiet) ? null : error)));
            root.Subcommands.Add(stability);

            var benchQuick = new Option<bool>("--quick") { Description = "Fewer sizes and shorter timings." };
            var bench = new Command("bench", "Stopwatch micro-benchmarks: ns per projection, per segment-iteration, per mesh vertex; bytes per step; feature costs.")
            {
                benchQuick,
            };
            bench.SetAction(p => Guard(console, error, () => BenchCommand.Execute(console, p.GetValue(benchQuick))));
            root.Subcommands.Add(bench);

            var figuresOut = OutOption();
            var figureSet = new Argument<string>("set")
            {
                Description = "harness: the manual's harness-rig figures; paper: the seed paper's Figs. 5–9a with captions and the burr texture; folds: the slack folds after a break (a known mesh problem); all: every set.",
                Arity = ArgumentArity.ZeroOrOne,
                DefaultValueFactory = _ => FiguresCommand.Harness,
            };
            figureSet.AcceptOnlyFromAmong(FiguresCommand.Harness, FiguresCommand.Paper, FiguresCommand.Folds, FiguresCommand.All);
            var figures = new Command("figures", "Render figures from the core's mesh of real simulations as PNG (harness rig, or the paper's Figs. 5–9a); the committed copies: --out \"Documentation~/images\".")
            {
                figureSet, figuresOut,
            };
            figures.SetAction(p => Guard(console, error, () => FiguresCommand.Execute(console, p.GetValue(figuresOut), p.GetValue(figureSet))));
            root.Subcommands.Add(figures);

            var accuracyOut = OutOption();
            var accuracy = new Command("accuracy", "The defaults' error against analytic answers at the validated step (1/90 s), 1/60 s and Unity's default 0.02 s: Markdown table.")
            {
                accuracyOut,
            };
            accuracy.SetAction(p => Guard(console, error, () => AccuracyCommand.Execute(console, p.GetValue(accuracyOut))));
            root.Subcommands.Add(accuracy);
            return root;
        }

        static Option<string> OutOption() => new Option<string>("--out", "-o")
        {
            Description = "Output folder (created if missing).",
            DefaultValueFactory = _ => "lab-out~",
        };

        static Option<bool> QuietOption() => new Option<bool>("--quiet", "-q")
        {
            Description = "No progress lines; for run only the verdict line (errors still go to stderr).",
        };

        /// <summary>Runs a command body; every error becomes one friendly line (no .NET exception text) and its exit code.</summary>
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
            catch (UsageException e)
            {
                error.WriteLine("error: " + e.Message);
                return InvalidInput;
            }
            catch (UnauthorizedAccessException)
            {
                error.WriteLine("error: permission denied while writing the output files; choose a writable folder with --out");
                return Failure;
            }
            catch (DirectoryNotFoundException)
            {
                error.WriteLine("error: a folder of the output path does not exist or vanished; check --out");
                return Failure;
            }
            catch (PathTooLongException)
            {
                error.WriteLine("error: the output path is too long; choose a shorter --out");
                return Failure;
            }
            catch (IOException)
            {
                error.WriteLine("error: could not write the output files (the disk may be full, read-only, or a file is open in another program); check --out");
                return Failure;
            }
            catch (Exception e) when (Environment.GetEnvironmentVariable("HOOKEROPE_LAB_TRACE") == null)
            {
                error.WriteLine("internal error (a bug in the lab, please report it): " + e.GetType().Name + " (set HOOKEROPE_LAB_TRACE=1 for the details)");
                return Failure;
            }
        }

        /// <summary>Parses and runs <paramref name="args"/>; returns the exit code (2 for a usage error, with "did you mean …").</summary>
        public static int Invoke(string[] args, IAnsiConsole console, TextWriter output, TextWriter error)
        {
            var root = Build(console, error);
            var parse = root.Parse(args);
            if (parse.Errors.Count > 0)
            {
                foreach (var line in UsageErrors(parse, root)) error.WriteLine(line);
                return InvalidInput;
            }
            return parse.Invoke(new InvocationConfiguration { Output = output, Error = error });
        }

        /// <summary>One friendly line per parse error, with the closest command, option or scenario name, and a pointer to --help.</summary>
        public static List<string> UsageErrors(ParseResult parse, RootCommand root)
        {
            var lines = new List<string>();
            var command = parse.CommandResult.Command;
            var commands = new List<string>();
            foreach (var c in root.Subcommands) commands.Add(c.Name);
            var options = OptionNames(command);
            var explained = new HashSet<string>();
            foreach (var token in parse.UnmatchedTokens)
            {
                explained.Add(token);
                if (token.StartsWith("-"))
                    lines.Add($"error: unknown option \"{token}\" for {Name(command)}" + Suggestions.DidYouMean(token, options));
                else if (command == root)
                    lines.Add($"error: unknown command \"{token}\"" + Suggestions.DidYouMean(token, commands) + "; the commands are " + string.Join(", ", commands));
                else if (command.Name == "run")
                    lines.Add($"error: \"{token}\" is one argument too many: run takes one scenario name or file");
                else
                    lines.Add($"error: unexpected argument \"{token}\" for {Name(command)}");
            }
            foreach (var e in parse.Errors)
            {
                bool aboutExplained = false;
                foreach (var token in explained) if (e.Message.Contains("'" + token + "'")) aboutExplained = true;
                if (aboutExplained) continue;
                if (e.Message.Contains("Required command"))
                {
                    if (parse.UnmatchedTokens.Count == 0)
                        lines.Add("error: no command given; the commands are " + string.Join(", ", commands) + " (the main job: `run`)");
                }
                else
                    lines.Add("error: " + Friendly(e.Message));
            }
            if (lines.Count == 0) lines.Add("error: invalid command line");
            lines.Add(HelpHint(command));
            return lines;
        }

        static string Name(Command command) => command is RootCommand ? "the lab" : command.Name;

        static string HelpHint(Command command) => command is RootCommand ? "see `--help` for the commands and options" : $"see `{command.Name} --help` for the options";

        static List<string> OptionNames(Command command)
        {
            var names = new List<string>();
            foreach (var o in command.Options)
            {
                names.Add(o.Name);
                foreach (var alias in o.Aliases) names.Add(alias);
            }
            return names;
        }

        /// <summary>System.CommandLine's message with .NET type names put in words.</summary>
        static string Friendly(string message) => message
            .Replace("'System.Int32'", "a whole number").Replace("'System.Double'", "a number")
            .Replace("'System.Boolean'", "true or false").Replace("'System.String'", "text");
    }
}
