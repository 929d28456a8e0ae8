using System.Collections.Generic;
using System.IO;
using System.Text.Json;
using HookeRope.Lab.Commands;
using HookeRope.Lab.Output;
using NUnit.Framework;
using Spectre.Console;

namespace HookeRope.Lab.Tests
{
    /// <summary>CLI polish (issue 16 item 5): usage errors exit 2 with "did you mean", friendly messages, progress lines, width, --quiet/--json.</summary>
    [TestFixture]
    public sealed class CliUsageTests : TempFolderTest
    {
        static int Invoke(out string output, out string error, params string[] args) => InvokeLab(out output, out error, args);

        static void AssertFriendly(string error)
        {
            Assert.That(error, Does.Not.Contain("   at "));
            Assert.That(error, Does.Not.Contain("Exception"));
            Assert.That(error, Does.Not.Contain("System."));
        }

        [TestCase(new[] { "runn" }, "did you mean \"run\"")]
        [TestCase(new[] { "stabilty" }, "did you mean \"stability\"")]
        [TestCase(new string[0], "no command given")]
        [TestCase(new[] { "run", "fal-arrest" }, "did you mean \"fall-arrest\"")]
        [TestCase(new[] { "run", "--chek" }, "did you mean \"--check\"")]
        [TestCase(new[] { "report", "--repets", "3" }, "did you mean \"--repeats\"")]
        [TestCase(new[] { "report", "--repeats", "0" }, "--repeats: 0 is out of range [1, 50]")]
        [TestCase(new[] { "report", "--repeats", "many" }, "a whole number")]
        [TestCase(new[] { "run", "static-hang", "extra" }, "one argument too many")]
        public void UsageErrorsExitTwoWithAFriendlyLine(string[] args, string expected)
        {
            int code = Invoke(out _, out string error, args);
            Assert.That(code, Is.EqualTo(LabCli.InvalidInput), error);
            Assert.That(error, Does.Contain(expected));
            AssertFriendly(error);
        }

        [Test]
        public void OutputPathThatIsAFileExitsTwoNamingThePath()
        {
            string file = Path.Combine(dir, "taken");
            File.WriteAllText(file, "x");
            foreach (var args in new[] { new[] { "run", "--out", file }, new[] { "run", "--out", Path.Combine(file, "sub") }, new[] { "stability", "--quick", "--out", file } })
            {
                Assert.That(Invoke(out _, out string error, args), Is.EqualTo(LabCli.InvalidInput), string.Join(" ", args));
                Assert.That(error, Does.Contain("--out: \"" + file + "\" is a file"));
                AssertFriendly(error);
            }
        }

        [Test]
        public void JsonModePrintsTheFullPrecisionSummaryAndWritesItToo()
        {
            Assert.That(Invoke(out string output, out string error, "run", "--json", "--out", dir), Is.EqualTo(0), error);
            using (var doc = JsonDocument.Parse(output))
            {
                var root = doc.RootElement;
                Assert.That(root.GetProperty("verdict").GetProperty("kind").GetString(), Is.EqualTo("converged"));
                double peak = root.GetProperty("peakAnchorForce_N").GetDouble();
                Assert.That(peak, Is.EqualTo(5518).Within(0.05 * 5518), "the energy balance's peak force");
                Assert.That(root.GetProperty("limits").GetProperty("en355_6kN").GetBoolean(), Is.True);
                Assert.That(root.GetProperty("checks")[0].GetProperty("passed").GetBoolean(), Is.True);
                Assert.That(root.GetProperty("breakTime_s").ValueKind, Is.EqualTo(JsonValueKind.Null));
            }
            string file = File.ReadAllText(Path.Combine(dir, "fall-arrest-summary.json"));
            Assert.That(file.Trim(), Is.EqualTo(output.Trim()));
            Assert.That(error, Is.Empty, "no progress lines in --json mode");
        }

        [Test]
        public void QuietModePrintsOnlyTheVerdict()
        {
            Assert.That(Invoke(out string output, out _, "run", "static-hang", "--quiet", "--out", dir), Is.EqualTo(0));
            var lines = output.Trim().Split('\n');
            Assert.That(lines.Length, Is.EqualTo(1), output);
            Assert.That(lines[0], Does.StartWith("verdict: converged"));
        }

        [Test]
        public void ProgressLinesComeEveryIntervalWithAnEta()
        {
            double now = 0;
            var writer = new StringWriter();
            var progress = new ProgressLines("run", 1000, writer, 10, () => now);
            var seen = new List<string>();
            for (int k = 0; k <= 1000; k += 50)
            {
                now = k * 0.04;                  // 40 s for the whole run
                progress.Report(k);
            }
            var lines = writer.ToString().Trim().Split('\n');
            Assert.That(lines.Length, Is.EqualTo(4), writer.ToString());   // at 10, 20, 30 and 40 s
            Assert.That(lines[0].Trim(), Is.EqualTo("run: 25 % (250 of 1000), 10.0 s elapsed, about 30.0 s left"));
            Assert.That(ProgressLines.Duration(185), Is.EqualTo("3 min 05 s"));
        }

        [Test]
        public void RedirectedOutputIsLaidOutFullWidth()
        {
            var console = AnsiConsole.Create(new AnsiConsoleSettings { Out = new AnsiConsoleOutput(new StringWriter()) });
            console.Profile.Width = 80;
            Assert.That(LabConsole.ForProcess(console, redirected: true).Profile.Width, Is.EqualTo(LabConsole.RedirectedWidth));
            console.Profile.Width = 80;
            Assert.That(LabConsole.ForProcess(console, redirected: false).Profile.Width, Is.EqualTo(80));
        }

        [TestCase("kitten", "sitting", 3)]
        [TestCase("run", "run", 0)]
        [TestCase("", "abc", 3)]
        public void EditDistance(string a, string b, int expected) => Assert.That(Suggestions.Distance(a, b), Is.EqualTo(expected));

        [Test]
        public void CsvNumbersAreFullPrecisionWithoutNegativeZero()
        {
            Assert.That(CsvWriter.Format(-0.0), Is.EqualTo("0"));
            Assert.That(double.Parse(CsvWriter.Format(0.1 + 0.2), System.Globalization.CultureInfo.InvariantCulture), Is.EqualTo(0.1 + 0.2));
            Assert.That(CsvWriter.Format(1.0 / 3), Is.EqualTo("0.3333333333333333"));
        }
    }
}
