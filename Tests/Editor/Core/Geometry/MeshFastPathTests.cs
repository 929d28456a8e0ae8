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

        /// <summary>The goal lanyard (64 segments) dropped from straight, then whipped by one pin: 150 frames.</summary>
        [TestCaseSource(nameof(Sides))]
        public void ADroppedAndWhippedLanyardDrawsTheSameBitsOnEveryPath(int sides)
        {
            var settings = new RopeSettings { SegmentCount = 64 };
            RopeSimulation Make()
            {
                RopeSimulation s = GoalLanyard.Pinned(settings, 0f, 1.8f);
                s.MeshSettings.RadialSegments = sides;
                return s;
            }
            var reference = new Pair(Make(), Make());
            for (int frame = 0; frame < 150; frame++)
            {
                if (frame >= 60)
                {
                    // whip the far pin up and down and toward the near one (0.4 m at 3 Hz)
                    float t = (frame - 60) * HostStep;
                    var target = new Float3(1.8f - 0.3f * MathF.Sin(6f * MathF.PI * t), 2f + 0.4f * MathF.Sin(6f * MathF.PI * t), 0f);
                    reference.Full.Rope.SetPinTarget(1, target);
                    reference.Fast.Rope.SetPinTarget(1, target);
                }
                reference.Step();
                reference.AssertSameMesh("lanyard, " + sides + " sides, frame " + frame);
            }
            Assert.That(reference.MostRings, Is.GreaterThan(2 * 64), "the whipped lanyard draws more than two rings per segment at some frame");
        }

        /// <summary>The lab's fracture cord (<see cref="FractureCord"/>: Zone neck, fracture, burr strands) pulled to its break and 25 frames on: necks, broken ends with burrs, dangling halves and fold tips.</summary>
        [TestCaseSource(nameof(Sides))]
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
                    builder.ForceFullLimits = true;
                    builder.AlwaysRebuild = true;
                    full = Full.FillMesh(fullVertices, fullIndices);
                    VectorPath.Enabled = true;
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
