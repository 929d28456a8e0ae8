using System;
using System.IO;

namespace HookeRope.StandIn
{
    /// <summary>
    /// Not part of Unity: maps Unity asset paths to files. The stand-in has no project, only this package: a path
    /// "Packages/&lt;name&gt;/…" with the name of a package that can be found (<see cref="PackageFiles.FindPackage"/>)
    /// maps into that package's folder; "Assets/…" and other packages are outside the stand-in.
    /// </summary>
    internal static class AssetPaths
    {
        const string Packages = "Packages/";

        /// <summary>The file of <paramref name="assetPath"/>; throws for paths outside the packages the stand-in can find.</summary>
        internal static string ToFile(string assetPath, string member)
        {
            if (!assetPath.StartsWith(Packages, StringComparison.Ordinal))
                throw StandInError.Unsupported(member + " of '" + assetPath + "' (the stand-in has no project: only 'Packages/<package name>/…' paths resolve)");
            int slash = assetPath.IndexOf('/', Packages.Length);
            string name = slash < 0 ? assetPath.Substring(Packages.Length) : assetPath.Substring(Packages.Length, slash - Packages.Length);
            string root = PackageFiles.FindPackage(name);
            if (root == null)
                throw StandInError.Unsupported(member + " of '" + assetPath + "': package '" + name + "' not found (set HOOKEROPE_PACKAGE_ROOT)");
            string relative = slash < 0 ? "" : assetPath.Substring(slash + 1);
            foreach (string segment in relative.Split('/'))
                if (segment.Length == 0 || segment == "." || segment == ".." || segment.Contains("\\"))
                    throw new ArgumentException("malformed asset path '" + assetPath + "'", nameof(assetPath));
            return Path.Combine(root, relative.Replace('/', Path.DirectorySeparatorChar));
        }
    }
}
