using System;
using NUnit.Framework;
using UnityEngine;

namespace HookeRope.Tests.Components
{
    /// <summary>
    /// Edit mode (in Unity and headless on the Unity stand-in), issue 13 item 6: the burr ends drawn after a break are
    /// real geometry, so they look right with any opaque material. Submesh 1 of the uploaded mesh holds, per broken
    /// end, one strand per radial segment, each a closed three-sided spike of three triangles; every triangle has a
    /// non-zero area and Unity's front-face winding facing outward (geometric normal Cross(b − a, c − a) along the
    /// vertex normal and away from the strand's centre), as every tube and cap triangle of submesh 0 does.
    /// </summary>
    [TestFixture]
    public sealed class RopeBurrGeometryTests
    {
        UnityRopeScene _scene;

        [SetUp] public void SetUp() { _scene = new UnityRopeScene(); _scene.Begin(); }
        [TearDown] public void TearDown() => _scene.End();

        /// <summary>A 1.2 m rope of radius 2 cm between two points, stretched until it breaks, then drawn.</summary>
        (ElasticRope Rope, RopeMeshRenderer Renderer) BrokenRope()
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
            for (int step = 0; step < 300 && !rope.IsBroken; step++)
            {
                grip.position = new Vector3(0.3f, 2f - 0.004f * step, 0f);
                rope.Simulate(0.01f);
            }
            Assert.That(rope.IsBroken, Is.True);
            rope.Simulate(0.01f);
            var renderer = go.GetComponent<RopeMeshRenderer>();
            Assert.That(renderer.Render(1f), Is.True);
            return (rope, renderer);
        }

        static Vector3 WindingNormal(Vector3[] p, int[] t, int k) => Vector3.Cross(p[t[k + 1]] - p[t[k]], p[t[k + 2]] - p[t[k]]);

        [Test]
        public void StrandsAreOutwardFacingTrianglesWithArea()
        {
            var (rope, renderer) = BrokenRope();
            var mesh = renderer.Mesh;
            Assert.That(mesh.subMeshCount, Is.EqualTo(2));
            var positions = mesh.vertices;
            var normals = mesh.normals;
            var strands = mesh.GetTriangles(1);
            int radial = renderer.RadialSegments;
            Assert.That(strands.Length, Is.EqualTo(2 * radial * 9), "two broken ends × one strand per radial segment × 3 triangles");

            float r = rope.Radius;
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
                    smallestArea = Math.Min(smallestArea, area / (r * r));
                    var unit = winding.normalized;
                    var faceCentre = (positions[strands[k]] + positions[strands[k + 1]] + positions[strands[k + 2]]) / 3f;
                    for (int c = 0; c < 3; c++) leastAlignment = Math.Min(leastAlignment, Vector3.Dot(unit, normals[strands[k + c]]));
                    leastOutward = Math.Min(leastOutward, Vector3.Dot(unit, (faceCentre - centre).normalized));
                }
            }
            TestContext.WriteLine("strand triangles: " + strands.Length / 3 + ", smallest area/r² " + smallestArea + ", least normal·winding " + leastAlignment + ", least outward " + leastOutward);
            Assert.That(smallestArea, Is.GreaterThan(0.1f), "every strand triangle has an area above 10 % of r²");
            Assert.That(leastAlignment, Is.GreaterThan(0.999f), "vertex normals equal the winding normal: lit on the side drawn");
            Assert.That(leastOutward, Is.GreaterThan(0.5f), "front faces point away from the strand: back-face culling keeps the outside");
        }

        [Test]
        public void TubeAndCapsWindOutwardLikeTheStrands()
        {
            var (_, renderer) = BrokenRope();
            var mesh = renderer.Mesh;
            var positions = mesh.vertices;
            var normals = mesh.normals;
            var tube = mesh.GetTriangles(0);
            Assert.That(tube.Length, Is.GreaterThan(0));
            float leastAlignment = float.PositiveInfinity;
            int degenerate = 0;
            for (int k = 0; k < tube.Length; k += 3)
            {
                var winding = WindingNormal(positions, tube, k);
                if (winding.sqrMagnitude == 0f) { degenerate++; continue; }
                var unit = winding.normalized;
                for (int c = 0; c < 3; c++) leastAlignment = Math.Min(leastAlignment, Vector3.Dot(unit, normals[tube[k + c]]));
            }
            TestContext.WriteLine("tube and cap triangles: " + tube.Length / 3 + ", least normal·winding " + leastAlignment);
            Assert.That(degenerate, Is.EqualTo(0));
            Assert.That(leastAlignment, Is.GreaterThan(0.9f), "one winding convention for the whole mesh: front faces outward");
        }
    }
}
