using HookeRope.Geometry;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools.Constraints;
using Is = UnityEngine.TestTools.Constraints.Is;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in), issue 17 item 4 through the renderer: a rope draped
    /// over a listed capsule bar is drawn outside the bar (within 2 % of its radius) although the renderer's object is
    /// rotated and uniformly scaled, while the same positions filled without a frame sink into it; allocation-free once warm.
    /// </summary>
    [TestFixture]
    public sealed class RopeContactDrawingTests
    {
        const float BarRadius = 0.1f;
        static readonly Vector3 BarCentre = new Vector3(0f, 1f, 0f);

        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        [Test]
        public void TubeDrawnByARotatedScaledRendererStaysOutsideTheWrappedBar()
        {
            var rope = DrapedRope(out var renderer);
            Assert.That(renderer.Render(1f), Is.True);
            var vertices = MeshInUse.Vertices(renderer.Mesh);
            float deepest = float.PositiveInfinity;
            for (int v = 0; v < vertices.Length; v++)
                deepest = Mathf_Min(deepest, OutsideBar(renderer.transform.TransformPoint(vertices[v])));

            float frameless = DeepestWithoutFrame(rope);
            TestContext.WriteLine("drawn surface to bar: renderer " + deepest / rope.Radius + " r, frameless fill " + frameless / rope.Radius + " r");
            Assert.That(frameless, Is.LessThan(-0.1f * rope.Radius), "the positions alone sink into the bar (the case being fixed)");
            Assert.That(deepest, Is.GreaterThan(-0.02f * rope.Radius));
            Assert.That(deepest, Is.LessThan(0.1f * rope.Radius), "the tube touches the bar");
            for (int frame = 0; frame < 3; frame++) renderer.Render(1f);
            Assert.That(() => { renderer.Render(1f); }, Is.Not.AllocatingGCMemory(), "pushing rings out of the bar allocates nothing");
        }

        /// <summary>
        /// The tube built from the rope's world positions by the frameless overload (vertices in world space, no
        /// collider check): the deepest vertex relative to the bar's surface (m).
        /// </summary>
        static float DeepestWithoutFrame(ElasticRope rope)
        {
            var simulation = rope.Simulation;
            int n = rope.ParticleCount;
            var x = new float[n];
            var y = new float[n];
            var z = new float[n];
            for (int i = 0; i < n; i++)
            {
                var p = rope.GetParticlePosition(i);
                x[i] = p.x; y[i] = p.y; z[i] = p.z;
            }
            var vertices = new TubeVertex[simulation.GetVertexCount()];
            var indices = new int[simulation.GetIndexCount()];
            var update = simulation.FillMesh(x, y, z, vertices, indices);
            float deepest = float.PositiveInfinity;
            for (int v = 0; v < update.VertexCount; v++)
                deepest = Mathf_Min(deepest, OutsideBar(new Vector3(vertices[v].PX, vertices[v].PY, vertices[v].PZ)));
            return deepest;
        }

        /// <summary>Signed distance (m) of world point <paramref name="p"/> from the bar's surface (the bar runs along z, 1 m long).</summary>
        static float OutsideBar(Vector3 p)
        {
            Vector3 d = p - BarCentre;
            return (float)System.Math.Sqrt(d.x * d.x + d.y * d.y) - BarRadius;
        }

        static float Mathf_Min(float a, float b) => a < b ? a : b;

        /// <summary>
        /// A 2.4 m cord (radius 1 cm, 24 segments of 10 cm) lowered by 1.2 m over a capsule bar (radius 0.1 m along z through
        /// (0, 1, 0), listed) between anchors 2 m apart; the rope's object is rotated and scaled by 1.7.
        /// </summary>
        ElasticRope DrapedRope(out RopeMeshRenderer renderer)
        {
            var barObject = _scene.Track(new GameObject("Bar"));
            barObject.transform.position = BarCentre;
            var bar = barObject.AddComponent<CapsuleCollider>();
            bar.radius = BarRadius;
            bar.height = 1f;
            bar.direction = 2;

            var left = _scene.Point("Left", new Vector3(-1f, 1.6f, 0f));
            var right = _scene.Point("Right", new Vector3(1f, 1.6f, 0f));
            var go = _scene.Track(new GameObject("Rope", typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer)));
            go.transform.position = new Vector3(0.4f, 0.3f, -0.2f);
            go.transform.rotation = Quaternion.Euler(25f, 40f, -15f);
            go.transform.localScale = new Vector3(1.7f, 1.7f, 1.7f);
            var rope = go.GetComponent<ElasticRope>();
            rope.RestLength = 2.4f;
            rope.SegmentCount = 24;
            rope.Radius = 0.01f;
            rope.AxialStiffness = 2000f;
            rope.Fracture = false;
            rope.CollisionMode = RopeCollisionMode.ListedColliders;
            rope.Colliders = new Collider[] { bar };
            rope.StartAttachment.Point = left;
            rope.EndAttachment.Point = right;
            rope.Rebuild();
            for (int step = 0; step < 200; step++)
            {
                float y = 1.6f - 1.2f * Mathf_Min(1f, step / 100f);
                left.position = new Vector3(-1f, y, 0f);
                right.position = new Vector3(1f, y, 0f);
                rope.Simulate(0.01f);
            }
            Assert.That(rope.GetParticlePosition(rope.ParticleCount / 2).y, Is.GreaterThan(1.1f), "the rope drapes over the bar");
            renderer = go.GetComponent<RopeMeshRenderer>();
            return rope;
        }
    }
}
