using System.Collections;
using HookeRope.Editor;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode without entering Play (in Unity and headless on the Unity stand-in): the [ExecuteAlways]
    /// <see cref="RopeMeshRenderer"/> gives an unbuilt rope a mesh at the first editor tick, straight between the
    /// ends or along the static-sag preview (which follows a moved end); its generated mesh, materials and burr
    /// texture are created once, carry DontSave hide flags, are never written over a user's material and are
    /// destroyed when the renderer is disabled or the rope destroyed.
    /// </summary>
    [TestFixture]
    public sealed class RopeMeshRendererEditModeTests
    {
        static readonly Vector3 s_Top = new Vector3(0f, 3f, 0f), s_Grip = new Vector3(0.3f, 2f, 0f);
        const float Radius = 0.02f;

        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        (ElasticRope Rope, RopeMeshRenderer Renderer, Transform Grip) Build()
        {
            var top = _scene.Point("Top", s_Top);
            var grip = _scene.Point("Grip", s_Grip);
            var go = _scene.Track(new GameObject("Rope", typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer)));
            var rope = go.GetComponent<ElasticRope>();
            rope.RestLength = 1.2f;
            rope.Radius = Radius;
            rope.SegmentCount = 20;
            rope.StartAttachment.Point = top;
            rope.EndAttachment.Point = grip;
            return (rope, go.GetComponent<RopeMeshRenderer>(), grip);
        }

        /// <summary>
        /// One whole editor tick: `yield return null` resumes after Update, so the second one resumes after the
        /// first frame's LateUpdate has drawn.
        /// </summary>
        static IEnumerator Tick()
        {
            yield return null;
            yield return null;
        }

        static Vector3[] WorldVertices(RopeMeshRenderer renderer)
        {
            var mesh = renderer.GetComponent<MeshFilter>().sharedMesh;
            Assert.That(mesh, Is.Not.Null, "the MeshFilter holds the generated mesh (pickable in the Scene view)");
            var vertices = MeshInUse.Vertices(mesh);
            Assert.That(vertices.Length, Is.GreaterThan(0));
            for (int v = 0; v < vertices.Length; v++) vertices[v] = renderer.transform.TransformPoint(vertices[v]);
            return vertices;
        }

        [UnityTest]
        public IEnumerator OneEditorTickDrawsTheRopeStraightBetweenItsEnds()
        {
            Assert.That(Application.isPlaying, Is.False);
            var (rope, renderer, _) = Build();
            Assert.That(renderer.Mesh, Is.Null);
            yield return Tick();
            Assert.That(rope.IsBuilt, Is.False, "edit mode draws without simulating");
            Assert.That(renderer.Mesh, Is.Not.Null, "LateUpdate ran in edit mode ([ExecuteAlways])");
            var vertices = WorldVertices(renderer);
            Vector3 axis = s_Grip - s_Top;
            float length = axis.magnitude;
            axis /= length;
            float lowest = float.PositiveInfinity, highest = float.NegativeInfinity;
            for (int v = 0; v < vertices.Length; v++)
            {
                Vector3 d = vertices[v] - s_Top;
                float along = Vector3.Dot(d, axis);
                float off = (d - along * axis).magnitude;
                Assert.That(off, Is.LessThanOrEqualTo(Radius + 1e-4f), "vertex " + v + " off the straight line");
                Assert.That(along, Is.InRange(-Radius - 1e-4f, length + Radius + 1e-4f), "vertex " + v + " beyond the ends");
                lowest = System.Math.Min(lowest, along);
                highest = System.Math.Max(highest, along);
            }
            Assert.That(lowest, Is.LessThan(1e-3f), "the tube starts at the start point");
            Assert.That(highest, Is.GreaterThan(length - 1e-3f), "the tube reaches the end point");
        }

        [UnityTest]
        public IEnumerator RepeatedTicksAndRendersReuseTheGeneratedObjectsAndDestroyFreesThem()
        {
            var (rope, renderer, _) = Build();
            yield return Tick();
            var mesh = renderer.Mesh;
            var meshRenderer = renderer.GetComponent<MeshRenderer>();
            var materials = meshRenderer.sharedMaterials;
            Assert.That(materials.Length, Is.EqualTo(2));
            Material tube = materials[0], burr = materials[1];
            Texture texture = burr != null && burr.HasProperty("_MainTex") ? burr.GetTexture("_MainTex") : null;
            Assert.That(mesh.hideFlags & HideFlags.DontSave, Is.EqualTo(HideFlags.DontSave));
            if (tube != null) Assert.That(tube.hideFlags & HideFlags.DontSave, Is.EqualTo(HideFlags.DontSave));
            if (burr != null) Assert.That(burr.hideFlags & HideFlags.DontSave, Is.EqualTo(HideFlags.DontSave));
            if (texture != null) Assert.That(texture.hideFlags, Is.EqualTo(HideFlags.HideAndDontSave));
            if (UnityEngine.Rendering.GraphicsSettings.currentRenderPipeline == null)
            {
                Assert.That(tube, Is.Not.Null, "Built-in: a generated Standard material");
                Assert.That(texture, Is.Not.Null, "Built-in: the generated burr texture");
            }

            for (int i = 0; i < 100; i++)
            {
                Assert.That(renderer.Render(1f), Is.True);
                yield return Tick();
            }
            Assert.That(renderer.Mesh, Is.SameAs(mesh));
            Assert.That(renderer.GetComponent<MeshFilter>().sharedMesh, Is.SameAs(mesh));
            var after = meshRenderer.sharedMaterials;
            Assert.That(after.Length, Is.EqualTo(2));
            Assert.That(after[0], Is.SameAs(tube));
            Assert.That(after[1], Is.SameAs(burr));
            if (burr != null) Assert.That(burr.GetTexture("_MainTex"), Is.SameAs(texture));

            Object.DestroyImmediate(rope.gameObject);
            Assert.That(mesh == null, Is.True, "mesh destroyed");
            if (tube != null) Assert.That(tube == null, Is.True, "tube material destroyed");
            if (burr != null) Assert.That(burr == null, Is.True, "burr material destroyed");
            if (texture != null) Assert.That(texture == null, Is.True, "burr texture destroyed");
        }

        [UnityTest]
        public IEnumerator DisablingTheRendererDestroysAndUnassignsTheGeneratedObjects()
        {
            var (_, renderer, _) = Build();
            yield return Tick();
            var mesh = renderer.Mesh;
            var meshRenderer = renderer.GetComponent<MeshRenderer>();
            var materials = meshRenderer.sharedMaterials;
            renderer.enabled = false;
            Assert.That(mesh == null, Is.True, "mesh destroyed on disable");
            Assert.That(renderer.GetComponent<MeshFilter>().sharedMesh == null, Is.True, "the MeshFilter slot is emptied");
            for (int i = 0; i < materials.Length; i++)
                if (!ReferenceEquals(materials[i], null)) Assert.That(materials[i] == null, Is.True, "generated material " + i + " destroyed");
            var slots = meshRenderer.sharedMaterials;
            for (int i = 0; i < slots.Length; i++) Assert.That(slots[i] == null, Is.True, "slot " + i + " emptied");
            renderer.enabled = true;
            yield return Tick();
            Assert.That(renderer.Mesh, Is.Not.Null, "re-enabled: drawn again");
            Assert.That(renderer.Mesh, Is.Not.SameAs(mesh));
        }

        [UnityTest]
        public IEnumerator AUserMaterialIsKeptAndNeverDestroyed()
        {
            var shader = Shader.Find("Standard");
            if (shader == null) Assert.Ignore("needs the Built-in Standard shader");
            var (rope, renderer, _) = Build();
            var mine = new Material(shader) { name = "Mine" };
            try
            {
                var meshRenderer = renderer.GetComponent<MeshRenderer>();
                meshRenderer.sharedMaterials = new[] { mine, mine };
                yield return Tick();
                Assert.That(renderer.Mesh, Is.Not.Null);
                Assert.That(meshRenderer.sharedMaterials[0], Is.SameAs(mine));
                Assert.That(meshRenderer.sharedMaterials[1], Is.SameAs(mine));
                Object.DestroyImmediate(rope.gameObject);
                Assert.That(mine == null, Is.False, "the user's material survives");
            }
            finally
            {
                Object.DestroyImmediate(mine);
            }
        }

        [UnityTest]
        public IEnumerator TheMeshFollowsTheStaticSagPreviewAndItsMovedEnd()
        {
            var (rope, renderer, grip) = Build();
            grip.position = new Vector3(1f, 3f, 0f); // level span of 1 m with a 1.2 m rope: it sags
            StaticSagPreview.Compute(rope, 3f);
            yield return Tick();
            var preview = StaticSagPreview.Get(rope);
            Assert.That(preview.Length, Is.EqualTo(21));
            float lowestPreview = float.PositiveInfinity;
            for (int i = 0; i < preview.Length; i++) lowestPreview = System.Math.Min(lowestPreview, preview[i].y);
            Assert.That(lowestPreview, Is.LessThan(2.8f), "the preview sags");
            Assert.That(LowestVertex(renderer), Is.EqualTo(lowestPreview - Radius).Within(0.01f), "the mesh lies on the preview");

            grip.position = new Vector3(0.5f, 3f, 0f); // shorter span: deeper sag
            yield return Tick();
            var moved = StaticSagPreview.Get(rope);
            Assert.That((moved[moved.Length - 1] - grip.position).magnitude, Is.LessThan(1e-3f), "the preview follows the moved end");
            float lowestMoved = float.PositiveInfinity;
            for (int i = 0; i < moved.Length; i++) lowestMoved = System.Math.Min(lowestMoved, moved[i].y);
            Assert.That(lowestMoved, Is.LessThan(lowestPreview - 0.05f), "a shorter span sags deeper");
            Assert.That(LowestVertex(renderer), Is.EqualTo(lowestMoved - Radius).Within(0.01f), "the mesh follows");
        }

        static float LowestVertex(RopeMeshRenderer renderer)
        {
            var vertices = WorldVertices(renderer);
            float lowest = float.PositiveInfinity;
            for (int v = 0; v < vertices.Length; v++) lowest = System.Math.Min(lowest, vertices[v].y);
            return lowest;
        }
    }
}
