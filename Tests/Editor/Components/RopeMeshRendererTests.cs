using HookeRope.Geometry;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools.Constraints;
using Is = UnityEngine.TestTools.Constraints.Is;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in): the rope mesh built from a stepped rope has finite vertices that stay near the rope
    /// and inside the bounds set on the mesh, also after a break changed the topology; the renderer only uploads the core's
    /// mesh (<see cref="RopeSimulation.FillMesh(System.ReadOnlySpan{float}, System.ReadOnlySpan{float}, System.ReadOnlySpan{float}, TubeVertex[], int[], float)"/>)
    /// and allocates nothing per frame once warm.
    /// </summary>
    [TestFixture]
    public sealed class RopeMeshRendererTests
    {
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        (ElasticRope Rope, RopeMeshRenderer Renderer, Transform Grip) Build()
        {
            var top = _scene.Point("Top", new Vector3(0f, 3f, 0f));
            var grip = _scene.Point("Grip", new Vector3(0.3f, 2f, 0f));
            var go = _scene.Track(new GameObject("Rope", typeof(MeshFilter), typeof(MeshRenderer), typeof(ElasticRope), typeof(RopeMeshRenderer)));
            var rope = go.GetComponent<ElasticRope>();
            rope.RestLength = 1.2f;
            rope.Radius = 0.02f;
            rope.SegmentCount = 20;
            rope.BreakStrain = 0.3f;
            rope.StartAttachment.Point = top;
            rope.EndAttachment.Point = grip;
            rope.Rebuild();
            return (rope, go.GetComponent<RopeMeshRenderer>(), grip);
        }

        static void AssertMeshFollowsRope(ElasticRope rope, Mesh mesh)
        {
            var vertices = MeshInUse.Vertices(mesh);
            Assert.That(vertices.Length, Is.GreaterThan(0));
            var bounds = mesh.bounds;
            Vector3 min = bounds.center - bounds.size * 0.5f, max = bounds.center + bounds.size * 0.5f;
            float reach = 20f * rope.Radius;
            for (int v = 0; v < vertices.Length; v++)
            {
                var p = vertices[v];
                Assert.That(float.IsNaN(p.x) || float.IsNaN(p.y) || float.IsNaN(p.z), Is.False, "vertex " + v + " is NaN");
                Assert.That(p.x >= min.x - 1e-4f && p.y >= min.y - 1e-4f && p.z >= min.z - 1e-4f &&
                            p.x <= max.x + 1e-4f && p.y <= max.y + 1e-4f && p.z <= max.z + 1e-4f, Is.True, "vertex " + v + " outside the mesh bounds");
                float nearest = float.PositiveInfinity;
                for (int i = 0; i < rope.ParticleCount; i++)
                {
                    float d = (rope.transform.TransformPoint(p) - rope.GetParticlePosition(i)).magnitude;
                    if (d < nearest) nearest = d;
                }
                Assert.That(nearest, Is.LessThan(reach + 1.2f / 20f), "vertex " + v + " far from the rope");
            }
        }

        [Test]
        public void MeshOfSteppedRopeIsFiniteAndFollowsTheRope()
        {
            var (rope, renderer, _) = Build();
            for (int step = 0; step < 100; step++) rope.Simulate(0.01f);
            Assert.That(renderer.Render(0.5f), Is.True);
            AssertMeshFollowsRope(rope, renderer.Mesh);
        }

        [Test]
        public void BuiltInPipelineGetsAnOrangeTubeAndAnOpaqueBurrCopy()
        {
            if (UnityEngine.Rendering.GraphicsSettings.currentRenderPipeline != null)
                Assert.Ignore("the generated materials checked here are the Built-in pipeline's");
            var (rope, renderer, _) = Build();
            renderer.Render(1f);
            var materials = renderer.GetComponent<MeshRenderer>().sharedMaterials;
            Assert.That(materials.Length, Is.EqualTo(2), "submesh 0 tube, submesh 1 burr strands");
            Assert.That(renderer.Mesh.subMeshCount, Is.EqualTo(2));
            var tube = materials[0];
            Assert.That(tube.shader.name, Is.EqualTo("Standard"));
            var orange = tube.GetColor("_Color");
            Assert.That(orange.r, Is.EqualTo(0.93f).Within(1e-6f));
            Assert.That(orange.g, Is.EqualTo(0.5f).Within(1e-6f));
            Assert.That(orange.b, Is.EqualTo(0.12f).Within(1e-6f));
            var burr = materials[1];
            Assert.That(burr, Is.Not.SameAs(tube));
            Assert.That(burr.shader, Is.SameAs(tube.shader), "the strands are geometry: the tube's opaque shader draws them");
            Assert.That(burr.IsKeywordEnabled("_ALPHATEST_ON"), Is.False, "no shader_feature keyword a player could strip");
            Assert.That(burr.shaderKeywords.Length, Is.EqualTo(0));
            Assert.That(burr.renderQueue, Is.EqualTo(2000), "Geometry queue");
            Assert.That(burr.GetColor("_Color").g, Is.EqualTo(0.5f).Within(1e-6f), "the rope's colour, streaked by the texture");
            var texture = burr.GetTexture("_MainTex");
            Assert.That(texture, Is.Not.Null);
            Assert.That(tube.GetTexture("_MainTex"), Is.Null);
            Assert.That(texture.width, Is.EqualTo(256));
            Assert.That(texture.height, Is.EqualTo(64));
            Assert.That(texture.isReadable, Is.False, "the CPU copy is released after the upload");
            Assert.That(rope.IsBuilt, Is.True);
        }

        [Test]
        public void MeshStaysFiniteAfterTheRopeBreaks()
        {
            var (rope, renderer, grip) = Build();
            renderer.Render(1f);
            int intactVertices = renderer.Mesh.vertexCount;
            for (int step = 0; step < 300 && !rope.IsBroken; step++)
            {
                grip.position = new Vector3(0.3f, 2f - 0.004f * step, 0f);
                rope.Simulate(0.01f);
            }
            Assert.That(rope.IsBroken, Is.True);
            rope.Simulate(0.01f);
            renderer.Render(1f);
            Assert.That(renderer.Mesh.vertexCount, Is.GreaterThan(intactVertices), "broken ends add caps and burr strands");
            AssertMeshFollowsRope(rope, renderer.Mesh);
        }

        void BreakIt(ElasticRope rope, Transform grip)
        {
            for (int step = 0; step < 300 && !rope.IsBroken; step++)
            {
                grip.position = new Vector3(0.3f, 2f - 0.004f * step, 0f);
                rope.Simulate(0.01f);
            }
            Assert.That(rope.IsBroken, Is.True);
            rope.Simulate(0.01f);
        }

        [Test]
        public void RenderAllocatesNothingOnceWarm()
        {
            var (rope, renderer, grip) = Build();
            for (int step = 0; step < 20; step++) rope.Simulate(0.01f);
            for (int frame = 0; frame < 3; frame++) renderer.Render(0.5f);
            Assert.That(() => { renderer.Render(0.5f); }, Is.Not.AllocatingGCMemory(), "intact");

            BreakIt(rope, grip);
            for (int frame = 0; frame < 3; frame++) renderer.Render(0.5f);
            Assert.That(() => { renderer.Render(0.5f); }, Is.Not.AllocatingGCMemory(), "broken");
        }

        /// <summary>
        /// Issue 18: without tangents the mesh is laid out as position, normal and uv (32 bytes, no tangent attribute) and
        /// holds the positions, normals and uv of the mesh with tangents bit for bit, intact and broken; a frame allocates
        /// nothing once warm; with tangents again the 48-byte layout returns.
        /// </summary>
        [Test]
        public void WithoutTangentsTheMeshIsThirtyTwoBytesAVertexAndTheSameSurface()
        {
            var (rope, renderer, grip) = Build();
            for (int step = 0; step < 20; step++) rope.Simulate(0.01f);
            for (int pass = 0; pass < 2; pass++)
            {
                Assert.That(renderer.Tangents, Is.True, "the default");
                Assert.That(renderer.Render(0.5f), Is.True);
                var mesh = renderer.Mesh;
                Assert.That(mesh.GetVertexBufferStride(0), Is.EqualTo(TubeVertex.SizeInBytes));
                var positions = MeshInUse.Vertices(mesh);
                var normals = mesh.normals;
                var uv = mesh.uv;

                renderer.Tangents = false;
                Assert.That(renderer.Render(0.5f), Is.True);
                Assert.That(mesh.GetVertexBufferStride(0), Is.EqualTo(LeanTubeVertex.SizeInBytes));
                Assert.That(mesh.vertexAttributeCount, Is.EqualTo(3));
                Assert.That(mesh.HasVertexAttribute(UnityEngine.Rendering.VertexAttribute.Tangent), Is.False);
                Assert.That(mesh.HasVertexAttribute(UnityEngine.Rendering.VertexAttribute.TexCoord0), Is.True);
                var leanPositions = MeshInUse.Vertices(mesh);
                var leanNormals = mesh.normals;
                var leanUv = mesh.uv;
                Assert.That(leanPositions.Length, Is.EqualTo(positions.Length));
                int differing = 0;
                for (int v = 0; v < positions.Length; v++)
                    if (!SameBits(positions[v], leanPositions[v]) || !SameBits(normals[v], leanNormals[v])
                        || !SameBits(new Vector3(uv[v].x, uv[v].y, 0f), new Vector3(leanUv[v].x, leanUv[v].y, 0f))) differing++;
                Assert.That(differing, Is.EqualTo(0), (pass == 0 ? "intact" : "broken") + ": vertices whose position, normal or uv differ in a bit");
                for (int frame = 0; frame < 3; frame++) renderer.Render(0.5f);
                Assert.That(() => { renderer.Render(0.5f); }, Is.Not.AllocatingGCMemory(), "a frame without tangents");

                renderer.Tangents = true;
                Assert.That(renderer.Render(0.5f), Is.True);
                Assert.That(mesh.GetVertexBufferStride(0), Is.EqualTo(TubeVertex.SizeInBytes), "tangents again");
                Assert.That(mesh.HasVertexAttribute(UnityEngine.Rendering.VertexAttribute.Tangent), Is.True);
                if (pass == 0) BreakIt(rope, grip);
            }
        }

        static bool SameBits(Vector3 a, Vector3 b) =>
            System.BitConverter.SingleToInt32Bits(a.x) == System.BitConverter.SingleToInt32Bits(b.x)
            && System.BitConverter.SingleToInt32Bits(a.y) == System.BitConverter.SingleToInt32Bits(b.y)
            && System.BitConverter.SingleToInt32Bits(a.z) == System.BitConverter.SingleToInt32Bits(b.z);

        /// <summary>
        /// Issue 18, "0 bytes per update": the mesh's buffers hold the ring budget's most from the first frame, so while the
        /// swung rope's adaptive ring budget steps the vertex buffer keeps its size (the capacity) and only the sub-meshes'
        /// counts move, and no frame allocates.
        /// </summary>
        [Test]
        public void ARingBudgetStepsWithinTheMeshBuffersAndNoFrameAllocates()
        {
            var (rope, renderer, grip) = Build();
            rope.Radius = 0.002f;
            rope.Rebuild();
            renderer.Render(1f);
            for (int frame = 0; frame < 3; frame++) { rope.Simulate(0.01f); renderer.Render(1f); }
            var mesh = renderer.Mesh;
            int capacity = rope.Simulation.GetVertexCapacity();
            var inUse = new int[120];
            var sizes = new int[120];
            Assert.That(() =>
            {
                for (int frame = 0; frame < inUse.Length; frame++)
                {
                    grip.position = new Vector3(0.3f + 0.25f * System.MathF.Sin(0.2f * frame), 2f, 0.1f * System.MathF.Sin(0.3f * frame));
                    rope.Simulate(0.01f);
                    renderer.Render(1f);
                    inUse[frame] = mesh.GetSubMesh(0).vertexCount;
                    sizes[frame] = mesh.vertexCount;
                }
            }, Is.Not.AllocatingGCMemory(), "120 frames of a swung rope");
            int steps = 0;
            for (int frame = 1; frame < inUse.Length; frame++) if (inUse[frame] != inUse[frame - 1]) steps++;
            TestContext.WriteLine("capacity " + capacity + " vertices; in use " + inUse[0] + " … " + inUse[inUse.Length - 1] + ", " + steps + " budget steps");
            Assert.That(steps, Is.GreaterThan(0), "the ring budget stepped during the frames");
            foreach (int size in sizes) Assert.That(size, Is.EqualTo(capacity), "the vertex buffer keeps the capacity");
            foreach (int used in inUse) Assert.That(used, Is.LessThanOrEqualTo(capacity));
        }

        /// <summary>
        /// Swings two ropes' grips alike for 60 frames of 0.01 s, drawing both after every step; returns the most vertices
        /// each drew.
        /// </summary>
        static (int A, int B) SwingBoth((ElasticRope Rope, RopeMeshRenderer Renderer, Transform Grip) a, (ElasticRope Rope, RopeMeshRenderer Renderer, Transform Grip) b)
        {
            int mostA = 0, mostB = 0;
            for (int frame = 0; frame < 60; frame++)
            {
                var p = new Vector3(0.3f + 0.25f * System.MathF.Sin(0.2f * frame), 2f, 0.1f * System.MathF.Sin(0.3f * frame));
                a.Grip.position = p;
                b.Grip.position = p;
                a.Rope.Simulate(0.01f);
                b.Rope.Simulate(0.01f);
                Assert.That(a.Renderer.Render(1f), Is.True);
                Assert.That(b.Renderer.Render(1f), Is.True);
                mostA = System.Math.Max(mostA, a.Renderer.Mesh.GetSubMesh(0).vertexCount);
                mostB = System.Math.Max(mostB, b.Renderer.Mesh.GetSubMesh(0).vertexCount);
            }
            return (mostA, mostB);
        }

        [Test]
        public void RingToleranceReachesTheCoreMeshAndDrawsFewerVertices()
        {
            // two identical swung ropes, one drawn at Ring Tolerance 4: the same physics, fewer rings where it bends
            var (exact, exactRenderer, exactGrip) = Build();
            var (loose, looseRenderer, looseGrip) = Build();
            foreach (var rope in new[] { exact, loose }) { rope.Radius = 0.002f; rope.Rebuild(); }
            looseRenderer.RingTolerance = 4f;
            var (exactMost, looseMost) = SwingBoth((exact, exactRenderer, exactGrip), (loose, looseRenderer, looseGrip));
            TestContext.WriteLine("most vertices in use over 60 frames: " + exactMost + " at Ring Tolerance 1, " + looseMost + " at 4");
            Assert.That(loose.Simulation.MeshSettings.RingTolerance, Is.EqualTo(4f), "the renderer's value is the core mesh's");
            Assert.That(exact.Simulation.MeshSettings.RingTolerance, Is.EqualTo(1f));
            Assert.That(looseMost, Is.LessThan(exactMost));
            AssertMeshFollowsRope(loose, looseRenderer.Mesh);
        }

        /// <summary>World distance (m) from <paramref name="viewer"/> to the box around the rope's particles.</summary>
        static float DistanceToParticleBox(ElasticRope rope, Vector3 viewer)
        {
            Vector3 min = rope.GetParticlePosition(0), max = min;
            for (int i = 1; i < rope.ParticleCount; i++)
            {
                min = Vector3.Min(min, rope.GetParticlePosition(i));
                max = Vector3.Max(max, rope.GetParticlePosition(i));
            }
            return (viewer - Vector3.Max(min, Vector3.Min(max, viewer))).magnitude;
        }

        [Test]
        public void ADistantViewPointScalesTheRingToleranceAndDrawsFewerVertices()
        {
            // two identical swung ropes of 12 sides, one seen from 1 m, one from 40 m, detail distance 2 m: the far one
            // (20 D) draws 6 sides at the tolerance of ViewDetail for 12 -> 6, the near one all 12 at 1
            var (near, nearRenderer, nearGrip) = Build();
            var (far, farRenderer, farGrip) = Build();
            foreach (var rope in new[] { near, far }) { rope.Radius = 0.002f; rope.Rebuild(); }
            var farViewer = _scene.Point("Far viewer", new Vector3(0.15f, 2.5f, 40f));
            nearRenderer.ViewPoint = _scene.Point("Near viewer", new Vector3(0.15f, 2.5f, 1f));
            farRenderer.ViewPoint = farViewer;
            nearRenderer.DetailDistance = 2f;
            farRenderer.DetailDistance = 2f;
            var (nearMost, farMost) = SwingBoth((near, nearRenderer, nearGrip), (far, farRenderer, farGrip));
            TestContext.WriteLine("most vertices in use over 60 frames: " + nearMost + " seen from 1 m, " + farMost + " from 40 m");
            Assert.That(nearRenderer.DrawnRingTolerance, Is.EqualTo(1f), "inside the detail distance");
            Assert.That(nearRenderer.DrawnRadialSegments, Is.EqualTo(12));
            Assert.That(farRenderer.DrawnRadialSegments, Is.EqualTo(6), "half the sides from 4.4 D on");
            float at40 = ViewDetail.RingTolerance(1f, 2f, DistanceToParticleBox(far, farViewer.position), 12, 6);
            Assert.That(at40, Is.GreaterThan(4f).And.LessThan(6f), "20 D over the 6-gon's 3.9 times the depth");
            Assert.That(farRenderer.DrawnRingTolerance, Is.EqualTo(at40).Within(1e-4f));
            Assert.That(far.Simulation.MeshSettings.RingTolerance, Is.EqualTo(farRenderer.DrawnRingTolerance), "the drawn values are the core mesh's");
            Assert.That(far.Simulation.MeshSettings.RadialSegments, Is.EqualTo(6));
            Assert.That(farRenderer.RingTolerance, Is.EqualTo(1f), "the settings themselves are left alone");
            Assert.That(farRenderer.RadialSegments, Is.EqualTo(12));
            Assert.That(farMost, Is.LessThan(nearMost / 2));
            AssertMeshFollowsRope(far, farRenderer.Mesh);

            // at 9 m (4.5 D): still 6 sides, the tolerance d / D of the distance to the particles' box over the 6-gon's
            // depth, also under a uniform scale of the rope's GameObject (measured in its local space, turned into metres)
            farViewer.position = new Vector3(0.15f, 2.5f, 9f);
            Assert.That(farRenderer.Render(1f), Is.True);
            float at9 = ViewDetail.RingTolerance(1f, 2f, DistanceToParticleBox(far, farViewer.position), 12, 6);
            TestContext.WriteLine("seen from 9 m: " + farRenderer.DrawnRadialSegments + " sides, tolerance " + farRenderer.DrawnRingTolerance + ", expected " + at9);
            Assert.That(farRenderer.DrawnRadialSegments, Is.EqualTo(6));
            Assert.That(farRenderer.DrawnRingTolerance, Is.EqualTo(at9).Within(1e-4f));
            far.transform.localScale = new Vector3(2f, 2f, 2f);
            Assert.That(farRenderer.Render(1f), Is.True);
            Assert.That(farRenderer.DrawnRingTolerance, Is.EqualTo(at9).Within(1e-4f), "the same distance in metres at scale 2");
            far.transform.localScale = Vector3.one;

            // at 7 m (within 4 D): all 12 sides again, the plain d / D, the mesh again the rope's
            farViewer.position = new Vector3(0.15f, 2.5f, 7f);
            Assert.That(farRenderer.Render(1f), Is.True);
            Assert.That(farRenderer.DrawnRadialSegments, Is.EqualTo(12));
            Assert.That(farRenderer.DrawnRingTolerance, Is.EqualTo(ViewDetail.RingTolerance(1f, 2f, DistanceToParticleBox(far, farViewer.position))).Within(1e-4f));
            Assert.That(farRenderer.Mesh.GetSubMesh(0).vertexCount % 13, Is.EqualTo(0), "13 vertices a ring (12 sides and the seam)");
            AssertMeshFollowsRope(far, farRenderer.Mesh);

            // off again: no view point, or a detail distance of 0
            farViewer.position = new Vector3(0.15f, 2.5f, 40f);
            farRenderer.DetailDistance = 0f;
            Assert.That(farRenderer.Render(1f), Is.True);
            Assert.That(farRenderer.DrawnRingTolerance, Is.EqualTo(1f));
            Assert.That(farRenderer.DrawnRadialSegments, Is.EqualTo(12));
            farRenderer.DetailDistance = 2f;
            farRenderer.ViewPoint = null;
            Assert.That(farRenderer.Render(1f), Is.True);
            Assert.That(farRenderer.DrawnRingTolerance, Is.EqualTo(1f), "no view point and no main camera");

            // no view point: the main camera's distance (the first enabled Camera tagged MainCamera)
            var cameraObject = _scene.Track(new GameObject("XR camera", typeof(Camera)));
            cameraObject.transform.position = new Vector3(0.15f, 2.5f, 9f);
            Assert.That(farRenderer.Render(1f), Is.True);
            Assert.That(farRenderer.DrawnRingTolerance, Is.EqualTo(1f), "an untagged camera is not the main camera");
            cameraObject.tag = "MainCamera";
            Assert.That(farRenderer.Render(1f), Is.True);
            Assert.That(farRenderer.DrawnRadialSegments, Is.EqualTo(6), "the main camera at 9 m (4.5 D)");
            Assert.That(farRenderer.DrawnRingTolerance, Is.EqualTo(at9).Within(1e-4f));
            cameraObject.GetComponent<Camera>().enabled = false;
            Assert.That(farRenderer.Render(1f), Is.True);
            Assert.That(farRenderer.DrawnRingTolerance, Is.EqualTo(1f), "a disabled camera is not the main camera");
            Assert.That(() => farRenderer.DetailDistance = -1f, Throws.TypeOf<System.ArgumentOutOfRangeException>().With.Message.Contain("DetailDistance"));
            Assert.That(farRenderer.DetailDistance, Is.EqualTo(2f), "a rejected value leaves the setting");
        }

        [Test]
        public void TheSideCountKeepsItsBandAndTheDistanceIsTakenInWorldSpace()
        {
            // D = 1 m; the viewer straight out along z from the particles' box, at 20, 4.2, 3.9 and 4.2 m
            var (rope, renderer, grip) = Build();
            var viewer = _scene.Point("Viewer", Vector3.zero);
            renderer.ViewPoint = viewer;
            renderer.DetailDistance = 1f;
            rope.Simulate(0.01f);
            void DrawFrom(float distance)
            {
                // the box's nearest face along +z, then the viewer that far beyond it
                float front = float.NegativeInfinity;
                for (int i = 0; i < rope.ParticleCount; i++) front = System.Math.Max(front, rope.GetParticlePosition(i).z);
                viewer.position = new Vector3(0.15f, 2.5f, front + distance);
                Assert.That(renderer.Render(1f), Is.True);
            }
            DrawFrom(20f);
            Assert.That(renderer.DrawnRadialSegments, Is.EqualTo(6), "20 D: half the sides");
            DrawFrom(4.2f);
            Assert.That(renderer.DrawnRadialSegments, Is.EqualTo(6), "4.2 D, coming nearer: still half (the band down to 4 D)");
            DrawFrom(3.9f);
            Assert.That(renderer.DrawnRadialSegments, Is.EqualTo(12), "within 4 D: all of them");
            DrawFrom(4.2f);
            Assert.That(renderer.DrawnRadialSegments, Is.EqualTo(12), "4.2 D, going away: still all (the band up to 4.4 D)");

            // under a parent scaled (1, 0.1, 1), the rope's GameObject turned 45° about z (a skewed frame, whose lossyScale
            // is no bound on its stretch): the tolerance still follows the world distance
            var parent = _scene.Point("Squashed parent", Vector3.zero);
            parent.localScale = new Vector3(1f, 0.1f, 1f);
            rope.transform.SetParent(parent, true);
            rope.transform.rotation = Quaternion.Euler(0f, 0f, 45f);
            viewer.position = new Vector3(6f, 2.5f, 0f);
            Assert.That(renderer.Render(1f), Is.True);
            float expected = ViewDetail.RingTolerance(1f, 1f, DistanceToParticleBox(rope, viewer.position), 12, renderer.DrawnRadialSegments);
            TestContext.WriteLine("skewed frame: " + renderer.DrawnRadialSegments + " sides, tolerance " + renderer.DrawnRingTolerance + ", expected " + expected);
            Assert.That(renderer.DrawnRingTolerance, Is.EqualTo(expected).Within(1e-3f));
            AssertMeshFollowsRope(rope, renderer.Mesh);
        }

        [Test]
        public void ABrokenRopeFarAwayKeepsItsSides()
        {
            var (rope, renderer, grip) = Build();
            renderer.ViewPoint = _scene.Point("Viewer", new Vector3(0.15f, 2.5f, 40f));
            renderer.DetailDistance = 2f;
            rope.Simulate(0.01f);
            Assert.That(renderer.Render(1f), Is.True);
            Assert.That(renderer.DrawnRadialSegments, Is.EqualTo(6), "intact: half its sides at 20 D");
            BreakIt(rope, grip);
            Assert.That(renderer.Render(1f), Is.True);
            Assert.That(renderer.DrawnRadialSegments, Is.EqualTo(12), "broken: the burrs keep their strands");
            Assert.That(renderer.DrawnRingTolerance, Is.EqualTo(ViewDetail.RingTolerance(1f, 2f, DistanceToParticleBox(rope, renderer.ViewPoint.position))).Within(1e-4f));
            AssertMeshFollowsRope(rope, renderer.Mesh);
        }

        [TestCase(false, true, TestName = "AViewPointThatMovesEveryFrameAllocatesNothing(the view point)")]
        [TestCase(true, true, TestName = "AViewPointThatMovesEveryFrameAllocatesNothing(the main camera)")]
        [TestCase(false, false, TestName = "AViewPointThatMovesEveryFrameAllocatesNothing(the view point, without tangents)")]
        public void AViewPointThatMovesEveryFrameAllocatesNothing(bool mainCamera, bool tangents)
        {
            var (rope, renderer, grip) = Build();
            renderer.Tangents = tangents;
            var viewer = _scene.Point("Viewer", new Vector3(0f, 2f, 3f));
            if (mainCamera)
            {
                viewer.gameObject.AddComponent<Camera>();
                viewer.gameObject.tag = "MainCamera";
            }
            else renderer.ViewPoint = viewer;
            renderer.DetailDistance = 1f;
            for (int step = 0; step < 20; step++) rope.Simulate(0.01f);
            float nearest = float.PositiveInfinity, farthest = 0f;
            int fewest = int.MaxValue, most = 0;
            void Walk()
            {
                for (int frame = 0; frame < 120; frame++)
                {
                    // the viewer walks from 3 m to 15 m and back: 12 sides, 6 from 4.4 m, 12 again within 4 m
                    viewer.position = new Vector3(0f, 2f, 9f - 6f * System.MathF.Cos(0.05f * frame));
                    renderer.Render(1f);
                    nearest = System.Math.Min(nearest, renderer.DrawnRingTolerance);
                    farthest = System.Math.Max(farthest, renderer.DrawnRingTolerance);
                    fewest = System.Math.Min(fewest, renderer.DrawnRadialSegments);
                    most = System.Math.Max(most, renderer.DrawnRadialSegments);
                }
            }
            // the first walk makes the 6-sided builder and the buffers' sizes; the second only switches between them
            Walk();
            Assert.That(Walk, Is.Not.AllocatingGCMemory(), "120 frames with the viewer moving, the side count switching");
            TestContext.WriteLine("over the walk: " + fewest + " … " + most + " sides, ring tolerance " + nearest + " … " + farthest);
            Assert.That(fewest, Is.EqualTo(6));
            Assert.That(most, Is.EqualTo(12));
            Assert.That(renderer.Mesh.GetVertexBufferStride(0), Is.EqualTo(tangents ? TubeVertex.SizeInBytes : LeanTubeVertex.SizeInBytes));
            Assert.That(nearest, Is.LessThan(3.5f));
            Assert.That(farthest, Is.GreaterThan(3.5f));
            AssertMeshFollowsRope(rope, renderer.Mesh);
        }

        [TestCase(false)]
        [TestCase(true)]
        public void UploadedVerticesAreTheCoreMesh(bool broken)
        {
            var (rope, renderer, grip) = Build();
            var frame = rope.transform;
            frame.position = new Vector3(0.4f, -1.5f, 2f);
            frame.rotation = Quaternion.Euler(10f, 35f, -20f);
            frame.localScale = new Vector3(2f, 2f, 2f);
            for (int step = 0; step < 30; step++) rope.Simulate(0.01f);
            if (broken) BreakIt(rope, grip);
            const float alpha = 0.3f;
            Assert.That(renderer.Render(alpha), Is.True);

            // The same interpolated positions, in the renderer's local space, through the core's one mesh path.
            var simulation = rope.Simulation;
            int particles = rope.ParticleCount;
            var world = new float[3 * particles];
            rope.GetInterpolatedPositions(alpha, world);
            float[] x = new float[particles], y = new float[particles], z = new float[particles];
            for (int i = 0; i < particles; i++)
            {
                var local = frame.InverseTransformPoint(new Vector3(world[3 * i], world[3 * i + 1], world[3 * i + 2]));
                x[i] = local.x;
                y[i] = local.y;
                z[i] = local.z;
            }
            var vertices = new TubeVertex[simulation.GetVertexCount()];
            var indices = new int[simulation.GetIndexCount()];
            var update = simulation.FillMesh(x, y, z, vertices, indices, radiusScale: 0.5f);

            // the vertex buffer holds the ring budget's most (sized once), the sub-meshes the vertices in use
            Assert.That(renderer.Mesh.vertexCount, Is.EqualTo(simulation.GetVertexCapacity()), "vertex buffer = capacity");
            Assert.That(renderer.Mesh.GetSubMesh(0).vertexCount, Is.EqualTo(update.VertexCount), "vertices in use");
            var uploaded = MeshInUse.Vertices(renderer.Mesh);
            Assert.That(uploaded.Length, Is.EqualTo(update.VertexCount));
            for (int v = 0; v < update.VertexCount; v++)
            {
                Assert.That(uploaded[v].x, Is.EqualTo(vertices[v].PX).Within(1e-6f), "vertex " + v);
                Assert.That(uploaded[v].y, Is.EqualTo(vertices[v].PY).Within(1e-6f), "vertex " + v);
                Assert.That(uploaded[v].z, Is.EqualTo(vertices[v].PZ).Within(1e-6f), "vertex " + v);
            }
            var triangles = renderer.Mesh.triangles;
            Assert.That(triangles.Length, Is.EqualTo(update.IndexCount));
            for (int k = 0; k < update.IndexCount; k++) Assert.That(triangles[k], Is.EqualTo(indices[k]), "index " + k);
        }

        /// <summary>The test rope, broken and drawn: its mesh has the tube (submesh 0) and the burr strands (submesh 1).</summary>
        (ElasticRope Rope, RopeMeshRenderer Renderer, Mesh Mesh) BrokenAndDrawn()
        {
            var (rope, renderer, grip) = Build();
            BreakIt(rope, grip);
            Assert.That(renderer.Render(1f), Is.True);
            Assert.That(renderer.Mesh.subMeshCount, Is.EqualTo(2));
            return (rope, renderer, renderer.Mesh);
        }

        static Vector3 WindingNormal(Vector3[] p, int[] t, int k) => Vector3.Cross(p[t[k + 1]] - p[t[k]], p[t[k + 2]] - p[t[k]]);

        /// <summary>
        /// Issue 13 item 6: the burr ends are real geometry, so any opaque material draws them. Submesh 1 holds, per
        /// broken end, one fibre per 1/40 cm² of the cross-section (issue 17), each a closed three-sided spike of three triangles, every one
        /// with area and Unity's front-face winding (geometric normal Cross(b − a, c − a)) along its vertex normal
        /// and away from the strand's centre.
        /// </summary>
        [Test]
        public void BurrStrandsAreOutwardFacingTrianglesWithArea()
        {
            var (rope, renderer, mesh) = BrokenAndDrawn();
            var positions = mesh.vertices;
            var normals = mesh.normals;
            var strands = mesh.GetTriangles(1);
            int radial = renderer.RadialSegments;
            float r = rope.Radius;
            // Issue 17: fibres across the whole cut, 40 per cm² of π R², at least one per radial segment, at most 256.
            int fibres = (int)System.Math.Min(256.0, System.Math.Max(radial, System.Math.Round(40.0 * System.Math.PI * r * r * 1e4)));
            Assert.That(strands.Length, Is.EqualTo(2 * fibres * 9), "two broken ends × fibres × 3 triangles");

            float smallestArea = float.PositiveInfinity, leastAlignment = float.PositiveInfinity, leastOutward = float.PositiveInfinity;
            for (int s = 0; s < strands.Length; s += 9)
            {
                // The spike's four corners (three base points and the tip) average to a point inside it.
                var centre = Vector3.zero;
                for (int q = 0; q < 9; q++) centre += positions[strands[s + q]];
                centre /= 9f;
                for (int k = s; k < s + 9; k += 3)
                {
                    var winding = WindingNormal(positions, strands, k);
                    float area = 0.5f * winding.magnitude;
                    smallestArea = System.Math.Min(smallestArea, area / (r * r));
                    var unit = winding.normalized;
                    var faceCentre = (positions[strands[k]] + positions[strands[k + 1]] + positions[strands[k + 2]]) / 3f;
                    for (int c = 0; c < 3; c++) leastAlignment = System.Math.Min(leastAlignment, Vector3.Dot(unit, normals[strands[k + c]]));
                    leastOutward = System.Math.Min(leastOutward, Vector3.Dot(unit, (faceCentre - centre).normalized));
                }
            }
            TestContext.WriteLine("strand triangles: " + strands.Length / 3 + ", smallest area/r² " + smallestArea + ", least normal·winding " + leastAlignment + ", least outward " + leastOutward);
            Assert.That(smallestArea, Is.GreaterThan(0.01f), "every fibre triangle has an area above 1 % of r²");
            Assert.That(leastAlignment, Is.GreaterThan(0.999f), "vertex normals equal the winding normal: lit on the side drawn");
            Assert.That(leastOutward, Is.GreaterThan(0.5f), "front faces point away from the strand: back-face culling keeps the outside");
        }

        /// <summary>
        /// The tube and caps of a broken rope use the strands' winding: front faces outward. Undamped (issue 17): a step after
        /// the break the upper piece has recoiled into 14 cm (10 segments of 6 cm rest, particles 0.3 mm apart in places,
        /// two of them passed their neighbours): the tube there closes into fold tips and cones whose smooth vertex normals
        /// lean off their thin triangles (measured: more than 26° on 27 % of the area, least cosine 0.086), but no triangle is
        /// wound against its normals and no vertex is lit from behind on any triangle around it.
        /// </summary>
        [Test]
        public void TubeAndCapsWindOutwardLikeTheBurrStrands()
        {
            var mesh = BrokenAndDrawn().Mesh;
            var positions = mesh.vertices;
            var normals = mesh.normals;
            var tube = mesh.GetTriangles(0);
            Assert.That(tube.Length, Is.GreaterThan(0));
            double leastAlignment = double.PositiveInfinity, leastSummed = double.PositiveInfinity, area = 0.0, leaning = 0.0;
            int degenerate = 0;
            for (int k = 0; k < tube.Length; k += 3)
            {
                // the winding normal in double (Vector3.normalized returns zero below a length of 1e-5, a 5 mm² triangle)
                Vector3 a = positions[tube[k]], b = positions[tube[k + 1]], c = positions[tube[k + 2]];
                double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, wx = c.x - a.x, wy = c.y - a.y, wz = c.z - a.z;
                double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
                double length = System.Math.Sqrt(nx * nx + ny * ny + nz * nz);
                if (length == 0.0) { degenerate++; continue; }
                nx /= length; ny /= length; nz /= length;
                area += 0.5 * length;
                double least = double.PositiveInfinity, sx = 0.0, sy = 0.0, sz = 0.0;
                for (int q = 0; q < 3; q++)
                {
                    Vector3 n = normals[tube[k + q]];
                    least = System.Math.Min(least, nx * n.x + ny * n.y + nz * n.z);
                    sx += n.x; sy += n.y; sz += n.z;
                }
                leastAlignment = System.Math.Min(leastAlignment, least);
                leastSummed = System.Math.Min(leastSummed, (nx * sx + ny * sy + nz * sz) / System.Math.Sqrt(sx * sx + sy * sy + sz * sz));
                if (least < 0.9) leaning += 0.5 * length;
            }
            TestContext.WriteLine("tube and cap triangles: " + tube.Length / 3 + ", least normal·winding " + leastAlignment + ", least mean normal·winding " + leastSummed +
                                  ", share of the area with a normal leaning over 26° " + leaning / area);
            Assert.That(degenerate, Is.EqualTo(0));
            Assert.That(leastSummed, Is.GreaterThan(0.0), "one winding convention for the whole mesh: front faces outward");
            Assert.That(leastAlignment, Is.GreaterThan(0.0), "no vertex lit from behind on a triangle it belongs to");
        }
    }
}
