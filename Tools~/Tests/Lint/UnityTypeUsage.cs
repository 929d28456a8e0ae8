using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// Collects, by semantic analysis, every UnityEngine* / UnityEditor* type the package's shipped Unity code names
    /// or touches: the runtime assembly (Runtime/ outside Runtime/Core) as the Editor and as a player compile it, the
    /// editor assembly (Editor/) and the samples (Samples~/, shipped with the package). The sources are compiled with
    /// Roslyn against the stand-in assemblies exactly like the check projects in Tools~/Unity/Check; every type
    /// symbol, every member's declaring type, every expression's type (and generic arguments, array elements, base
    /// types of the package's own classes) is recorded.
    /// </summary>
    static class UnityTypeUsage
    {
        /// <summary>A Unity type (full metadata name, e.g. "UnityEngine.Rigidbody") and the package files using it.</summary>
        public static SortedDictionary<string, SortedSet<string>> Collect(string packageRoot)
        {
            var used = new SortedDictionary<string, SortedSet<string>>(StringComparer.Ordinal);
            var baseRefs = References();

            var runtimeFiles = Sources(packageRoot, "Runtime", exclude: Path.Combine("Runtime", "Core") + Path.DirectorySeparatorChar);
            var editorFiles = Sources(packageRoot, "Editor");
            var sampleFiles = Sources(packageRoot, "Samples~");

            var runtimeInEditor = Compile("HookeRope", packageRoot, runtimeFiles, baseRefs, "UNITY_EDITOR");
            var runtimePlayer = Compile("HookeRope", packageRoot, runtimeFiles, baseRefs);
            var editor = Compile("HookeRope.Editor", packageRoot, editorFiles,
                baseRefs.Append(runtimeInEditor.ToMetadataReference()), "UNITY_EDITOR");
            var samples = Compile("HookeRope.Samples", packageRoot, sampleFiles,
                baseRefs.Append(runtimePlayer.ToMetadataReference()));

            foreach (var c in new[] { runtimeInEditor, runtimePlayer, editor, samples })
            {
                var errors = c.GetDiagnostics().Where(d => d.Severity == DiagnosticSeverity.Error).ToList();
                if (errors.Count > 0)
                    throw new InvalidOperationException(c.AssemblyName + " does not compile against the stand-in:\n" +
                                                        string.Join("\n", errors.Take(20)));
                Record(c, packageRoot, used);
            }
            return used;
        }

        /// <summary>
        /// Serialized classes in the YAML assets the package ships (scenes, prefabs, materials, assets under Runtime/,
        /// Editor/, Samples~/): the class name of each object ("--- !u!81 &amp;…" then "AudioListener:") and the files.
        /// </summary>
        public static SortedDictionary<string, SortedSet<string>> CollectSerialized(string packageRoot)
        {
            var used = new SortedDictionary<string, SortedSet<string>>(StringComparer.Ordinal);
            var extensions = new[] { ".unity", ".prefab", ".mat", ".asset", ".controller", ".physicMaterial" };
            foreach (var folder in new[] { "Runtime", "Editor", "Samples~" })
            {
                var dir = Path.Combine(packageRoot, folder);
                if (!Directory.Exists(dir)) continue;
                foreach (var file in Directory.EnumerateFiles(dir, "*", SearchOption.AllDirectories)
                             .Where(f => extensions.Contains(Path.GetExtension(f), StringComparer.OrdinalIgnoreCase)))
                {
                    var lines = File.ReadAllLines(file);
                    var relative = Path.GetRelativePath(packageRoot, file).Replace('\\', '/');
                    for (var i = 0; i + 1 < lines.Length; i++)
                    {
                        if (!lines[i].StartsWith("--- !u!", StringComparison.Ordinal)) continue;
                        var name = lines[i + 1].TrimEnd();
                        if (!name.EndsWith(":", StringComparison.Ordinal)) continue;
                        name = name.Substring(0, name.Length - 1);
                        if (!used.TryGetValue(name, out var files)) used[name] = files = new SortedSet<string>(StringComparer.Ordinal);
                        files.Add(relative);
                    }
                }
            }
            return used;
        }

        static IEnumerable<string> Sources(string root, string folder, string exclude = null)
        {
            var dir = Path.Combine(root, folder);
            if (!Directory.Exists(dir)) return Enumerable.Empty<string>();
            return Directory.EnumerateFiles(dir, "*.cs", SearchOption.AllDirectories)
                .Where(f => exclude == null || !Path.GetRelativePath(root, f).StartsWith(exclude, StringComparison.Ordinal))
                .OrderBy(f => f, StringComparer.Ordinal)
                .ToList();
        }

        static List<MetadataReference> References()
        {
            var paths = ((string)AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES"))
                .Split(Path.PathSeparator)
                .Where(p => p.Length > 0)
                .Concat(new[]
                {
                    typeof(UnityEngine.MonoBehaviour).Assembly.Location,
                    typeof(UnityEditor.Editor).Assembly.Location,
                    typeof(HookeRope.RopeSimulation).Assembly.Location,
                })
                .Select(Path.GetFullPath)
                .Distinct(StringComparer.Ordinal);
            return paths.Select(p => (MetadataReference)MetadataReference.CreateFromFile(p)).ToList();
        }

        static CSharpCompilation Compile(string name, string root, IEnumerable<string> files,
            IEnumerable<MetadataReference> references, params string[] extraDefines)
        {
            var options = new CSharpParseOptions(LanguageVersion.CSharp9,
                preprocessorSymbols: new[] { "UNITY_2022_3_OR_NEWER" }.Concat(extraDefines));
            var trees = files.Select(f => CSharpSyntaxTree.ParseText(File.ReadAllText(f), options,
                path: Path.GetRelativePath(root, f).Replace('\\', '/')));
            return CSharpCompilation.Create(name, trees, references,
                new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary));
        }

        static void Record(CSharpCompilation compilation, string root, IDictionary<string, SortedSet<string>> used)
        {
            foreach (var tree in compilation.SyntaxTrees)
            {
                var model = compilation.GetSemanticModel(tree);
                var file = tree.FilePath;
                foreach (var node in tree.GetRoot().DescendantNodes())
                {
                    var info = model.GetSymbolInfo(node);
                    AddSymbol(info.Symbol, file, used);
                    foreach (var candidate in info.CandidateSymbols) AddSymbol(candidate, file, used);
                    var type = model.GetTypeInfo(node);
                    AddType(type.Type, file, used);
                    AddType(type.ConvertedType, file, used);
                    var declared = model.GetDeclaredSymbol(node);
                    if (declared is INamedTypeSymbol own)
                    {
                        for (var b = own.BaseType; b != null; b = b.BaseType) AddType(b, file, used);
                        foreach (var i in own.AllInterfaces) AddType(i, file, used);
                    }
                    else if (declared != null)
                    {
                        AddSymbol(declared, file, used);
                    }
                }
            }
        }

        static void AddSymbol(ISymbol symbol, string file, IDictionary<string, SortedSet<string>> used)
        {
            switch (symbol)
            {
                case null:
                    return;
                case ITypeSymbol t:
                    AddType(t, file, used);
                    return;
                case IMethodSymbol m:
                    AddType(m.ContainingType, file, used);
                    AddType(m.ReturnType, file, used);
                    foreach (var p in m.Parameters) AddType(p.Type, file, used);
                    foreach (var a in m.TypeArguments) AddType(a, file, used);
                    return;
                case IPropertySymbol p:
                    AddType(p.ContainingType, file, used);
                    AddType(p.Type, file, used);
                    return;
                case IFieldSymbol f:
                    AddType(f.ContainingType, file, used);
                    AddType(f.Type, file, used);
                    return;
                case IEventSymbol e:
                    AddType(e.ContainingType, file, used);
                    AddType(e.Type, file, used);
                    return;
                case ILocalSymbol l:
                    AddType(l.Type, file, used);
                    return;
                case IParameterSymbol p:
                    AddType(p.Type, file, used);
                    return;
            }
        }

        static void AddType(ITypeSymbol type, string file, IDictionary<string, SortedSet<string>> used)
        {
            switch (type)
            {
                case null:
                    return;
                case IArrayTypeSymbol array:
                    AddType(array.ElementType, file, used);
                    return;
                case IPointerTypeSymbol pointer:
                    AddType(pointer.PointedAtType, file, used);
                    return;
                case INamedTypeSymbol named:
                    foreach (var a in named.TypeArguments) AddType(a, file, used);
                    if (named.ContainingType != null) AddType(named.ContainingType, file, used);
                    var def = named.OriginalDefinition;
                    var ns = def.ContainingNamespace?.ToDisplayString() ?? "";
                    if (!IsUnityNamespace(ns)) return;
                    var name = ns + "." + def.MetadataName;
                    for (var outer = def.ContainingType; outer != null; outer = outer.ContainingType)
                        name = ns + "." + outer.MetadataName + "+" + name.Substring(ns.Length + 1);
                    if (!used.TryGetValue(name, out var files)) used[name] = files = new SortedSet<string>(StringComparer.Ordinal);
                    files.Add(file);
                    return;
            }
        }

        static bool IsUnityNamespace(string ns) =>
            ns == "UnityEngine" || ns.StartsWith("UnityEngine.", StringComparison.Ordinal) ||
            ns == "UnityEditor" || ns.StartsWith("UnityEditor.", StringComparison.Ordinal);
    }
}
