using System.IO;
using System.Linq;
using NUnit.Framework;

namespace HookeRope.Tests.Lint
{
    /// <summary>
    /// The sample scenes (Samples~/*/*.unity) are in the format Unity 2022.3 saves (<see cref="SceneFormat"/>), and the
    /// check finds each kind of older or broken file (a doctored copy of a sample).
    /// </summary>
    [TestFixture]
    public sealed class SceneFormatTests
    {
        static string[] Scenes() => Directory.GetFiles(Path.Combine(PackageRoot.Path, "Samples~"), "*.unity", SearchOption.AllDirectories)
            .OrderBy(f => f, System.StringComparer.Ordinal).ToArray();

        static string Sample => File.ReadAllText(Scenes()[0]).Replace("\r\n", "\n");

        [Test]
        public void SampleScenesAreIn2022_3Format()
        {
            var scenes = Scenes();
            Assert.That(scenes.Length, Is.EqualTo(4), "CollisionBend, FallArrest, NeckingAndFracture, PoissonSweep");
            foreach (var scene in scenes)
                Assert.That(SceneFormat.Problems(Path.GetFileName(scene), File.ReadAllText(scene).Replace("\r\n", "\n")), Is.Empty);
        }

        [Test]
        public void EverySampleListsItsThreeRootsInSceneRoots()
        {
            foreach (var scene in Scenes())
            {
                var docs = SceneFormat.Parse(File.ReadAllText(scene).Replace("\r\n", "\n"));
                var roots = docs.Last();
                Assert.That(roots.ClassId, Is.EqualTo(SceneFormat.SceneRootsClass), scene);
                Assert.That(roots.Body.Split('\n').Count(l => l.StartsWith("  - {fileID: ", System.StringComparison.Ordinal)), Is.EqualTo(3),
                    scene + ": Main Camera, Directional Light, Bootstrap");
            }
        }

        [TestCase("  serializedVersion: 2\n  m_LocalRotation", "  m_LocalRotation", "must be serializedVersion 2")]
        [TestCase("  m_Father: {fileID: 0}\n", "  m_Father: {fileID: 0}\n  m_RootOrder: 0\n", "has m_RootOrder")]
        [TestCase("    serializedVersion: 3\n    agentTypeID", "    serializedVersion: 2\n    agentTypeID", "m_BuildSettings must be serializedVersion 3")]
        [TestCase("    buildHeightMesh: 0\n", "    accuratePlacement: 0\n", "lacks buildHeightMesh")]
        [TestCase("RenderSettings:\n  m_ObjectHideFlags: 0\n  serializedVersion: 9", "RenderSettings:\n  m_ObjectHideFlags: 0\n  serializedVersion: 10", "RenderSettings serializedVersion 10")]
        [TestCase("  m_Iso: 200\n", "", "Camera &")]
        [TestCase("OcclusionCullingSettings:\n  m_ObjectHideFlags: 0\n", "OcclusionCullingSettings:\n", "lacks m_ObjectHideFlags")]
        public void OlderOrBrokenFormIsFound(string from, string to, string expected)
        {
            string text = Sample;
            Assert.That(text, Does.Contain(from));
            var problems = SceneFormat.Problems("doctored", ReplaceFirst(text, from, to));
            Assert.That(problems.Any(p => p.Contains(expected)), Is.True, string.Join("\n", problems));
        }

        [Test]
        public void MissingOrWrongSceneRootsIsFound()
        {
            string text = Sample;
            int at = text.IndexOf("--- !u!1660057539", System.StringComparison.Ordinal);
            Assert.That(SceneFormat.Problems("none", text.Substring(0, at)), Has.Some.Contains("0 SceneRoots"));

            var docs = SceneFormat.Parse(text);
            string firstRoot = docs.Last().Body.Split('\n').First(l => l.StartsWith("  - ", System.StringComparison.Ordinal));
            var dropped = SceneFormat.Problems("dropped", text.Replace(firstRoot + "\n", ""));
            Assert.That(dropped, Has.Some.Contains("is missing from SceneRoots"));
            var extra = SceneFormat.Problems("extra", text + "  - {fileID: 42}\n");
            Assert.That(extra, Has.Some.Contains("SceneRoots lists &42"));
        }

        static string ReplaceFirst(string text, string from, string to)
        {
            int i = text.IndexOf(from, System.StringComparison.Ordinal);
            return text.Substring(0, i) + to + text.Substring(i + from.Length);
        }
    }
}
