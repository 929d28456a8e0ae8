using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using NUnit.Framework;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// package.json declares exactly the Unity built-in modules the package uses: every UnityEngine /
    /// UnityEditor type named or touched by Runtime/ (outside Runtime/Core, as the Editor and a player compile it),
    /// Editor/ and Samples~/ (found by <see cref="UnityTypeUsage"/>), and every serialized class in the scenes and
    /// prefabs shipped there, is mapped to its module by <see cref="UnityModuleTable"/>; each module with a package must be a dependency at version 1.0.0, and no
    /// com.unity.modules.* dependency may be declared that nothing uses. A type or serialized class missing from the table fails, so a new
    /// Unity API use forces the table (and maybe package.json) to be updated. Planted defects show the check bites.
    /// </summary>
    [TestFixture]
    public sealed class ModuleDependencyTests
    {
        const string ModulePrefix = "com.unity.modules.";

        static SortedDictionary<string, SortedSet<string>> s_Used;

        static SortedDictionary<string, SortedSet<string>> Used =>
            s_Used ?? (s_Used = UnityTypeUsage.Collect(PackageRoot.Path));

        static SortedDictionary<string, SortedSet<string>> Serialized => UnityTypeUsage.CollectSerialized(PackageRoot.Path);

        string _dir;

        [SetUp]
        public void MakeTempDir()
        {
            _dir = Path.Combine(Path.GetTempPath(), "hookerope-modules-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void DeleteTempDir()
        {
            if (Directory.Exists(_dir)) Directory.Delete(_dir, true);
        }

        /// <summary>Problems of a manifest against the used types: unknown types, missing, wrong-version and unused modules.</summary>
        static List<string> Problems(string manifestPath, IDictionary<string, SortedSet<string>> used,
            IDictionary<string, SortedSet<string>> serialized)
        {
            var problems = new List<string>();
            var needed = new SortedDictionary<string, SortedSet<string>>(StringComparer.Ordinal);
            void Need(IDictionary<string, SortedSet<string>> uses, IReadOnlyDictionary<string, UnityModuleTable.Module> table,
                string what, string label)
            {
                foreach (var pair in uses)
                {
                    if (!table.TryGetValue(pair.Key, out var module))
                    {
                        problems.Add($"unknown {what} {pair.Key} (used in {string.Join(", ", pair.Value)}): add it with its " +
                                     "module to Tools~/Tests/Lint/UnityModuleTable.cs");
                        continue;
                    }
                    if (module.Package == null) continue;
                    if (!needed.TryGetValue(module.Package, out var why))
                        needed[module.Package] = why = new SortedSet<string>(StringComparer.Ordinal);
                    why.Add(label + pair.Key);
                }
            }
            Need(used, UnityModuleTable.Types, "Unity type", "");
            Need(serialized, UnityModuleTable.SerializedClasses, "serialized class", "serialized ");

            var declared = new Dictionary<string, string>(StringComparer.Ordinal);
            using (var doc = JsonDocument.Parse(File.ReadAllText(manifestPath)))
                if (doc.RootElement.TryGetProperty("dependencies", out var deps) && deps.ValueKind == JsonValueKind.Object)
                    foreach (var dep in deps.EnumerateObject())
                        declared[dep.Name] = dep.Value.ValueKind == JsonValueKind.String ? dep.Value.GetString() : dep.Value.ToString();

            foreach (var pair in needed)
            {
                if (!declared.TryGetValue(pair.Key, out var version))
                    problems.Add($"package.json: missing dependency \"{pair.Key}\": \"{UnityModuleTable.BuiltInModuleVersion}\" " +
                                 $"(uses {string.Join(", ", pair.Value)})");
                else if (version != UnityModuleTable.BuiltInModuleVersion)
                    problems.Add($"package.json: dependency {pair.Key} is '{version}', Unity 2022.3 has " +
                                 UnityModuleTable.BuiltInModuleVersion);
            }
            foreach (var name in declared.Keys.Where(n => n.StartsWith(ModulePrefix, StringComparison.Ordinal) && !needed.ContainsKey(n)))
                problems.Add($"package.json: dependency {name} is declared but no package code uses its module");
            return problems;
        }

        string CopyManifest(Func<string, string> edit)
        {
            var path = Path.Combine(_dir, "package.json");
            var original = File.ReadAllText(Path.Combine(PackageRoot.Path, "package.json"));
            var edited = edit(original);
            Assert.That(edited, Is.Not.EqualTo(original), "the planted defect did not change package.json");
            File.WriteAllText(path, edited);
            return path;
        }

        [Test]
        public void PackageDeclaresExactlyTheModulesItsCodeUses()
        {
            var problems = Problems(Path.Combine(PackageRoot.Path, "package.json"), Used, Serialized);
            Assert.That(problems, Is.Empty, string.Join("\n", problems));
        }

        [Test]
        public void UsageCoversRuntimeEditorAndSamples()
        {
            // The collector sees each part: physics from the runtime, IMGUI from the editor, sample-only types.
            Assert.That(Used["UnityEngine.Rigidbody"], Has.Some.StartsWith("Runtime/"));
            Assert.That(Used["UnityEngine.Physics"], Has.Some.StartsWith("Runtime/"));
            Assert.That(Used["UnityEngine.GUILayout"], Has.Some.StartsWith("Editor/"));
            Assert.That(Used["UnityEditor.Editor"], Has.Some.StartsWith("Editor/"));
            Assert.That(Used["UnityEngine.RigidbodyConstraints"], Has.Some.StartsWith("Samples~/"));
        }

        [Test]
        public void TableModulesAreListedWithASource()
        {
            foreach (var module in UnityModuleTable.Types.Values.Distinct())
            {
                Assert.That(UnityModuleTable.Modules, Has.Member(module));
                Assert.That(module.Source, Does.StartWith("https://docs.unity3d.com/2022.3/"));
                if (module.Package != null) Assert.That(module.Package, Does.StartWith(ModulePrefix));
            }
        }

        [Test]
        public void ManifestWithoutPhysicsIsReported()
        {
            var path = CopyManifest(t => t.Replace("\"com.unity.modules.physics\": \"1.0.0\",", "")
                                          .Replace(",\n    \"com.unity.modules.physics\": \"1.0.0\"", "")
                                          .Replace("\"com.unity.modules.physics\": \"1.0.0\"", ""));
            Assert.That(Problems(path, Used, Serialized),
                Has.Some.Contains("missing dependency \"com.unity.modules.physics\"").And.Some.Contains("UnityEngine.Rigidbody"));
        }

        [Test]
        public void WrongModuleVersionIsReported()
        {
            var path = CopyManifest(t => t.Replace("\"com.unity.modules.physics\": \"1.0.0\"", "\"com.unity.modules.physics\": \"2.0.0\""));
            Assert.That(Problems(path, Used, Serialized), Has.Some.Contains("com.unity.modules.physics is '2.0.0'"));
        }

        [Test]
        public void UnusedModuleIsReported()
        {
            var path = CopyManifest(t => t.Replace("\"dependencies\": {", "\"dependencies\": {\n    \"com.unity.modules.animation\": \"1.0.0\","));
            Assert.That(Problems(path, Used, Serialized), Has.Some.Contains("com.unity.modules.animation is declared but no package code uses"));
        }

        [Test]
        public void UnknownUnityTypeIsReported()
        {
            var used = new SortedDictionary<string, SortedSet<string>>(Used, StringComparer.Ordinal)
            {
                ["UnityEngine.ParticleSystem"] = new SortedSet<string> { "Runtime/Planted.cs" },
            };
            Assert.That(Problems(Path.Combine(PackageRoot.Path, "package.json"), used, Serialized),
                Has.Some.Contains("unknown Unity type UnityEngine.ParticleSystem (used in Runtime/Planted.cs)"));
        }

        [Test]
        public void UnknownSerializedClassIsReported()
        {
            var serialized = new SortedDictionary<string, SortedSet<string>>(Serialized, StringComparer.Ordinal)
            {
                ["Animator"] = new SortedSet<string> { "Samples~/Planted.unity" },
            };
            Assert.That(Problems(Path.Combine(PackageRoot.Path, "package.json"), Used, serialized),
                Has.Some.Contains("unknown serialized class Animator (used in Samples~/Planted.unity)"));
        }

        [Test]
        public void SerializedScanFindsTheSampleScenesAudioListener()
        {
            Assert.That(Serialized["AudioListener"], Has.Some.StartsWith("Samples~/").And.Some.EndsWith(".unity"));
            Assert.That(Serialized["MeshRenderer"], Has.Some.StartsWith("Runtime/Prefabs/"));
        }

        [Test]
        public void CollectorFindsAPlantedUse()
        {
            // A copy of the package with a runtime file that reaches the physics module only through members: the
            // text never names Rigidbody (a textual scan would miss it; the semantic one must not).
            var copy = Path.Combine(_dir, "pkg");
            foreach (var folder in new[] { "Runtime", "Editor", "Samples~" })
                CopyTree(Path.Combine(PackageRoot.Path, folder), Path.Combine(copy, folder));
            File.WriteAllText(Path.Combine(copy, "Runtime", "Planted.cs"),
                "namespace HookeRope { static class Planted { static float Probe(RopeEnd end) => end.Body.mass; } }");
            var used = UnityTypeUsage.Collect(copy);
            Assert.That(used["UnityEngine.Rigidbody"], Has.Member("Runtime/Planted.cs"));
        }

        static void CopyTree(string from, string to)
        {
            if (!Directory.Exists(from)) return;
            Directory.CreateDirectory(to);
            foreach (var file in Directory.EnumerateFiles(from)) File.Copy(file, Path.Combine(to, Path.GetFileName(file)));
            foreach (var dir in Directory.EnumerateDirectories(from)) CopyTree(dir, Path.Combine(to, Path.GetFileName(dir)));
        }
    }
}
