using System;
using System.Collections.Generic;
using System.IO;
using System.Runtime.CompilerServices;
using System.Text.RegularExpressions;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: where a UPM package's files are. Finds the package root of a file (the nearest folder up
    /// with a package.json), and the root of a package by name (HOOKEROPE_PACKAGE_ROOT, then the folders above the
    /// test assembly, the stand-in assembly, the working directory and, last, this source file's folder as it was when
    /// compiled — the stand-in is built from the package's own Tools~), for Unity's "Packages/&lt;name&gt;/" paths.
    /// </summary>
    internal static class PackageFiles
    {
        static readonly Regex NameField = new Regex("\"name\"\\s*:\\s*\"([^\"]+)\"");

        /// <summary>The "name" of the package.json in <paramref name="folder"/>, or null.</summary>
        internal static string PackageName(string folder)
        {
            string manifest = Path.Combine(folder, "package.json");
            if (!File.Exists(manifest)) return null;
            var match = NameField.Match(File.ReadAllText(manifest));
            return match.Success ? match.Groups[1].Value : null;
        }

        /// <summary>The nearest folder at or above <paramref name="path"/>'s folder holding a package.json, or null.</summary>
        internal static string RootOf(string path)
        {
            for (var dir = new FileInfo(Path.GetFullPath(path)).Directory; dir != null; dir = dir.Parent)
                if (File.Exists(Path.Combine(dir.FullName, "package.json"))) return dir.FullName;
            return null;
        }

        /// <summary>The root folder of the package named <paramref name="name"/>, or null when it cannot be found.</summary>
        internal static string FindPackage(string name)
        {
            string fromEnvironment = Environment.GetEnvironmentVariable("HOOKEROPE_PACKAGE_ROOT");
            if (!string.IsNullOrEmpty(fromEnvironment) && Directory.Exists(fromEnvironment) && PackageName(fromEnvironment) == name)
                return Path.GetFullPath(fromEnvironment);
            var starts = new List<string> { AppContext.BaseDirectory, Path.GetDirectoryName(typeof(PackageFiles).Assembly.Location), Environment.CurrentDirectory, SourceFolder() };
            foreach (var start in starts)
            {
                if (string.IsNullOrEmpty(start)) continue;
                for (var dir = new DirectoryInfo(start); dir != null; dir = dir.Parent)
                    if (PackageName(dir.FullName) == name) return dir.FullName;
            }
            return null;
        }

        static string SourceFolder([CallerFilePath] string path = "") => string.IsNullOrEmpty(path) ? null : Path.GetDirectoryName(path);
    }
}
