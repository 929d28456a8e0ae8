using System.IO;
using HookeRope.Lab.Commands;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary><c>report --headline FILE</c>: the generated block replaces only what lies between its markers; a file without them is a usage error before the grid runs.</summary>
    [TestFixture]
    public sealed class HeadlineBlockTests : TempFolderTest
    {
        static string Document(string inside, string newline = "\n") =>
            "# Title" + newline + "prose before" + newline + HeadlineBlock.Start + newline + inside + newline + HeadlineBlock.End + newline + "prose after" + newline;

        [Test]
        public void OnlyTheLinesBetweenTheMarkersChange()
        {
            string text = Document("| old | table |\n|---|---|\n| 1 | 2 |");
            string replaced = HeadlineBlock.Replace(text, "| new |\n|---|\n| 3 |\n", "README.md");
            Assert.That(replaced, Is.EqualTo("# Title\nprose before\n" + HeadlineBlock.Start + "\n\n| new |\n|---|\n| 3 |\n\n" + HeadlineBlock.End + "\nprose after\n"));
            Assert.That(HeadlineBlock.Replace(replaced, "| new |\n|---|\n| 3 |", "README.md"), Is.EqualTo(replaced), "regenerating the same headline changes nothing");
        }

        [Test]
        public void WindowsLineEndsStayWindowsLineEnds()
        {
            string replaced = HeadlineBlock.Replace(Document("x", "\r\n"), "a\nb", "README.md");
            Assert.That(replaced, Does.Contain("\r\n\r\na\r\nb\r\n\r\n" + HeadlineBlock.End + "\r\n"));
            Assert.That(replaced.Replace("\r\n", "").Contains("\n"), Is.False);
        }

        [TestCase("no markers at all\n")]
        [TestCase(HeadlineBlock.End + "\n" + HeadlineBlock.Start + "\n")]
        [TestCase(HeadlineBlock.Start + "\nx\n" + HeadlineBlock.End + "\n" + HeadlineBlock.Start + "\n" + HeadlineBlock.End + "\n")]
        public void AFileWithoutOnePairOfMarkersIsRefusedNamingIt(string text)
        {
            var e = Assert.Throws<UsageException>(() => HeadlineBlock.Replace(text, "x", "docs/README.md"));
            Assert.That(e.Message, Does.Contain("--headline: \"docs/README.md\" needs one line"));
        }

        [Test]
        public void TheReportRefusesABadHeadlineFileBeforeMeasuring()
        {
            string file = Path.Combine(dir, "README.md");
            File.WriteAllText(file, "no markers\n");
            int code = InvokeLab(out _, out string error, "report", "--quick", "--out", dir, "--headline", file);
            Assert.That(code, Is.EqualTo(LabCli.InvalidInput));
            Assert.That(error, Does.Contain("needs one line"));
            Assert.That(File.Exists(Path.Combine(dir, "report.md")), Is.False, "nothing was measured");
            code = InvokeLab(out _, out error, "report", "--quick", "--out", dir, "--headline", Path.Combine(dir, "missing.md"));
            Assert.That(code, Is.EqualTo(LabCli.InvalidInput));
            Assert.That(error, Does.Contain("does not exist"));
        }

        [Test]
        public void TheQuickReportWritesItsHeadlineIntoEveryNamedFile()
        {
            string a = Path.Combine(dir, "README.md"), b = Path.Combine(dir, "lab.md");
            File.WriteAllText(a, Document("stale"));
            File.WriteAllText(b, Document("stale"));
            int code = InvokeLab(out _, out string error, "report", "--quick", "--quiet", "--out", dir, "--headline", a, "--headline", b);
            Assert.That(code, Is.EqualTo(0), error);
            foreach (var file in new[] { a, b })
            {
                string text = File.ReadAllText(file);
                Assert.That(text, Does.Not.Contain("stale"));
                Assert.That(text, Does.StartWith("# Title\nprose before\n"));
                Assert.That(text, Does.EndWith(HeadlineBlock.End + "\nprose after\n"));
                Assert.That(text, Does.Contain("| exact BDF2 1it × 4sub |"));
                Assert.That(text, Does.Contain("| exact BE 1it × 4sub |"));
                Assert.That(text, Does.Contain("load average (1, 5, 15 min)"));
                Assert.That(text, Does.Contain("- Exact chain with backward Euler:"));
            }
        }
    }
}
