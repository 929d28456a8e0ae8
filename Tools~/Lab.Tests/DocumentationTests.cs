using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using HookeRope.Lab.Scenarios;
using HookeRope.Lab.Stability;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>
    /// Documentation~/lab.md documents every field the scenario parser accepts and every built-in scenario; the committed
    /// full grid report (Documentation~/stability-grid.md) explains its limits as the grid does now.
    /// </summary>
    [TestFixture]
    public sealed class DocumentationTests
    {
        static string PackageRoot()
        {
            var dir = new DirectoryInfo(TestContext.CurrentContext.TestDirectory);
            while (dir != null && !File.Exists(Path.Combine(dir.FullName, "package.json"))) dir = dir.Parent;
            Assert.That(dir, Is.Not.Null, "package root (package.json) above the test directory");
            return dir.FullName;
        }

        [Test]
        public void EveryParsedFieldIsDocumented()
        {
            string root = PackageRoot();
            string parser = File.ReadAllText(Path.Combine(root, "Tools~", "Lab", "Scenarios", "ScenarioParser.cs"));
            string doc = File.ReadAllText(Path.Combine(root, "Documentation~", "lab.md"));
            var fields = new SortedSet<string>();
            foreach (Match m in Regex.Matches(parser, "\\.(?:Number|OptionalNumber|Integer|Boolean|String|Choice|Vector|OptionalVector|Array|Numbers|Object|Has)\\(\"(\\w+)\""))
                fields.Add(m.Groups[1].Value);
            // the rope and solver fields are read through the parameter table (JsonFields.Parameter(row, …))
            foreach (var row in RopeParameters.All)
                if (row.Json != null) fields.Add(row.Json);
            Assert.That(fields.Count, Is.GreaterThan(30), "the parser's field names were found");
            var missing = new List<string>();
            foreach (var field in fields)
                if (!doc.Contains("`" + field + "`")) missing.Add(field);
            Assert.That(missing, Is.Empty, "fields accepted by ScenarioParser but not documented in lab.md");
        }

        [Test]
        public void TheCommittedGridReportExplainsEachLimitAsTheGridDoesNow()
        {
            // `stability --full` writes the report; the full grid passes every case (GridCommand exits 1 otherwise), so
            // each limit's line counts 0 cases. A changed explanation in GridLimits needs the report written again.
            string report = File.ReadAllText(Path.Combine(PackageRoot(), "Documentation~", "stability-grid.md"));
            foreach (string limit in GridLimits.All)
                Assert.That(report, Does.Contain(GridLimits.ReportLine(limit, 0) + "\n"),
                    GridLimits.Name(limit) + ": Documentation~/stability-grid.md is older than GridLimits (run `stability --full` and copy its stability-grid.md)");
            Assert.That(report, Does.Contain("## Failures (every failing case; the limit column names the documented limit it falls under)\n\nNone.\n"));
        }

        [Test]
        public void EveryBuiltInScenarioIsDocumented()
        {
            string doc = File.ReadAllText(Path.Combine(PackageRoot(), "Documentation~", "lab.md"));
            foreach (var name in BuiltInScenarios.Names) Assert.That(doc, Does.Contain("`" + name + "`"), name);
        }
    }
}
