using System;
using System.IO;

namespace HookeRope.Tests.Lint
{
    /// <summary>Finds the package root (the folder holding package.json) above the test assembly.</summary>
    static class PackageRoot
    {
        /// <summary>Absolute path of the package root.</summary>
        public static string Path { get; } = Find();

        static string Find()
        {
            var dir = new DirectoryInfo(AppContext.BaseDirectory);
            while (dir != null)
            {
                var manifest = System.IO.Path.Combine(dir.FullName, "package.json");
                if (File.Exists(manifest) && File.ReadAllText(manifest).Contains("\"com.hookerope.elastic-rope\""))
                    return dir.FullName;
                dir = dir.Parent;
            }
            throw new InvalidOperationException("package.json of com.hookerope.elastic-rope not found above " + AppContext.BaseDirectory);
        }
    }
}
