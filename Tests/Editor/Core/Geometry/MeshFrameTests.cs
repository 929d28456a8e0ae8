using System;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// Issue 17 item 4 for caller frames: positions given in a rotated, scaled, shifted frame (a renderer's local
    /// space) with its <see cref="MeshFrame"/> give the rope-local mesh (pushed out of the collider) seen from that
    /// frame; without the frame the same positions sink into the collider. Bad frames throw.
    /// </summary>
    public sealed class MeshFrameTests
    {
        private const float R = 0.01f;
        private const float Bar = 0.1f;
        private static readonly Float3 BarCentre = new Float3(0f, 1f, 0f);

        /// <summary>A 4-segment rope laid over a 0.1 m sphere at (0, 1, 0), its particles 45° apart on the sphere plus R.</summary>
        internal static RopeSimulation WrappedRope()
        {
            var settings = new RopeSettings { RestLength = 0.35f, SegmentCount = 4, Radius = R };
            var sim = new RopeSimulation(settings, new Float3(-0.11f, 1f, 0f), new Float3(0.11f, 1f, 0f));
            sim.Rope.AddCollider(ColliderShape.Sphere(BarCentre, Bar));
            for (int i = 0; i <= 4; i++)
            {
                double angle = Math.PI * (1.0 - i / 4.0);
                sim.Rope.SetPosition(i, BarCentre + new Float3((float)Math.Cos(angle), (float)Math.Sin(angle), 0f) * (Bar + R));
            }
            return sim;
        }

        private static float Deepest(TubeVertex[] vertices, int count, Func<Float3, Float3> toWorld)
        {
            float deepest = float.PositiveInfinity;
            for (int v = 0; v < count; v++)
                deepest = Math.Min(deepest, (toWorld(new Float3(vertices[v].PX, vertices[v].PY, vertices[v].PZ)) - BarCentre).Length - Bar);
            return deepest;
        }

        [Test]
        public void RotatedScaledFrameDrawsTheRopeLocalMeshOutsideTheCollider()
        {
            RopeSimulation sim = WrappedRope();
            Rope rope = sim.Rope;
            var reference = new TubeVertex[sim.GetVertexCount()];
            var framed = new TubeVertex[reference.Length];
            var frameless = new TubeVertex[reference.Length];
            var indices = new int[sim.GetIndexCount()];
            var a = sim.FillMesh(reference, indices);

            // caller frame: at (0.4, 0.3, -0.2), rotated 50° about (1, 2, -1), 1.7 m per unit
            var frame = new MeshFrame(new Float3(0.4f, 0.3f, -0.2f), Quat.FromAxisAngle(new Float3(1f, 2f, -1f), 0.87f), 1.7f);
            int n = rope.ParticleCount;
            float[] x = new float[n], y = new float[n], z = new float[n];
            for (int i = 0; i < n; i++)
            {
                Float3 world = rope.Origin + new Float3(rope.PositionX[i], rope.PositionY[i], rope.PositionZ[i]);
                Float3 local = frame.Rotation.Conjugate.Rotate(world - frame.Origin) * (1f / frame.Scale);
                x[i] = local.X; y[i] = local.Y; z[i] = local.Z;
            }
            var b = sim.FillMesh(x, y, z, framed, indices, 1f / frame.Scale, frame);
            var c = sim.FillMesh(x, y, z, frameless, indices, 1f / frame.Scale);

            Func<Float3, Float3> fromFrame = p => frame.Origin + frame.Rotation.Rotate(p * frame.Scale);
            float deepestReference = Deepest(reference, a.VertexCount, p => rope.Origin + p);
            float deepestFramed = Deepest(framed, b.VertexCount, fromFrame);
            float deepestFrameless = Deepest(frameless, c.VertexCount, fromFrame);
            TestContext.WriteLine("deepest vertex below the sphere: rope-local " + deepestReference / R + " R, framed " +
                                  deepestFramed / R + " R, frameless " + deepestFrameless / R + " R");
            Assert.That(deepestFrameless, Is.LessThan(-0.1f * R), "without the frame the tube sinks in (the case being fixed)");
            Assert.That(deepestFramed, Is.GreaterThan(-0.02f * R));
            // every ring and cap (blocks of radial + 1 vertices; vertices 1..radial go once round the ring) has the
            // reference's centre and radius; only the rings' phase may differ (frames are transported from the caller's axes)
            Assert.That(b.VertexCount, Is.EqualTo(a.VertexCount));
            int radial = sim.MeshSettings.RadialSegments;
            for (int block = 0; block + radial < a.VertexCount; block += radial + 1)
            {
                Float3 expected = RingCentre(reference, block, radial, p => rope.Origin + p, out float expectedRadius);
                Float3 actual = RingCentre(framed, block, radial, fromFrame, out float actualRadius);
                Assert.That((actual - expected).Length, Is.LessThan(1e-3f * R), "centre of the ring at vertex " + block);
                Assert.That(actualRadius, Is.EqualTo(expectedRadius).Within(1e-3f * R), "radius of the ring at vertex " + block);
            }
        }

        /// <summary>World centre (m) and radius (m) of the ring whose vertices 1..radial follow <paramref name="block"/>.</summary>
        private static Float3 RingCentre(TubeVertex[] vertices, int block, int radial, Func<Float3, Float3> toWorld, out float radius)
        {
            Float3 sum = Float3.Zero;
            for (int i = 1; i <= radial; i++)
                sum = sum + toWorld(new Float3(vertices[block + i].PX, vertices[block + i].PY, vertices[block + i].PZ));
            Float3 centre = sum * (1f / radial);
            radius = (toWorld(new Float3(vertices[block + 1].PX, vertices[block + 1].PY, vertices[block + 1].PZ)) - centre).Length;
            return centre;
        }

        [Test]
        public void BadFramesThrowNamingTheParameter()
        {
            var scale = Assert.Throws<ArgumentOutOfRangeException>(() => new MeshFrame(Float3.Zero, Quat.Identity, 0f));
            Assert.That(scale.ParamName, Is.EqualTo("scale"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new MeshFrame(Float3.Zero, Quat.Identity, float.NaN)).ParamName, Is.EqualTo("scale"));
            Assert.That(Assert.Throws<ArgumentException>(() => new MeshFrame(new Float3(float.PositiveInfinity, 0f, 0f), Quat.Identity, 1f)).ParamName, Is.EqualTo("origin"));
            Assert.That(Assert.Throws<ArgumentException>(() => new MeshFrame(Float3.Zero, new Quat(0f, 0f, 0f, 0f), 1f)).ParamName, Is.EqualTo("rotation"));
        }
    }
}
