using System.IO;
using NUnit.Framework;

namespace HookeRope.Lab.Tests
{
    /// <summary>Base of tests that write files: each test gets a fresh folder under the temp path, removed afterwards.</summary>
    public abstract class TempFolderTest
    {
        /// <summary>The current test's output folder.</summary>
        protected string dir;

        [SetUp]
        public void CreateFolder()
        {
            dir = Path.Combine(Path.GetTempPath(), "hookerope-lab-" + System.Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
        }

        /// <summary>Runs the lab's command line with plain consoles; returns the exit code, stdout and stderr.</summary>
        protected static int InvokeLab(out string output, out string error, params string[] args)
        {
            var o = new StringWriter();
            var e = new StringWriter();
            int code = HookeRope.Lab.Commands.LabCli.Invoke(args, HookeRope.Lab.Commands.LabConsole.Plain(o), o, e);
            output = o.ToString();
            error = e.ToString();
            return code;
        }

        [TearDown]
        public void DeleteFolder()
        {
            if (Directory.Exists(dir)) Directory.Delete(dir, true);
        }
    }
}
