using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// The package's code and tests see exactly Unity's public API: nothing under the folders Unity imports may name the
    /// stand-in's own namespace (HookeRope.StandIn), which does not exist in Unity. The stand-in keeps its control
    /// surface internal; this guards against a public helper slipping into package code.
    /// </summary>
    [TestFixture]
    public sealed class StandInIsolationTests
    {
        static readonly string[] s_ImportedFolders = { "Runtime", "Editor", "Tests", "Samples~" };

        [Test]
        public void PackageSourcesNeverNameTheStandIn()
        {
            var offenders = new List<string>();
            foreach (var folder in s_ImportedFolders)
            {
                var root = Path.Combine(PackageRoot.Path, folder);
                if (!Directory.Exists(root)) continue;
                foreach (var file in Directory.EnumerateFiles(root, "*.cs", SearchOption.AllDirectories))
                    if (File.ReadAllText(file).Contains("HookeRope.StandIn")) offenders.Add(Path.GetRelativePath(PackageRoot.Path, file));
            }
            Assert.That(offenders, Is.Empty, "package sources must use only Unity's public API");
        }
    }
}
