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

        [TearDown]
        public void DeleteFolder()
        {
            if (Directory.Exists(dir)) Directory.Delete(dir, true);
        }
    }
}
