using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using HookeRope.Lab.Scenarios;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>Documentation~/lab.md documents every field the scenario parser accepts and every built-in scenario.</summary>
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
        public void EveryBuiltInScenarioIsDocumented()
        {
            string doc = File.ReadAllText(Path.Combine(PackageRoot(), "Documentation~", "lab.md"));
            foreach (var name in BuiltInScenarios.Names) Assert.That(doc, Does.Contain("`" + name + "`"), name);
        }
    }
}
