using System;
using NUnit.Framework;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): the Unity idioms of issue 13 item 8 — the mesh renderer
    /// brings its rope ([RequireComponent]), both components sit in the package's own Add Component menu, and the
    /// rope runs before default-order scripts ([DefaultExecutionOrder]) so scripts that read it see the current step.
    /// </summary>
    [TestFixture]
    public sealed class ComponentIdiomsTests
    {
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        [Test]
        public void AddingTheMeshRendererToABareObjectAddsTheRope()
        {
            var go = _scene.Track(new GameObject("Bare"));
            var renderer = go.AddComponent<RopeMeshRenderer>();
            Assert.That(renderer, Is.Not.Null);
            Assert.That(go.GetComponent<ElasticRope>(), Is.Not.Null, "[RequireComponent(typeof(ElasticRope))]");
            Assert.That(go.GetComponent<MeshFilter>(), Is.Not.Null);
            Assert.That(go.GetComponent<MeshRenderer>(), Is.Not.Null);
        }

        [TestCase(typeof(ElasticRope), "HookeRope/Elastic Rope")]
        [TestCase(typeof(RopeMeshRenderer), "HookeRope/Elastic Rope Mesh")]
        public void ComponentsAreInThePackagesOwnAddComponentMenu(Type component, string path)
        {
            // The menu path is the constructor argument (componentMenu is public in Unity but undocumented).
            string found = null;
            foreach (var data in component.GetCustomAttributesData())
                if (data.AttributeType == typeof(AddComponentMenu)) found = (string)data.ConstructorArguments[0].Value;
            Assert.That(found, Is.EqualTo(path));
        }

        [Test]
        public void TheRopeRunsBeforeDefaultOrderScripts()
        {
            var order = (DefaultExecutionOrder)Attribute.GetCustomAttribute(typeof(ElasticRope), typeof(DefaultExecutionOrder));
            Assert.That(order, Is.Not.Null);
            Assert.That(order.order, Is.LessThan(0));
        }
    }
}
