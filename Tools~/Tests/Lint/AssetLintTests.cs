using System;
using System.IO;
using System.Linq;
using NUnit.Framework;

namespace HookeRope.Tests.Lint
{
    /// <summary>The package passes the asset lint, and every check fails on a planted defect.</summary>
    [TestFixture]
    public sealed class AssetLintTests
    {
        string _copy;

        [SetUp]
        public void CopyPackage()
        {
            _copy = Path.Combine(Path.GetTempPath(), "hookerope-lint-" + Guid.NewGuid().ToString("N"));
            CopyImported(PackageRoot.Path, _copy);
        }

        [TearDown]
        public void DeleteCopy()
        {
            if (Directory.Exists(_copy)) Directory.Delete(_copy, true);
        }

        [Test]
        public void PackageHasNoLintProblems()
        {
            var problems = new AssetLint(PackageRoot.Path).All();
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
        }

        [Test]
        public void UntouchedCopyHasNoLintProblems()
        {
            Assert.That(new AssetLint(_copy).All(), Is.Empty);
        }

        [Test]
        public void MissingMetaIsFound()
        {
            File.Delete(Path.Combine(_copy, "Runtime", "HookeRope.asmdef.meta"));
            Assert.That(new AssetLint(_copy).MissingMetas(), Has.Some.Contains("missing meta: Runtime/HookeRope.asmdef"));
        }

        [Test]
        public void MissingFolderMetaIsFound()
        {
            Directory.CreateDirectory(Path.Combine(_copy, "Runtime", "Planted"));
            Assert.That(new AssetLint(_copy).MissingMetas(), Has.Some.Contains("missing meta: Runtime/Planted"));
        }

        [Test]
        public void OrphanMetaIsFound()
        {
            WriteMeta(Path.Combine(_copy, "Runtime", "Gone.cs.meta"), "5b0e4f3c8a9d4e6fb1c2d3e4f5a6b7c8");
            Assert.That(new AssetLint(_copy).OrphanMetas(), Has.Some.Contains("orphan meta: Runtime/Gone.cs.meta"));
        }

        [Test]
        public void DuplicateGuidIsFound()
        {
            var guid = ReadGuid(Path.Combine(_copy, "Runtime", "HookeRope.asmdef.meta"));
            File.WriteAllText(Path.Combine(_copy, "Runtime", "Planted.txt"), "x");
            WriteMeta(Path.Combine(_copy, "Runtime", "Planted.txt.meta"), guid);
            Assert.That(new AssetLint(_copy).DuplicateGuids(), Has.Some.Contains("duplicate guid " + guid));
        }

        [TestCase("5B0E4F3C8A9D4E6FB1C2D3E4F5A6B7C8")]
        [TestCase("5b0e4f3c8a9d4e6fb1c2d3e4f5a6b7")]
        [TestCase("5b0e4f3c-8a9d-4e6f-b1c2-d3e4f5a6b7c8")]
        public void MalformedGuidIsFound(string guid)
        {
            File.WriteAllText(Path.Combine(_copy, "Runtime", "Planted.txt"), "x");
            WriteMeta(Path.Combine(_copy, "Runtime", "Planted.txt.meta"), guid);
            Assert.That(new AssetLint(_copy).MalformedMetas(), Has.Some.Contains("Runtime/Planted.txt.meta"));
        }

        [Test]
        public void DanglingPrefabGuidIsFound()
        {
            var prefab = Path.Combine(_copy, "Runtime", "Planted.prefab");
            File.WriteAllText(prefab, "%YAML 1.1\n--- !u!114 &1\nMonoBehaviour:\n  m_Script: {fileID: 11500000, guid: 0123456789abcdef0123456789abcdef, type: 3}\n");
            WriteMeta(prefab + ".meta", "6c1f5a4d9b0e4f7ac2d3e4f5a6b7c8d9");
            Assert.That(new AssetLint(_copy).DanglingAssetReferences(),
                Has.Some.Contains("dangling guid 0123456789abcdef0123456789abcdef in Runtime/Planted.prefab"));
        }

        [Test]
        public void BuiltInAndPackageGuidsResolve()
        {
            var prefab = Path.Combine(_copy, "Runtime", "Planted.prefab");
            var asmdefGuid = ReadGuid(Path.Combine(_copy, "Runtime", "HookeRope.asmdef.meta"));
            File.WriteAllText(prefab, "m_Mesh: {fileID: 10207, guid: 0000000000000000e000000000000000, type: 0}\n" +
                                      "m_Script: {fileID: 11500000, guid: " + asmdefGuid + ", type: 3}\n");
            WriteMeta(prefab + ".meta", "6c1f5a4d9b0e4f7ac2d3e4f5a6b7c8d9");
            Assert.That(new AssetLint(_copy).DanglingAssetReferences(), Is.Empty);
        }

        [Test]
        public void UnresolvedAsmdefReferenceIsFound()
        {
            var asmdef = Path.Combine(_copy, "Runtime", "HookeRope.asmdef");
            File.WriteAllText(asmdef, File.ReadAllText(asmdef).Replace("\"HookeRope.Core\"", "\"HookeRope.Kore\""));
            Assert.That(new AssetLint(_copy).AsmdefProblems(), Has.Some.Contains("'HookeRope.Kore' resolves to nothing"));
        }

        [Test]
        public void ScriptOutsideAsmdefIsFound()
        {
            var script = Path.Combine(_copy, "Stray.cs");
            File.WriteAllText(script, "class Stray {}");
            WriteMeta(script + ".meta", "7d2a6b5e0c1f4a8bd3e4f5a6b7c8d9e0");
            Assert.That(new AssetLint(_copy).ScriptsOutsideAsmdef(), Has.Some.Contains("Stray.cs"));
        }

        [Test]
        public void BrokenPackageManifestIsFound()
        {
            var manifest = Path.Combine(_copy, "package.json");
            File.WriteAllText(manifest, File.ReadAllText(manifest).Replace("\"version\": \"0.1.0\"", "\"version\": \"1.0\""));
            Assert.That(new AssetLint(_copy).PackageManifestProblems(), Has.Some.Contains("version '1.0' is not SemVer"));
            File.WriteAllText(manifest, "{ \"name\": ");
            Assert.That(new AssetLint(_copy).PackageManifestProblems(), Has.Some.Contains("does not parse"));
        }

        [Test]
        public void MissingSamplePathIsFound()
        {
            var manifest = Path.Combine(_copy, "package.json");
            var text = File.ReadAllText(manifest);
            var start = text.IndexOf("\"samples\"", StringComparison.Ordinal);
            var end = text.IndexOf(']', start);
            text = text.Substring(0, start) +
                   "\"samples\": [ { \"displayName\": \"Ghost\", \"description\": \"x\", \"path\": \"Samples~/Ghost\" } ]" +
                   text.Substring(end + 1);
            File.WriteAllText(manifest, text);
            Assert.That(new AssetLint(_copy).PackageManifestProblems(), Has.Some.Contains("'Samples~/Ghost' does not exist"));
        }

        [Test]
        public void MetaInDocumentationIsFound()
        {
            Directory.CreateDirectory(Path.Combine(_copy, "Documentation~"));
            WriteMeta(Path.Combine(_copy, "Documentation~", "index.md.meta"), "8e3b7c6f1d2a4b9ce4f5a6b7c8d9e0f1");
            Assert.That(new AssetLint(_copy).MetasInIgnoredFolders(), Has.Some.Contains("Documentation~/index.md.meta"));
        }

        static void WriteMeta(string path, string guid) =>
            File.WriteAllText(path, "fileFormatVersion: 2\nguid: " + guid + "\nDefaultImporter:\n  externalObjects: {}\n");

        static string ReadGuid(string meta) =>
            File.ReadAllLines(meta).First(l => l.StartsWith("guid: ", StringComparison.Ordinal)).Substring(6).Trim();

        /// <summary>Copies the package without build output or git data.</summary>
        static void CopyImported(string from, string to)
        {
            Directory.CreateDirectory(to);
            foreach (var file in Directory.EnumerateFiles(from))
                File.Copy(file, Path.Combine(to, Path.GetFileName(file)));
            foreach (var dir in Directory.EnumerateDirectories(from))
            {
                var name = Path.GetFileName(dir);
                if (name == ".git" || name == "Tools~" || name.StartsWith(".artifacts", StringComparison.Ordinal)) continue;
                CopyImported(dir, Path.Combine(to, name));
            }
        }
    }
}
