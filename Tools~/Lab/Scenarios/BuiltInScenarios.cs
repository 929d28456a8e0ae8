using System;
using System.Collections.Generic;
using System.IO;

namespace HookeRope.Lab.Scenarios
{
    /// <summary>The scenarios embedded in the lab assembly (Scenarios/BuiltIn/*.json).</summary>
    public static class BuiltInScenarios
    {
        /// <summary>Name of the scenario run when none is given.</summary>
        public const string Default = "fall-arrest";

        /// <summary>Every built-in scenario name, in presentation order.</summary>
        public static readonly string[] Names =
        {
            "fall-arrest", "static-hang", "spring-oscillator", "heavy-mass-ratio", "steel-cable",
            "poisson-sweep", "necking", "fracture", "collision-bend", "catenary",
            "spring-amplitude", "slack-bounce", "steel-snatch",
            "plastic-necking", "absorber-arrest", "swing-settle",
        };

        /// <summary>True when <paramref name="name"/> is a built-in scenario.</summary>
        public static bool Contains(string name) => Array.IndexOf(Names, name) >= 0;

        /// <summary>The JSON text of a built-in scenario.</summary>
        public static string Json(string name)
        {
            if (!Contains(name))
                throw new ArgumentException($"no built-in scenario \"{name}\" (known: {string.Join(", ", Names)})", nameof(name));
            var assembly = typeof(BuiltInScenarios).Assembly;
            using (var stream = assembly.GetManifestResourceStream("HookeRope.Lab.Scenarios." + name + ".json"))
            {
                if (stream == null) throw new InvalidOperationException("embedded scenario missing: " + name);
                using (var reader = new StreamReader(stream)) return reader.ReadToEnd();
            }
        }

        /// <summary>A freshly parsed copy of a built-in scenario.</summary>
        public static Scenario Load(string name) => ScenarioParser.Parse(Json(name));

        /// <summary>A built-in name or a path to a JSON file.</summary>
        public static Scenario Resolve(string nameOrPath)
        {
            if (string.IsNullOrEmpty(nameOrPath)) return Load(Default);
            if (Contains(nameOrPath)) return Load(nameOrPath);
            if (!File.Exists(nameOrPath))
                throw new ScenarioException("$", $"\"{nameOrPath}\" is neither a built-in scenario nor an existing file"
                    + Commands.Suggestions.DidYouMean(nameOrPath, Names) + $"; the built-in scenarios are {string.Join(", ", Names)}");
            if (Directory.Exists(nameOrPath))
                throw new ScenarioException("$", $"\"{nameOrPath}\" is a folder; give a scenario JSON file or a built-in name");
            var info = new FileInfo(nameOrPath);
            if (info.Length > ScenarioParser.MaxDocumentBytes)
                throw new ScenarioException("$", $"file too large ({info.Length} bytes, at most {ScenarioParser.MaxDocumentBytes})");
            return ScenarioParser.Parse(File.ReadAllText(nameOrPath));
        }

        /// <summary>All built-in scenarios, parsed.</summary>
        public static List<Scenario> All()
        {
            var list = new List<Scenario>();
            foreach (var name in Names) list.Add(Load(name));
            return list;
        }
    }
}
