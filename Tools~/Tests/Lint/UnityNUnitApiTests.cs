using System;
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// The harness runs NUnit 3.6 (the oldest 3.x served here), but Unity ships a 3.5-based build.
    /// These tests reject the APIs our test sources could compile against here that Unity lacks.
    /// </summary>
    [TestFixture]
    public sealed class UnityNUnitApiTests
    {
        /// <summary>Patterns for NUnit members missing from Unity's com.unity.ext.nunit 1.0.6 and 2.0.x.</summary>
        static readonly (string Name, Regex Pattern)[] Forbidden =
        {
            ("Assert.Multiple", new Regex(@"\bAssert\.Multiple\b")),
            ("Assert.Warn / Warn.If / Warn.Unless", new Regex(@"\b(Assert\.Warn|Warn\.If|Warn\.Unless)\b")),
            ("[NonParallelizable]", new Regex(@"\bNonParallelizable\b")),
            ("[DefaultFloatingPointTolerance]", new Regex(@"\bDefaultFloatingPointTolerance\b")),
            ("[FixtureLifeCycle]", new Regex(@"\bFixtureLifeCycle\b")),
            ("TestContext.Progress / TestContext.Error", new Regex(@"\bTestContext\.(Progress|Error)\b")),
            ("Is.AnyOf", new Regex(@"\bIs\.AnyOf\b")),
            ("Has.ItemAt / Has.One", new Regex(@"\bHas\.(ItemAt|One)\b")),
            ("async asserts", new Regex(@"\b(ThrowsAsync|CatchAsync|DoesNotThrowAsync)\b")),
            ("Does.ContainKey / ContainValue", new Regex(@"\bDoes\.(ContainKey|ContainValue)\b")),
            ("async Task tests", new Regex(@"\basync\s+(System\.Threading\.Tasks\.)?Task\b")),
        };

        static IEnumerable<string> UnityTestSources()
        {
            var tests = Path.Combine(PackageRoot.Path, "Tests");
            return Directory.Exists(tests)
                ? Directory.EnumerateFiles(tests, "*.cs", SearchOption.AllDirectories)
                : Array.Empty<string>();
        }

        static List<string> Violations(string source, string label)
        {
            var found = new List<string>();
            foreach (var (name, pattern) in Forbidden)
                if (pattern.IsMatch(source))
                    found.Add($"{label}: uses {name}, which Unity's NUnit 3.5 build lacks");
            return found;
        }

        [Test]
        public void TestSourcesUseOnlyUnityNUnitApis()
        {
            var found = new List<string>();
            foreach (var file in UnityTestSources())
                found.AddRange(Violations(File.ReadAllText(file), Path.GetRelativePath(PackageRoot.Path, file)));
            Assert.That(found, Is.Empty, string.Join("\n", found));
        }

        [TestCase("Assert.Multiple(() => { });")]
        [TestCase("Warn.If(true);")]
        [TestCase("Assert.That(x, Is.AnyOf(1, 2));")]
        [TestCase("public async Task Later() { }")]
        [TestCase("Assert.ThrowsAsync<Exception>(() => null);")]
        public void PlantedNUnit4StyleCallIsRejected(string line)
        {
            Assert.That(Violations(line, "planted.cs"), Has.Count.EqualTo(1));
        }

        [Test]
        public void AllowedCallsPass()
        {
            const string allowed = "Assert.That(x, Is.EqualTo(1).Within(1e-6)); Assert.Throws<ArgumentException>(() => F());";
            Assert.That(Violations(allowed, "allowed.cs"), Is.Empty);
        }
    }
}
