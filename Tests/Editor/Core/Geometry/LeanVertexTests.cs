using System;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Solver;
using HookeRope.Tests.Core.Fracture;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// Issue 18 item 2: a fill into vertices without tangents (<see cref="LeanTubeVertex"/>, 32 bytes) writes the bits of
    /// a <see cref="TubeVertex"/> fill in every field they share, with the same indices and bounds, on every path: both
    /// lean kernels (8-float vectors and 4-float: the vector paths off; with 4-lane vectors, as under Unity's Mono and
    /// IL2CPP, <c>.ci/run</c> runs the mesh fixtures again with AVX2 off), incremental builds, caps, fold tips, strip normals, broken ends with
    /// dangling halves and burr strands. Two identical simulations are stepped side by side, one filled each way.
    /// </summary>
    public sealed class LeanVertexTests
    {
        private const float HostStep = 1f / 90f;

        private static readonly int[] Sides = { 3, 8, 9, 12, 16, 24, 32 };

        private static readonly int[] CordSides = { 8, 12, 16, 32 };

        /// <summary>
        /// A capped lanyard 37 m from the origin (the frame origin is added last), dropped and whipped by its far pin for
        /// 60 frames, at side counts with and without an odd last vertex, with the vector paths on and off.
        /// </summary>
        [Test]
        public void AWhippedLanyardDrawsTheBitsOfTheFullVerticesWithoutTangents(
            [ValueSource(nameof(Sides))] int sides, [Values(true, false)] bool vectors)
        {
            var settings = new RopeSettings { SegmentCount = 24 };
            RopeSimulation Make()
            {
                RopeSimulation s = GoalLanyard.Pinned(settings, 37.25f, 1.4f);
                s.MeshSettings.RadialSegments = sides;
                return s;
            }
            var pair = new Pair(Make(), Make(), vectors);
            int radiiOnly = 0;
            for (int frame = 0; frame < 60; frame++)
            {
                if (frame >= 30)
                {
                    float t = (frame - 30) * HostStep;
                    var target = new Float3(38.65f - 0.3f * MathF.Sin(6f * MathF.PI * t), 2f + 0.4f * MathF.Sin(6f * MathF.PI * t), 0f);
                    pair.Tangents.Rope.SetPinTarget(1, target);
                    pair.Lean.Rope.SetPinTarget(1, target);
                }
                pair.Step();
                pair.AssertSameMesh(sides + " sides, frame " + frame);
                // the same pose with thinner radii: the radius-only build of the lean kernel
                pair.AssertSameMesh(sides + " sides, frame " + frame + ", radii only", 0.999f);
                if (pair.Lean.Mesh.Builder.LastBuild == TubeMeshBuilder.BuildKind.RadiiOnly) radiiOnly++;
            }
            Assert.That(radiiOnly, Is.GreaterThan(0), "radius-only builds were compared");
        }

        /// <summary>The lab's fracture cord pulled to its break and 25 steps on: necks, caps, dangling halves, burr strands, fold tips and strip normals.</summary>
        [Test]
        public void ABreakingCordDrawsTheBitsOfTheFullVerticesWithoutTangents([ValueSource(nameof(CordSides))] int sides, [Values(true, false)] bool vectors)
        {
            int pin = 0;
            RopeSimulation Make() => FractureCord.Build(new TubeMeshSettings { RadialSegments = sides }, out pin);
            var pair = new Pair(Make(), Make(), vectors);
            int step = 0, after = -1, stripRings = 0;
            while (after < 25 && step < 500)
            {
                step++;
                var target = new Float3(1f + 0.5f * step * HostStep, 0f, 0f);
                pair.Tangents.Rope.SetPinTarget(pin, target);
                pair.Lean.Rope.SetPinTarget(pin, target);
                pair.Step();
                pair.AssertSameMesh("cord, " + sides + " sides, step " + step);
                if (pair.Lean.IsBroken) after++;
                pair.Lean.Mesh.Builder.FoldCounts(out _, out _, out int strips);
                stripRings = Math.Max(stripRings, strips);
            }
            Assert.That(after, Is.EqualTo(25), "the cord breaks and is drawn 25 steps on");
            Assert.That(pair.BurrIndices, Is.GreaterThan(0), "burr strands were compared (submesh 1 had indices)");
            Assert.That(stripRings, Is.GreaterThan(0), "rings with strip normals were compared");
        }

        /// <summary>
        /// One simulation filled into a full buffer, then a lean one, then the same full buffer again (stale bytes written
        /// into it meanwhile), at rest: the other kind of buffer is a full build, and each fill gives the bits of a fresh
        /// simulation's fill.
        /// </summary>
        [Test]
        public void SwitchingTheKindOfBufferRewritesEveryVertex()
        {
            var settings = new RopeSettings { SegmentCount = 16 };
            RopeSimulation switching = GoalLanyard.Pinned(settings, 0f, 1.2f);
            RopeSimulation reference = GoalLanyard.Pinned(settings, 0f, 1.2f);
            for (int i = 0; i < 20; i++) { switching.Step(HostStep); reference.Step(HostStep); }
            int capacity = switching.GetVertexCapacity(), indexCapacity = switching.GetIndexCapacity();
            var full = new TubeVertex[capacity];
            var lean = new LeanTubeVertex[capacity];
            var expected = new TubeVertex[capacity];
            var indices = new int[indexCapacity];
            var expectedIndices = new int[indexCapacity];
            switching.FillMesh(full, indices);
            TubeMeshUpdate leanUpdate = switching.FillMesh(lean, indices);
            Assert.That(switching.Mesh.Builder.LastBuild, Is.EqualTo(TubeMeshBuilder.BuildKind.Full), "another kind of buffer: a full build");
            for (int i = 0; i < capacity; i++) full[i].PX = float.NaN;   // stale bytes that must be overwritten
            switching.FillMesh(full, indices);
            Assert.That(switching.Mesh.Builder.LastBuild, Is.EqualTo(TubeMeshBuilder.BuildKind.Full), "the full buffer again: a full build");
            TubeMeshUpdate update = reference.FillMesh(expected, expectedIndices);
            Assert.That(MeshChecks.DifferingVertices(expected, full, update.VertexCount), Is.EqualTo(0), "full again: the bits of a fresh fill");
            Assert.That(DifferingFields(expected, lean, leanUpdate.VertexCount), Is.EqualTo(0), "lean: the fields of a fresh full fill");
        }

        /// <summary>After warm-up a lean fill of a moving rope allocates nothing (RopeSimulation.FillMesh into caller buffers).</summary>
        [Test]
        public void ALeanFillAllocatesNothing()
        {
            var settings = new RopeSettings { SegmentCount = 32 };
            RopeSimulation s = GoalLanyard.Pinned(settings, 0f, 1.5f);
            s.MeshSettings.RadialSegments = 16;
            var vertices = new LeanTubeVertex[s.GetVertexCapacity()];
            var indices = new int[s.GetIndexCapacity()];
            for (int i = 0; i < 10; i++) { s.Step(HostStep); s.FillMesh(vertices, indices); }
            // the fewest of six rounds: the runtime's own tier-up may allocate on the thread in one of them
            long fewest = long.MaxValue;
            for (int round = 0; round < 6; round++)
            {
                long allocated = 0;
                for (int i = 0; i < 30; i++)
                {
                    s.Step(HostStep);
                    long before = GC.GetAllocatedBytesForCurrentThread();
                    s.FillMesh(vertices, indices);
                    allocated += GC.GetAllocatedBytesForCurrentThread() - before;
                }
                fewest = Math.Min(fewest, allocated);
            }
            Assert.That(fewest, Is.EqualTo(0), "bytes allocated by 30 lean fills (fewest of six rounds)");
        }

        /// <summary>A missing or short lean buffer is named, as for the full one.</summary>
        [Test]
        public void ABadLeanBufferIsNamed()
        {
            RopeSimulation s = GoalLanyard.Pinned(new RopeSettings { SegmentCount = 8 }, 0f, 1f);
            var indices = new int[s.GetIndexCapacity()];
            Assert.That(() => s.FillMesh((LeanTubeVertex[])null, indices),
                Throws.TypeOf<ArgumentNullException>().With.Property("ParamName").EqualTo("vertices"));
            Assert.That(() => s.FillMesh(new LeanTubeVertex[3], indices),
                Throws.ArgumentException.With.Property("ParamName").EqualTo("vertices").And.Message.Contain("GetVertexCount"));
        }

        /// <summary>The size of a lean vertex: the 32 bytes its upload layout (position, normal, uv in float32) promises.</summary>
        [Test]
        public void ALeanVertexIsThirtyTwoBytes()
        {
            Assert.That(System.Runtime.InteropServices.Marshal.SizeOf<LeanTubeVertex>(), Is.EqualTo(LeanTubeVertex.SizeInBytes));
            Assert.That(LeanTubeVertex.SizeInBytes * 3, Is.EqualTo(TubeVertex.SizeInBytes * 2), "two thirds of a full vertex");
        }

        /// <summary>Vertices among the first <paramref name="count"/> whose position, normal or uv differ in a bit.</summary>
        internal static int DifferingFields(TubeVertex[] full, LeanTubeVertex[] lean, int count)
        {
            int differing = 0;
            for (int i = 0; i < count; i++)
            {
                TubeVertex f = full[i];
                LeanTubeVertex l = lean[i];
                bool same = Bits(f.PX) == Bits(l.PX) && Bits(f.PY) == Bits(l.PY) && Bits(f.PZ) == Bits(l.PZ)
                    && Bits(f.NX) == Bits(l.NX) && Bits(f.NY) == Bits(l.NY) && Bits(f.NZ) == Bits(l.NZ)
                    && Bits(f.U) == Bits(l.U) && Bits(f.V) == Bits(l.V);
                if (!same) differing++;
            }
            return differing;
        }

        private static int Bits(float v) => BitConverter.SingleToInt32Bits(v);

        /// <summary>Two simulations of one scene: one filled with tangents, one without, both as an application fills them.</summary>
        private sealed class Pair
        {
            public readonly RopeSimulation Tangents, Lean;
            private readonly bool vectors;
            private TubeVertex[] fullVertices = new TubeVertex[0];
            private LeanTubeVertex[] leanVertices = new LeanTubeVertex[0];
            private int[] fullIndices = new int[0], leanIndices = new int[0];
            public int BurrIndices;

            public Pair(RopeSimulation tangents, RopeSimulation lean, bool vectorPaths)
            {
                Tangents = tangents;
                Lean = lean;
                vectors = vectorPaths;
            }

            public void Step()
            {
                Tangents.Step(HostStep);
                Lean.Step(HostStep);
            }

            /// <summary>Fills both (positions the rope's, ring radii times <paramref name="radiusScale"/>) and compares.</summary>
            public void AssertSameMesh(string what, float radiusScale = 1f)
            {
                if (fullVertices.Length < Tangents.GetVertexCapacity()) fullVertices = new TubeVertex[Tangents.GetVertexCapacity()];
                if (fullIndices.Length < Tangents.GetIndexCapacity()) fullIndices = new int[Tangents.GetIndexCapacity()];
                if (leanVertices.Length < Lean.GetVertexCapacity()) leanVertices = new LeanTubeVertex[Lean.GetVertexCapacity()];
                if (leanIndices.Length < Lean.GetIndexCapacity()) leanIndices = new int[Lean.GetIndexCapacity()];
                bool enabled = VectorPath.Enabled;
                TubeMeshUpdate full, lean;
                try
                {
                    VectorPath.Enabled = vectors;
                    Rope a = Tangents.Rope, b = Lean.Rope;
                    full = Tangents.FillMesh(a.PositionX, a.PositionY, a.PositionZ, fullVertices, fullIndices, radiusScale);
                    lean = Lean.FillMesh(b.PositionX, b.PositionY, b.PositionZ, leanVertices, leanIndices, radiusScale);
                }
                finally
                {
                    VectorPath.Enabled = enabled;
                }
                Assert.That(lean.VertexCount, Is.EqualTo(full.VertexCount), what + ": vertices");
                Assert.That(lean.IndexCount, Is.EqualTo(full.IndexCount), what + ": indices");
                Assert.That(DifferingFields(fullVertices, leanVertices, full.VertexCount), Is.EqualTo(0), what + ": vertices with other bits");
                int differing = 0;
                for (int i = 0; i < full.IndexCount; i++) if (fullIndices[i] != leanIndices[i]) differing++;
                Assert.That(differing, Is.EqualTo(0), what + ": other indices");
                Assert.That(lean.BoundsMin, Is.EqualTo(full.BoundsMin), what + ": bounds min");
                Assert.That(lean.BoundsMax, Is.EqualTo(full.BoundsMax), what + ": bounds max");
                BurrIndices = Math.Max(BurrIndices, lean.IndexCount - lean.TubeIndexCount);
            }
        }
    }
}
