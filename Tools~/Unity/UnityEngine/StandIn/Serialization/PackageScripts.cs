using System;
using System.Collections.Generic;
using System.IO;
using System.Text.RegularExpressions;
using UnityEngine;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: resolves a MonoBehaviour's m_Script {fileID: 11500000, guid: …} the way Unity's MonoScript
    /// does: the guid names a .cs file through its .meta, and the script class is the class named like the file in
    /// the loaded assemblies. Only the package's imported folders (Runtime, Editor, Tests, Samples~) are searched.
    /// </summary>
    internal static class PackageScripts
    {
        static readonly Regex GuidLine = new Regex(@"^guid:\s*([0-9a-fA-F]{32})\s*$", RegexOptions.Multiline);
        static readonly string[] ImportedFolders = { "Runtime", "Editor", "Tests", "Samples~" };
        static readonly Dictionary<string, Dictionary<string, string>> s_Scripts = new Dictionary<string, Dictionary<string, string>>();

        /// <summary>The .cs file of <paramref name="guid"/> in the package at <paramref name="packageRoot"/>, or null.</summary>
        internal static string ScriptFile(string packageRoot, string guid)
        {
            Dictionary<string, string> scripts;
            lock (s_Scripts)
            {
                if (!s_Scripts.TryGetValue(packageRoot, out scripts))
                {
                    scripts = Scan(packageRoot);
                    s_Scripts[packageRoot] = scripts;
                }
            }
            return scripts.TryGetValue(guid.ToLowerInvariant(), out var file) ? file : null;
        }

        /// <summary>The loaded script classes (MonoBehaviour or ScriptableObject) named <paramref name="className"/>.</summary>
        internal static List<Type> Classes(string className)
        {
            var found = new List<Type>();
            foreach (var type in ScriptAssemblies.Types())
                if (type.Name == className && (typeof(MonoBehaviour).IsAssignableFrom(type) || typeof(ScriptableObject).IsAssignableFrom(type)))
                    found.Add(type);
            return found;
        }

        static Dictionary<string, string> Scan(string root)
        {
            var scripts = new Dictionary<string, string>();
            foreach (string folder in ImportedFolders)
            {
                string path = Path.Combine(root, folder);
                if (!Directory.Exists(path)) continue;
                foreach (string meta in Directory.EnumerateFiles(path, "*.cs.meta", SearchOption.AllDirectories))
                {
                    var match = GuidLine.Match(File.ReadAllText(meta));
                    if (match.Success) scripts[match.Groups[1].Value.ToLowerInvariant()] = meta.Substring(0, meta.Length - ".meta".Length);
                }
            }
            return scripts;
        }
    }
}
