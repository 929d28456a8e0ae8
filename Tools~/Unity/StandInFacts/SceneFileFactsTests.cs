using System.IO;
using System.Linq;
using NUnit.Framework;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// The stand-in's Unity YAML reader (the one that loads the package prefab) reads the sample scenes in their 2022.3
    /// form: every object, the settings objects with file IDs 1–4 and the SceneRoots object (class 1660057539, file ID
    /// 2^63 − 1) whose m_Roots references resolve to root Transforms of the same file.
    /// </summary>
    [TestFixture]
    public sealed class SceneFileFactsTests
    {
        [Test]
        public void SampleScenesParseWithSceneRootsOnRootTransforms()
        {
            string root = PackageFiles.FindPackage("com.hookerope.elastic-rope");
            Assert.That(root, Is.Not.Null);
            var scenes = Directory.GetFiles(Path.Combine(root, "Samples~"), "*.unity", SearchOption.AllDirectories);
            Assert.That(scenes.Length, Is.EqualTo(4));
            foreach (var scene in scenes)
            {
                var docs = UnityYamlParser.Parse(File.ReadAllText(scene), scene);
                Assert.That(docs.Count, Is.EqualTo(15), scene + ": 4 settings, 3 GameObjects, 3 Transforms, Camera, AudioListener, Light, bootstrap script, SceneRoots");
                Assert.That(docs.Take(4).Select(d => d.FileId), Is.EqualTo(new long[] { 1, 2, 3, 4 }));
                var sceneRoots = docs.Last();
                Assert.That(sceneRoots.ClassId, Is.EqualTo(1660057539));
                Assert.That(sceneRoots.FileId, Is.EqualTo(long.MaxValue));
                var listed = ((YamlSequence)sceneRoots.Body.Find("m_Roots")).Items
                    .Select(i => long.Parse(((YamlScalar)((YamlMapping)i).Find("fileID")).Value)).ToArray();
                var rootTransforms = docs.Where(d => d.ClassId == 4 && ((YamlScalar)((YamlMapping)d.Body.Find("m_Father")).Find("fileID")).Value == "0")
                    .Select(d => d.FileId).ToArray();
                Assert.That(listed, Is.EquivalentTo(rootTransforms), scene);
                Assert.That(listed.Length, Is.EqualTo(3), scene);
            }
        }
    }
}
