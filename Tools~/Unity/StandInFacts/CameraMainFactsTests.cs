using NUnit.Framework;
using UnityEngine;

namespace HookeRope.StandIn.Facts
{
    /// <summary>
    /// The stand-in's Camera.main and GameObject tags against the Scripting Reference: Camera.main is the first enabled
    /// Camera tagged "MainCamera", null when there is none; a new GameObject is "Untagged"; only Unity's built-in tags
    /// are modelled (a project tag needs the TagManager, which the stand-in refuses by name).
    /// </summary>
    [TestFixture]
    public sealed class CameraMainFactsTests
    {
        FreshWorld _world;

        [SetUp] public void SetUp() => _world = new FreshWorld();
        [TearDown] public void TearDown() => _world.Dispose();

        [Test]
        public void TheMainCameraIsTheFirstEnabledCameraTaggedMainCamera()
        {
            Assert.That(Camera.main, Is.Null, "no camera");
            var untagged = (new GameObject("Untagged camera", typeof(Camera)));
            Assert.That(untagged.tag, Is.EqualTo("Untagged"), "a new GameObject's tag");
            Assert.That(Camera.main, Is.Null, "a camera without the tag");

            var first = (new GameObject("First", typeof(Camera)));
            var second = (new GameObject("Second", typeof(Camera)));
            first.tag = "MainCamera";
            second.tag = "MainCamera";
            Assert.That(first.CompareTag("MainCamera"), Is.True);
            Assert.That(untagged.CompareTag("MainCamera"), Is.False);
            Assert.That(Camera.main, Is.SameAs(first.GetComponent<Camera>()));

            first.GetComponent<Camera>().enabled = false;
            Assert.That(Camera.main, Is.SameAs(second.GetComponent<Camera>()), "a disabled camera is skipped");
            second.SetActive(false);
            Assert.That(Camera.main, Is.Null, "so is one on an inactive GameObject");
            first.GetComponent<Camera>().enabled = true;
            Assert.That(Camera.main, Is.SameAs(first.GetComponent<Camera>()));
            Object.DestroyImmediate(first);
            Assert.That(Camera.main, Is.Null, "a destroyed camera is gone");

            var tagged = (new GameObject("Tagged, no camera"));
            tagged.tag = "MainCamera";
            Assert.That(Camera.main, Is.Null, "the tag alone makes no camera");
        }

        [Test]
        public void OnlyTheBuiltInTagsAreModelled()
        {
            var go = (new GameObject("Tagged"));
            foreach (var builtIn in new[] { "Untagged", "Respawn", "Finish", "EditorOnly", "MainCamera", "Player", "GameController" })
            {
                go.tag = builtIn;
                Assert.That(go.tag, Is.EqualTo(builtIn));
            }
            Assert.That(() => go.tag = "Enemy", Throws.TypeOf<System.NotSupportedException>().With.Message.Contain("Enemy"));
            Assert.That(() => go.CompareTag("Enemy"), Throws.TypeOf<System.NotSupportedException>());
            Assert.That(go.tag, Is.EqualTo("GameController"), "a refused tag leaves the tag");
        }
    }
}
