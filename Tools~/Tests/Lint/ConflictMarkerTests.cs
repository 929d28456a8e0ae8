using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// No file in the repository keeps a merge-conflict marker: a line that starts with seven '&lt;' or seven '&gt;' and a
    /// space (git writes both around every conflict; a lone line of '=' is also a Markdown heading underline). The compiler
    /// catches markers in code; nothing else would catch them in the changelog, the manual, scenario JSON or YAML.
    /// </summary>
    [TestFixture]
    public sealed class ConflictMarkerTests
    {
        static readonly string[] Markers = { new string('<', 7) + " ", new string('>', 7) + " " };
        static readonly string[] TextEndings = { ".md", ".cs", ".json", ".yml", ".yaml", ".asmdef", ".prefab", ".unity", ".meta", ".csproj", ".props", ".sln", ".txt" };

        /// <summary>Lines "path:line" that hold a conflict marker, under root (skipping build output and .git).</summary>
        public static List<string> Find(string root)
        {
            var found = new List<string>();
            foreach (string file in Directory.EnumerateFiles(root, "*", SearchOption.AllDirectories))
            {
                string relative = Path.GetRelativePath(root, file).Replace('\\', '/');
                if (relative.StartsWith(".git/") || relative.Contains("/bin/") || relative.Contains("/obj/") || relative.Contains(".artifacts")) continue;
                if (System.Array.IndexOf(TextEndings, Path.GetExtension(file)) < 0) continue;
                int line = 0;
                foreach (string text in File.ReadLines(file))
                {
                    line++;
                    foreach (string marker in Markers)
                        if (text.StartsWith(marker, System.StringComparison.Ordinal))
                        {
                            found.Add(relative + ":" + line);
                            break;
                        }
                }
            }
            return found;
        }

        [Test]
        public void NoFileKeepsAConflictMarker()
        {
            var found = Find(PackageRoot.Path);
            Assert.That(found, Is.Empty, string.Join("\n", found));
        }

        [Test]
        public void APlantedMarkerIsFound()
        {
            string folder = Path.Combine(Path.GetTempPath(), "hookerope-markers-" + System.Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(folder);
            try
            {
                File.WriteAllLines(Path.Combine(folder, "CHANGELOG.md"), new[] { "# Changelog", new string('<', 7) + " HEAD", "- ours", new string('=', 7), "- theirs", new string('>', 7) + " main" });
                File.WriteAllLines(Path.Combine(folder, "clean.md"), new[] { "# Title", "=======", "text" });
                Assert.That(Find(folder), Is.EqualTo(new[] { "CHANGELOG.md:2", "CHANGELOG.md:6" }), "a heading underline is no marker");
            }
            finally { Directory.Delete(folder, true); }
        }
    }
}
