using System;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Solver;
using HookeRope.Tests.Core.Fracture;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Geometry
{
    /// <summary>
    /// Issue 18 item 2: the fill's fast paths give the mesh bytes of the full work. Two identical simulations are stepped
    /// side by side; one fills its mesh with the vector paths off (<see cref="VectorPath.Enabled"/>), every limit pass run
    /// (<see cref="TubeMeshBuilder.ForceFullLimits"/>) and everything recomputed (<see cref="TubeMeshBuilder.AlwaysRebuild"/>),
    /// the other as an application does (vector paths on, skips and incremental builds allowed). Every vertex word, index
    /// and the bounds must be the same bits at every frame.
    /// </summary>
    public sealed class MeshFastPathTests
    {
        private const float HostStep = 1f / 90f;

        private static readonly int[] Sides = { 8, 16, 32 };

        /// <summary>Side counts for the wide ring kernel (two vertices per three 8-float vectors): odd tail vertex at even counts, none at odd ones.</summary>
        private static readonly int[] KernelSides = { 3, 8, 9, 12, 16, 24, 32 };

        /// <summary>Side counts for the breaking cord (broken ends: caps, dangling halves, burrs) with the wide ring kernel.</summary>
        private static readonly int[] CordSides = { 8, 12, 16, 24, 32 };

        /// <summary>
        /// Issue 18 (s13): the wide ring kernel (<see cref="System.Numerics.Vector{T}"/> of 8 floats, engaged where the runtime has
        /// AVX2) writes the bytes of the 4-float kernel at every side count, including the odd last vertex, the capped ends'
        /// rims, a tapering radius (tilted normals) and a rope far from the origin (the frame origin added last): a capped
        /// lanyard away from the origin, dropped and whipped, 60 frames.
        /// </summary>
        [TestCaseSource(nameof(KernelSides))]
        public void TheWideRingKernelWritesTheSameBitsAtEverySideCount(int sides)
        {
            DropAndWhip(24, 37.25f, 1.4f, sides, true, 60, 30, "capped lanyard");
        }

        /// <summary>
        /// Issue 18 (s14): a ring closer than PushDistance·r to the previous one moves on along the step between the two
        /// rings before it. Particles 1 m along +x, 1 m along +y, then three more on the last (zero-length segments): the
        /// first of them (ring 3) steps PushDistance·r + 1e-7 along +y (x stays 1), not along the piece's first-to-last
        /// diagonal (the later rings on the same point are not checked here).
        /// </summary>
        [Test]
        public void APushedRingMovesOnAlongTheTwoRingsBeforeIt()
        {
            const float r = 0.05f;
            const int sides = 8;
            var shape = new RopeShape(5, 1f);
            shape.X[1] = 1f; shape.X[2] = 1f; shape.Y[2] = 1f;
            for (int i = 3; i <= 5; i++) { shape.X[i] = 1f; shape.Y[i] = 1f; }
            var builder = new TubeMeshBuilder(new TubeMeshSettings { RadialSegments = sides, RingsPerSegment = 1, CapEnds = false }, 5);
            TubeMeshTopologyTests.Build(builder, shape, r, new bool[5], out TubeVertex[] vertices, out _);
            float step = TubeMeshBuilder.PushDistance * r + 1e-7f;
            const int ring = 3;
            {
                double cx = 0, cy = 0, cz = 0;
                for (int s = 0; s < sides; s++)
                {
                    TubeVertex v = vertices[ring * (sides + 1) + s];
                    cx += v.PX; cy += v.PY; cz += v.PZ;
                }
                cx /= sides; cy /= sides; cz /= sides;
                Assert.That(cx, Is.EqualTo(1.0).Within(2e-5), "ring " + ring + " x");
                Assert.That(cz, Is.EqualTo(0.0).Within(2e-5), "ring " + ring + " z");
                Assert.That(cy, Is.EqualTo(1.0 + (ring - 2) * step).Within(2e-5), "ring " + ring + " y");
            }
        }

        /// <summary>
        /// Issue 18 (s17): the ring centres' and slopes' lanes (the settling, the Catmull–Rom weights, the outer control
        /// points, the interior slopes) draw the bits of the scalar loops, also where a block must fall back: a 40-segment
        /// curve with 4 rings a segment and a radius that steps between segments, as it is (every block on lanes), with
        /// particles 12 and 13 on one point (pushed rings inside a block) and with segment 15 20× shorter than its
        /// neighbours (a tangent at its ends needs its limit), each built with the vector paths off and on.
        /// </summary>
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        public void TheCentreAndSlopeLanesDrawTheBitsOfTheScalarLoops(int variant)
        {
            const int segments = 40;
            var shape = new RopeShape(segments, 0.1f);
            float x = 0f;
            for (int i = 0; i <= segments; i++)
            {
                if (i > 0) x += variant == 1 && i == 13 ? 0f : variant == 2 && i == 16 ? 0.005f : 0.1f;
                shape.X[i] = x;
                shape.Y[i] = 0.03f * MathF.Sin(0.7f * i);
                shape.Z[i] = 0.02f * MathF.Cos(0.45f * i);
            }
            if (variant == 1) { shape.Y[13] = shape.Y[12]; shape.Z[13] = shape.Z[12]; }
            var radii = new float[segments];
            for (int j = 0; j < segments; j++) radii[j] = j % 5 == 3 ? 0.045f : 0.01f;
            var broken = new bool[segments];
            var settings = new TubeMeshSettings { RadialSegments = 16, RingsPerSegment = 4, CapEnds = true };
            var both = new BuiltBothWays(new TubeMeshBuilder(settings, segments), new TubeMeshBuilder(settings, segments), broken,
                (builder, vertices, indices) => builder.Build(shape.X, shape.Y, shape.Z, shape.Rest, radii, broken, vertices, indices));
            TubeMeshUpdate full = both.Scalar, fast = both.Lanes;
            Assert.That(fast.VertexCount, Is.EqualTo(full.VertexCount), "vertices");
            Assert.That(MeshChecks.DifferingVertices(both.ScalarVertices, both.LanesVertices, full.VertexCount), Is.EqualTo(0), "vertices with other bits");
            for (int i = 0; i < full.IndexCount; i++) Assert.That(both.LanesIndices[i], Is.EqualTo(both.ScalarIndices[i]), "index " + i);
            Assert.That(BoundsBits(fast), Is.EqualTo(BoundsBits(full)), "bounds");

            static string BoundsBits(TubeMeshUpdate u) => string.Join(" ", BitConverter.SingleToInt32Bits(u.BoundsMin.X),
                BitConverter.SingleToInt32Bits(u.BoundsMin.Y), BitConverter.SingleToInt32Bits(u.BoundsMin.Z),
                BitConverter.SingleToInt32Bits(u.BoundsMax.X), BitConverter.SingleToInt32Bits(u.BoundsMax.Y),
                BitConverter.SingleToInt32Bits(u.BoundsMax.Z));
        }

        /// <summary>
        /// Issue 18 (s18): the ring radii's clamp on lanes (TubeMeshBuilder.ClampRadii: finite and above 1e-6 m, else
        /// 1e-6 m) draws the bits of the scalar clamp for the radii a lane can get wrong — NaN, ±∞, ±0, negative, 1e-6 itself,
        /// its neighbours, subnormal, float.MaxValue — spread over the blocks and the tail of a 40-segment rope's rings, built
        /// with the vector paths off and on.
        /// </summary>
        [Test]
        public void TheRadiusClampOnLanesDrawsTheBitsOfTheScalarClamp()
        {
            const int segments = 40;
            var shape = new RopeShape(segments, 0.1f);
            for (int i = 0; i <= segments; i++)
            {
                shape.X[i] = 0.1f * i;
                shape.Y[i] = 0.03f * MathF.Sin(0.7f * i);
                shape.Z[i] = 0.02f * MathF.Cos(0.45f * i);
            }
            var broken = new bool[segments];
            var settings = new TubeMeshSettings { RadialSegments = 16, RingsPerSegment = 4, CapEnds = true };
            var scalar = new TubeMeshBuilder(settings, segments);
            var lanes = new TubeMeshBuilder(settings, segments);
            float[] odd = { float.NaN, float.PositiveInfinity, float.NegativeInfinity, 0f, -0f, -0.01f, 1e-6f,
                BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(1e-6f) + 1),
                BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(1e-6f) - 1), 1e-45f, float.MaxValue };
            var radii = new float[scalar.Layout.RingCount];
            for (int k = 0; k < radii.Length; k++) radii[k] = k % 3 == 1 ? odd[(k / 3) % odd.Length] : 0.01f + 0.0001f * k;
            // the last rings (the scalar tail at every vector width) odd too
            for (int k = 1; k <= 4; k++) radii[radii.Length - k] = odd[k];
            var both = new BuiltBothWays(scalar, lanes, broken,
                (builder, vertices, indices) => builder.BuildWithRingRadii(shape.X, shape.Y, shape.Z, shape.Rest, radii, broken, vertices, indices));
            Assert.That(both.Lanes.VertexCount, Is.EqualTo(both.Scalar.VertexCount), "vertices");
            Assert.That(MeshChecks.DifferingVertices(both.ScalarVertices, both.LanesVertices, both.Scalar.VertexCount), Is.EqualTo(0), "vertices with other bits");
        }

        /// <summary>
        /// One mesh built by two builders into buffers of their own: <see cref="Scalar"/> with the vector paths off, then
        /// <see cref="Lanes"/> with them on (the switch restored afterwards), for tests that compare the two bit for bit.
        /// </summary>
        private sealed class BuiltBothWays
        {
            public readonly TubeMeshUpdate Scalar, Lanes;
            public readonly TubeVertex[] ScalarVertices, LanesVertices;
            public readonly int[] ScalarIndices, LanesIndices;

            public BuiltBothWays(TubeMeshBuilder scalar, TubeMeshBuilder lanes, bool[] broken,
                Func<TubeMeshBuilder, TubeVertex[], int[], TubeMeshUpdate> build)
            {
                ScalarVertices = new TubeVertex[scalar.GetVertexCount(broken)];
                LanesVertices = new TubeVertex[lanes.GetVertexCount(broken)];
                ScalarIndices = new int[scalar.GetIndexCount(broken)];
                LanesIndices = new int[lanes.GetIndexCount(broken)];
                bool enabled = VectorPath.Enabled;
                try
                {
                    VectorPath.Enabled = false;
                    Scalar = build(scalar, ScalarVertices, ScalarIndices);
                    VectorPath.Enabled = true;
                    Lanes = build(lanes, LanesVertices, LanesIndices);
                }
                finally
                {
                    VectorPath.Enabled = enabled;
                }
            }
        }

        /// <summary>The goal lanyard (64 segments) dropped from straight, then whipped by one pin: 150 frames.</summary>
        [TestCaseSource(nameof(Sides))]
        public void ADroppedAndWhippedLanyardDrawsTheSameBitsOnEveryPath(int sides)
        {
            Pair reference = DropAndWhip(64, 0f, 1.8f, sides, true, 150, 60, "lanyard");
            Assert.That(reference.MostRings, Is.GreaterThan(2 * 64), "the whipped lanyard draws more than two rings per segment at some frame");
        }

        /// <summary>
        /// Issue 18 (s15): the frames of a piece without folds in two passes (the centres' pass, then the transport alone)
        /// give the bits of the one frame loop that repairs folds as it goes (<see cref="TubeMeshBuilder.ForceFullLimits"/>),
        /// both with the vector paths off: the dropped and whipped lanyard, 150 frames.
        /// </summary>
        [TestCaseSource(nameof(Sides))]
        public void TheTwoFramePassesDrawTheBitsOfTheOneFrameLoop(int sides)
        {
            DropAndWhip(64, 0f, 1.8f, sides, true, 150, 60, "lanyard, two passes", fullLimits: true, fastVectors: false);
        }

        /// <summary>
        /// Issue 18 (s15): the first frame pass on <see cref="System.Numerics.Vector{T}"/> lanes (tangents, ring distances,
        /// fold tests, crossing caps of several rings at once) gives the bits of the scalar pass (vector paths off, the same
        /// two passes): the dropped and whipped lanyard, 150 frames, and the lane pass did draw pieces where the runtime
        /// accelerates vectors.
        /// </summary>
        [TestCaseSource(nameof(Sides))]
        public void TheFramePassOnLanesDrawsTheBitsOfTheScalarPass(int sides)
        {
            Pair pair = DropAndWhip(64, 0f, 1.8f, sides, true, 150, 60, "lanyard, frame lanes", fullLimits: false, fastVectors: true);
            if (System.Numerics.Vector.IsHardwareAccelerated)
                Assert.That(pair.Fast.Mesh.Builder.FramePiecesOnLanes, Is.GreaterThanOrEqualTo(60), "pieces whose first frame pass ran on lanes (at least the 60 frames of the drop)");
        }

        /// <summary>
        /// A lanyard of <paramref name="segments"/> pinned at x … x + span, dropped from straight and, from frame
        /// <paramref name="whipFrom"/>, whipped by its far pin (0.4 m at 3 Hz, up and down and toward the near pin), its
        /// meshes compared at every frame.
        /// </summary>
        private static Pair DropAndWhip(int segments, float x, float span, int sides, bool caps, int frames, int whipFrom, string what,
            bool fullLimits = true, bool fastVectors = true)
        {
            var settings = new RopeSettings { SegmentCount = segments };
            RopeSimulation Make()
            {
                RopeSimulation s = GoalLanyard.Pinned(settings, x, span);
                s.MeshSettings.RadialSegments = sides;
                s.MeshSettings.CapEnds = caps;
                return s;
            }
            var pair = new Pair(Make(), Make()) { FullLimits = fullLimits, FastVectors = fastVectors };
            for (int frame = 0; frame < frames; frame++)
            {
                if (frame >= whipFrom)
                {
                    float t = (frame - whipFrom) * HostStep;
                    var target = new Float3(x + span - 0.3f * MathF.Sin(6f * MathF.PI * t), 2f + 0.4f * MathF.Sin(6f * MathF.PI * t), 0f);
                    pair.Full.Rope.SetPinTarget(1, target);
                    pair.Fast.Rope.SetPinTarget(1, target);
                }
                pair.Step();
                pair.AssertSameMesh(what + ", " + sides + " sides, frame " + frame);
            }
            return pair;
        }

        /// <summary>The lab's fracture cord (<see cref="FractureCord"/>: Zone neck, fracture, burr strands) pulled to its break and 25 frames on: necks, broken ends with burrs, dangling halves and fold tips.</summary>
        [TestCaseSource(nameof(CordSides))]
        public void ANeckingBreakingCordDrawsTheSameBitsOnEveryPath(int sides)
        {
            int pin = 0;
            RopeSimulation Make() => FractureCord.Build(new TubeMeshSettings { RadialSegments = sides }, out pin);
            var pair = new Pair(Make(), Make());
            int step = 0, after = -1, tips = 0;
            bool necked = false;
            while (after < 25 && step < 500)
            {
                step++;
                var target = new Float3(1f + 0.5f * step * HostStep, 0f, 0f);
                pair.Full.Rope.SetPinTarget(pin, target);
                pair.Fast.Rope.SetPinTarget(pin, target);
                pair.Step();
                pair.AssertSameMesh("cord, " + sides + " sides, step " + step);
                necked |= pair.Fast.RadiusModel.NeckDepth > 0f;
                if (pair.Fast.IsBroken) after++;
                pair.Fast.Mesh.Builder.FoldCounts(out int t, out _, out _);
                tips = Math.Max(tips, t);
            }
            Assert.That(necked, Is.True, "the cord necks before it breaks");
            Assert.That(after, Is.EqualTo(25), "the cord breaks and is drawn 25 steps on");
            Assert.That(tips, Is.GreaterThan(0), "the recoiling pieces fold into tips (the limit passes do work)");
        }

        /// <summary>Two simulations of one scene: Full fills with every fast path off, Fast as an application does.</summary>
        private sealed class Pair
        {
            public readonly RopeSimulation Full, Fast;
            private TubeVertex[] fullVertices = new TubeVertex[0], fastVertices = new TubeVertex[0];
            private int[] fullIndices = new int[0], fastIndices = new int[0];
            public int MostRings;
            /// <summary>Full runs every limit pass and the one frame loop (<see cref="TubeMeshBuilder.ForceFullLimits"/>); false: the cheap tests and the frame passes, as Fast.</summary>
            public bool FullLimits = true;
            /// <summary>Fast fills with the vector paths on; false: off, as Full.</summary>
            public bool FastVectors = true;

            public Pair(RopeSimulation full, RopeSimulation fast)
            {
                Full = full;
                Fast = fast;
            }

            public void Step()
            {
                Full.Step(HostStep);
                Fast.Step(HostStep);
            }

            public void AssertSameMesh(string what)
            {
                Grow(Full, ref fullVertices, ref fullIndices);
                Grow(Fast, ref fastVertices, ref fastIndices);
                bool enabled = VectorPath.Enabled;
                TubeMeshUpdate full, fast;
                try
                {
                    VectorPath.Enabled = false;
                    TubeMeshBuilder builder = Full.Mesh.Builder;
                    builder.ForceFullLimits = FullLimits;
                    builder.AlwaysRebuild = true;
                    full = Full.FillMesh(fullVertices, fullIndices);
                    VectorPath.Enabled = FastVectors;
                    fast = Fast.FillMesh(fastVertices, fastIndices);
                }
                finally
                {
                    VectorPath.Enabled = enabled;
                }
                Assert.That(fast.VertexCount, Is.EqualTo(full.VertexCount), what + ": vertices");
                Assert.That(fast.IndexCount, Is.EqualTo(full.IndexCount), what + ": indices");
                Assert.That(MeshChecks.DifferingVertices(fullVertices, fastVertices, full.VertexCount), Is.EqualTo(0), what + ": vertices with other bits");
                int differing = 0;
                for (int i = 0; i < full.IndexCount; i++) if (fullIndices[i] != fastIndices[i]) differing++;
                Assert.That(differing, Is.EqualTo(0), what + ": other indices");
                Assert.That(Bits(fast.BoundsMin), Is.EqualTo(Bits(full.BoundsMin)), what + ": bounds min");
                Assert.That(Bits(fast.BoundsMax), Is.EqualTo(Bits(full.BoundsMax)), what + ": bounds max");
                MostRings = Math.Max(MostRings, Fast.Mesh.Builder.Layout.RingCount);
            }

            private static void Grow(RopeSimulation s, ref TubeVertex[] vertices, ref int[] indices)
            {
                if (vertices.Length < s.GetVertexCapacity()) vertices = new TubeVertex[s.GetVertexCapacity()];
                if (indices.Length < s.GetIndexCapacity()) indices = new int[s.GetIndexCapacity()];
            }

            private static string Bits(Float3 v) =>
                BitConverter.SingleToInt32Bits(v.X) + " " + BitConverter.SingleToInt32Bits(v.Y) + " " + BitConverter.SingleToInt32Bits(v.Z);
        }
    }
}
