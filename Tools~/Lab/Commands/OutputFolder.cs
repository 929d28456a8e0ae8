using System.IO;

namespace HookeRope.Lab.Commands
{
    /// <summary>The <c>--out</c> folder: created when missing; a file of that name is a usage error naming the path.</summary>
    public static class OutputFolder
    {
        /// <summary>Creates <paramref name="path"/> when missing; throws <see cref="UsageException"/> when it (or a parent) is a file.</summary>
        public static void Ensure(string path)
        {
            if (string.IsNullOrWhiteSpace(path)) throw new UsageException("--out: empty folder name");
            for (var dir = new DirectoryInfo(Path.GetFullPath(path)); dir != null; dir = dir.Parent)
            {
                if (File.Exists(dir.FullName))
                    throw new UsageException($"--out: \"{dir.FullName}\" is a file, not a folder; give a folder for the output files");
                if (Directory.Exists(dir.FullName)) break;
            }
            Directory.CreateDirectory(path);
        }
    }
}
