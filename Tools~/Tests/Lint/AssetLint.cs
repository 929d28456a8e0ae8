using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.Json;
using System.Text.RegularExpressions;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// The checks Unity itself would trip on in an immutable (git or registry) install, run on a
    /// package folder without an Editor. Each method returns one line per problem, naming the path.
    /// </summary>
    public sealed class AssetLint
    {
        /// <summary>Folders whose contents Unity imports (or copies on sample import), each needing metas.</summary>
        static readonly string[] ImportedRoots = { "Runtime", "Editor", "Tests", "Samples~" };

        /// <summary>GUIDs of Unity's built-in resources (meshes, default material, shaders).</summary>
        static readonly HashSet<string> BuiltInGuids = new HashSet<string>
        {
            "0000000000000000e000000000000000", // built-in meshes (Cube 10202, Sphere 10207, …)
            "0000000000000000f000000000000000", // built-in extras (Default-Material 10303, Standard shader 46)
        };

        /// <summary>Assemblies outside the package that an asmdef may reference by name.</summary>
        static readonly HashSet<string> KnownUnityAssemblies = new HashSet<string>
        {
            "UnityEngine.TestRunner", "UnityEditor.TestRunner",
        };

        /// <summary>GUIDs of the Unity Test Framework asmdefs, for "GUID:" style references.</summary>
        static readonly HashSet<string> KnownUnityAssemblyGuids = new HashSet<string>
        {
            "0acc523941302664db1f4e527237feb3", // UnityEngine.TestRunner
            "27619889b8ba8c24980f49ee34dbb44a", // UnityEditor.TestRunner
        };

        static readonly Regex GuidLine = new Regex(@"^guid: (\S*)\s*$", RegexOptions.Multiline);
        static readonly Regex GuidFormat = new Regex("^[0-9a-f]{32}$");
        static readonly Regex YamlGuidReference = new Regex(@"guid: ([0-9A-Za-z]+)");
        static readonly Regex PackageName = new Regex(@"^[a-z0-9][a-z0-9\-_]*(\.[a-z0-9\-_]+){2,}$");
        static readonly Regex SemVer = new Regex(@"^\d+\.\d+\.\d+(-[0-9A-Za-z\-.]+)?(\+[0-9A-Za-z\-.]+)?$");

        readonly string _root;

        /// <summary>Lints the package whose package.json sits in <paramref name="packageRoot"/>.</summary>
        public AssetLint(string packageRoot)
        {
            _root = Path.GetFullPath(packageRoot);
        }

        /// <summary>Every check at once.</summary>
        public List<string> All()
        {
            var problems = new List<string>();
            problems.AddRange(MissingMetas());
            problems.AddRange(OrphanMetas());
            problems.AddRange(MalformedMetas());
            problems.AddRange(DuplicateGuids());
            problems.AddRange(DanglingAssetReferences());
            problems.AddRange(AsmdefProblems());
            problems.AddRange(ScriptsOutsideAsmdef());
            problems.AddRange(PackageManifestProblems());
            problems.AddRange(MetasInIgnoredFolders());
            return problems;
        }

        /// <summary>Imported files and folders without a sibling .meta.</summary>
        public IEnumerable<string> MissingMetas()
        {
            foreach (var path in ImportedPaths())
                if (!File.Exists(path + ".meta"))
                    yield return $"missing meta: {Rel(path)}";
        }

        /// <summary>.meta files whose asset does not exist.</summary>
        public IEnumerable<string> OrphanMetas()
        {
            foreach (var meta in ImportedMetas())
            {
                var asset = meta.Substring(0, meta.Length - ".meta".Length);
                if (!File.Exists(asset) && !Directory.Exists(asset))
                    yield return $"orphan meta: {Rel(meta)}";
            }
        }

        /// <summary>Metas that are not "fileFormatVersion: 2" plus a 32-lowercase-hex GUID, or mark a folder wrongly.</summary>
        public IEnumerable<string> MalformedMetas()
        {
            foreach (var meta in ImportedMetas())
            {
                var text = File.ReadAllText(meta);
                if (!text.StartsWith("fileFormatVersion: 2\n", StringComparison.Ordinal))
                    yield return $"malformed meta (first line must be 'fileFormatVersion: 2'): {Rel(meta)}";
                var match = GuidLine.Match(text);
                if (!match.Success || !GuidFormat.IsMatch(match.Groups[1].Value))
                    yield return $"malformed meta (guid must be 32 lowercase hex digits): {Rel(meta)}";
                var asset = meta.Substring(0, meta.Length - ".meta".Length);
                bool isFolder = Directory.Exists(asset);
                bool saysFolder = text.Contains("\nfolderAsset: yes");
                if (isFolder != saysFolder && (isFolder || File.Exists(asset)))
                    yield return $"malformed meta (folderAsset must be set exactly for folders): {Rel(meta)}";
            }
        }

        /// <summary>GUIDs that appear in more than one meta.</summary>
        public IEnumerable<string> DuplicateGuids()
        {
            return GuidsByMeta()
                .GroupBy(pair => pair.Value)
                .Where(group => group.Count() > 1)
                .Select(group => $"duplicate guid {group.Key}: " + string.Join(", ", group.Select(p => Rel(p.Key)).OrderBy(s => s)));
        }

        /// <summary>guid references in prefabs, scenes, materials and assets that resolve to nothing.</summary>
        public IEnumerable<string> DanglingAssetReferences()
        {
            var known = new HashSet<string>(GuidsByMeta().Values);
            known.UnionWith(BuiltInGuids);
            foreach (var file in ImportedFiles())
            {
                var ext = Path.GetExtension(file);
                if (ext != ".prefab" && ext != ".unity" && ext != ".asset" && ext != ".mat")
                    continue;
                foreach (Match m in YamlGuidReference.Matches(File.ReadAllText(file)))
                    if (!known.Contains(m.Groups[1].Value))
                        yield return $"dangling guid {m.Groups[1].Value} in {Rel(file)}";
            }
        }

        /// <summary>asmdefs that do not parse, lack a name, repeat a name, or reference an unknown assembly.</summary>
        public IEnumerable<string> AsmdefProblems()
        {
            var asmdefs = ImportedFiles().Where(f => f.EndsWith(".asmdef", StringComparison.Ordinal)).ToList();
            var names = new Dictionary<string, string>();
            var guids = new HashSet<string>(KnownUnityAssemblyGuids);
            var parsed = new List<(string File, JsonElement Json)>();
            foreach (var file in asmdefs)
            {
                JsonElement json;
                string error = null;
                try { json = JsonDocument.Parse(File.ReadAllText(file)).RootElement.Clone(); }
                catch (JsonException e) { json = default; error = e.Message; }
                if (error != null) { yield return $"asmdef does not parse: {Rel(file)}: {error}"; continue; }
                if (!json.TryGetProperty("name", out var name) || name.ValueKind != JsonValueKind.String)
                {
                    yield return $"asmdef has no name: {Rel(file)}";
                    continue;
                }
                if (names.ContainsKey(name.GetString()))
                    yield return $"asmdef name {name.GetString()} used twice: {Rel(file)}";
                names[name.GetString()] = file;
                var metaGuid = GuidOf(file + ".meta");
                if (metaGuid != null) guids.Add(metaGuid);
                parsed.Add((file, json));
            }
            foreach (var (file, json) in parsed)
            {
                if (!json.TryGetProperty("references", out var refs)) continue;
                foreach (var r in refs.EnumerateArray())
                {
                    var reference = r.GetString() ?? "";
                    bool ok = reference.StartsWith("GUID:", StringComparison.Ordinal)
                        ? guids.Contains(reference.Substring(5))
                        : names.ContainsKey(reference) || KnownUnityAssemblies.Contains(reference);
                    if (!ok) yield return $"asmdef reference '{reference}' resolves to nothing: {Rel(file)}";
                }
            }
        }

        /// <summary>C# files that no asmdef covers: Unity would not compile them inside a package.</summary>
        public IEnumerable<string> ScriptsOutsideAsmdef()
        {
            foreach (var file in ImportedFiles())
            {
                if (!file.EndsWith(".cs", StringComparison.Ordinal) || IsInSamples(file)) continue;
                var dir = Path.GetDirectoryName(file);
                bool covered = false;
                while (dir != null && dir.Length >= _root.Length)
                {
                    if (Directory.EnumerateFiles(dir, "*.asmdef").Any()) { covered = true; break; }
                    dir = Path.GetDirectoryName(dir);
                }
                if (!covered) yield return $"script outside every asmdef: {Rel(file)}";
            }
        }

        /// <summary>package.json: parses, has the required and recommended fields, and valid samples.</summary>
        public IEnumerable<string> PackageManifestProblems()
        {
            var path = Path.Combine(_root, "package.json");
            if (!File.Exists(path)) { yield return "package.json is missing"; yield break; }
            JsonElement json;
            string error = null;
            try { json = JsonDocument.Parse(File.ReadAllText(path)).RootElement.Clone(); }
            catch (JsonException e) { json = default; error = e.Message; }
            if (error != null) { yield return $"package.json does not parse: {error}"; yield break; }

            foreach (var field in new[] { "name", "version", "displayName", "description", "unity" })
                if (!json.TryGetProperty(field, out var v) || v.ValueKind != JsonValueKind.String || v.GetString().Length == 0)
                    yield return $"package.json: '{field}' must be a non-empty string";
            if (json.TryGetProperty("name", out var n) && n.ValueKind == JsonValueKind.String)
            {
                var name = n.GetString();
                if (!PackageName.IsMatch(name) || name.StartsWith("com.unity", StringComparison.Ordinal) || name.Contains("unity"))
                    yield return $"package.json: name '{name}' must be reverse-domain lowercase and must not contain 'unity'";
            }
            if (json.TryGetProperty("version", out var ver) && ver.ValueKind == JsonValueKind.String && !SemVer.IsMatch(ver.GetString()))
                yield return $"package.json: version '{ver.GetString()}' is not SemVer MAJOR.MINOR.PATCH";
            if (json.TryGetProperty("dependencies", out var deps))
                foreach (var dep in deps.EnumerateObject())
                    if (dep.Value.ValueKind != JsonValueKind.String || !SemVer.IsMatch(dep.Value.GetString()))
                        yield return $"package.json: dependency '{dep.Name}' needs an exact SemVer version";
            if (json.TryGetProperty("samples", out var samples))
            {
                foreach (var sample in samples.EnumerateArray())
                {
                    var p = sample.TryGetProperty("path", out var sp) ? sp.GetString() ?? "" : "";
                    var label = sample.TryGetProperty("displayName", out var dn) ? dn.GetString() : "(no displayName)";
                    if (!p.StartsWith("Samples~/", StringComparison.Ordinal))
                        yield return $"package.json: sample '{label}' path '{p}' must start with Samples~/";
                    else if (!Directory.Exists(Path.Combine(_root, p)))
                        yield return $"package.json: sample '{label}' path '{p}' does not exist";
                }
            }
        }

        /// <summary>Metas in folders Unity never imports (Documentation~, the headless tools).</summary>
        public IEnumerable<string> MetasInIgnoredFolders()
        {
            foreach (var dir in Directory.EnumerateDirectories(_root))
            {
                var name = Path.GetFileName(dir);
                if (!name.EndsWith("~", StringComparison.Ordinal) || name == "Samples~") continue;
                foreach (var meta in Directory.EnumerateFiles(dir, "*.meta", SearchOption.AllDirectories))
                    if (!IsBuildOutput(meta))
                        yield return $"meta in a folder Unity ignores: {Rel(meta)}";
            }
        }

        IEnumerable<string> ImportedPaths()
        {
            foreach (var entry in Directory.EnumerateFileSystemEntries(_root))
            {
                var name = Path.GetFileName(entry);
                if (name.EndsWith(".meta", StringComparison.Ordinal) || IsIgnoredName(name)) continue;
                yield return entry;
            }
            foreach (var top in ImportedRoots)
            {
                var dir = Path.Combine(_root, top);
                if (!Directory.Exists(dir)) continue;
                foreach (var entry in Walk(dir))
                    if (!entry.EndsWith(".meta", StringComparison.Ordinal))
                        yield return entry;
            }
        }

        IEnumerable<string> ImportedFiles() => ImportedPaths().Where(File.Exists);

        IEnumerable<string> ImportedMetas()
        {
            foreach (var entry in Directory.EnumerateFiles(_root, "*.meta"))
                yield return entry;
            foreach (var top in ImportedRoots)
            {
                var dir = Path.Combine(_root, top);
                if (!Directory.Exists(dir)) continue;
                foreach (var entry in Walk(dir))
                    if (entry.EndsWith(".meta", StringComparison.Ordinal))
                        yield return entry;
            }
        }

        Dictionary<string, string> GuidsByMeta()
        {
            var result = new Dictionary<string, string>();
            foreach (var meta in ImportedMetas())
            {
                var guid = GuidOf(meta);
                if (guid != null) result[meta] = guid;
            }
            return result;
        }

        static string GuidOf(string meta)
        {
            if (!File.Exists(meta)) return null;
            var m = GuidLine.Match(File.ReadAllText(meta));
            return m.Success ? m.Groups[1].Value : null;
        }

        /// <summary>Depth-first walk that skips what Unity skips: hidden names and names ending in '~'.</summary>
        static IEnumerable<string> Walk(string dir)
        {
            foreach (var entry in Directory.EnumerateFileSystemEntries(dir).OrderBy(e => e, StringComparer.Ordinal))
            {
                if (IsIgnoredName(Path.GetFileName(entry))) continue;
                yield return entry;
                if (Directory.Exists(entry))
                    foreach (var inner in Walk(entry))
                        yield return inner;
            }
        }

        static bool IsIgnoredName(string name) =>
            name.StartsWith(".", StringComparison.Ordinal) || name.EndsWith("~", StringComparison.Ordinal) ||
            name.EndsWith(".tmp", StringComparison.Ordinal) || name.Equals("cvs", StringComparison.OrdinalIgnoreCase);

        static bool IsBuildOutput(string path) =>
            path.Contains($"{Path.DirectorySeparatorChar}.artifacts") ||
            path.Contains($"{Path.DirectorySeparatorChar}bin{Path.DirectorySeparatorChar}") ||
            path.Contains($"{Path.DirectorySeparatorChar}obj{Path.DirectorySeparatorChar}");

        bool IsInSamples(string path) => Rel(path).StartsWith("Samples~/", StringComparison.Ordinal);

        string Rel(string path) => Path.GetRelativePath(_root, path).Replace('\\', '/');
    }
}
