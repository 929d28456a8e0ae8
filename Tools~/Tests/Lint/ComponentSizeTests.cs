using System.IO;
using NUnit.Framework;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// Issue 12: ElasticRope.cs stays a file a reader takes in at once (build, step, read-outs). Its settings live in
    /// ElasticRope.Settings.cs, the coupling in RopeAttachmentBinding and RopeColliderBinding, the preview in the editor.
    /// </summary>
    [TestFixture]
    public sealed class ComponentSizeTests
    {
        const int MaxLines = 400;

        [Test]
        public void ElasticRopeStaysSmall()
        {
            int lines = File.ReadAllLines(Path.Combine(PackageRoot.Path, "Runtime", "ElasticRope.cs")).Length;
            TestContext.WriteLine("Runtime/ElasticRope.cs: " + lines + " lines");
            Assert.That(lines, Is.LessThan(MaxLines), "move settings, coupling or helpers out of ElasticRope.cs");
        }
    }
}
