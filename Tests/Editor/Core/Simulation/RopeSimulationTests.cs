using System;
using HookeRope.Geometry;
using HookeRope.Mathematics;
using HookeRope.Radius;
using HookeRope.Solver;
using HookeRope.Tests.Core.Geometry;
using NUnit.Framework;

namespace HookeRope.Tests.Core.Simulation
{
    public sealed class RopeSimulationTests
    {
        private const float Step = 1f / 90f;
        private const float R = 0.01f;

        private static RopeSettings Soft(float length, int segments, float axialStiffness, float ropeMass)
        {
            var s = new RopeSettings { RestLength = length, SegmentCount = segments, Radius = R };
            s.AxialStiffness = axialStiffness;
            s.LinearDensity = ropeMass / length;
            s.Damping = 0.05f;
            return s;
        }

        [Test]
        public void HangingHeavyRopeIsThinnerAtTheTop()
        {
            // 2 m, 2 kg rope of E·A = 200 N hanging from its top: static strain falls from ≈ 0.096 at the top to 0.
            var settings = Soft(2f, 20, 200f, 2f);
            var radius = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, Necking = false, Fracture = false };
            var sim = new RopeSimulation(settings, Float3.Zero, new Float3(0f, -2f, 0f), radius);
            sim.Rope.AddPin(0, Float3.Zero);
            for (int i = 0; i < 270; i++) sim.Step(Step);
            ReadOnlySpan<float> particle = sim.ParticleRadii;
            for (int i = 1; i < sim.Rope.ParticleCount; i++)
                Assert.That(particle[i], Is.GreaterThan(particle[i - 1]), "particle " + i);
            // Each segment's radius is eq. 16 of its own stretch (ν = 0.5: r = R·sqrt(L/l)).
            for (int j = 0; j < sim.Rope.SegmentCount; j++)
            {
                double expected = R * Math.Sqrt(sim.Rope.RestLengths[j] / sim.Rope.SegmentLengths[j]);
                Assert.That(sim.RadiusModel.SegmentRadii[j], Is.EqualTo(expected).Within(1e-6 * R));
            }
            // Top segment: static strain (m g (1 − 0.5/20))/(E·A) = 0.0956 → r = R/sqrt(1.0956) = 0.9554 R.
            double topStrain = 2.0 * 9.81 * (1.0 - 0.5 / 20.0) / 200.0;
            TestContext.WriteLine("top radius " + (sim.RadiusModel.SegmentRadii[0] / R).ToString("F4") + " R, static theory " + (1.0 / Math.Sqrt(1.0 + topStrain)).ToString("F4") + " R");
            Assert.That(sim.RadiusModel.SegmentRadii[0] / R, Is.EqualTo(1.0 / Math.Sqrt(1.0 + topStrain)).Within(0.002));
            Assert.That(sim.RadiusModel.SegmentRadii[19] / R, Is.GreaterThan(0.995));
            // The collision radius is the radius model's particle radius.
            for (int i = 0; i < sim.Rope.ParticleCount; i++)
                Assert.That(sim.Rope.ParticleRadius[i], Is.EqualTo(particle[i]));
        }

        [Test]
        public void RopeStretchedPastTheThresholdBreaksAtTheDefect()
        {
            var settings = Soft(1f, 20, 500f, 0.05f);
            settings.Gravity = Float3.Zero;
            var radius = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, NeckMode = NeckMode.Zone, DefectPosition = 0.33f, BreakStrain = 0.5f, BreakRadiusFraction = 0f };
            var sim = new RopeSimulation(settings, Float3.Zero, new Float3(1f, 0f, 0f), radius, new TubeMeshSettings { RadialSegments = 16 });
            sim.Rope.AddPin(0, Float3.Zero);
            int end = sim.Rope.AddPin(20, new Float3(1f, 0f, 0f));
            int brokenSegment = -1;
            sim.Rope.Broken += e => brokenSegment = e.Segment;
            float stretchAtBreak = float.NaN;
            for (int i = 1; i <= 200 && !sim.IsBroken; i++)
            {
                float stretch = 1f + 0.005f * i;
                sim.Rope.SetPinTarget(end, new Float3(stretch, 0f, 0f));
                sim.Step(Step);
                if (sim.IsBroken) stretchAtBreak = stretch;
            }
            Assert.That(sim.IsBroken, Is.True);
            Assert.That(brokenSegment, Is.EqualTo(6));
            Assert.That(sim.Rope.IsSegmentBroken(6), Is.True);
            for (int j = 0; j < 20; j++) if (j != 6) Assert.That(sim.Rope.IsSegmentBroken(j), Is.False, "segment " + j);
            Assert.That(stretchAtBreak, Is.EqualTo(1.5f).Within(0.02f));
            Assert.That(sim.RadiusModel.IsBroken, Is.True);
            Assert.That(sim.Readouts.FirstBreak.HasValue, Is.True);
            Assert.That(sim.Readouts.FirstBreak.Value.Segment, Is.EqualTo(6));
            Assert.That(sim.Rope.BrokenSegmentCount, Is.EqualTo(1));
            // The mesh now has two pieces with burrs at the break.
            var vertices = new TubeVertex[sim.GetVertexCount()];
            var indices = new int[sim.GetIndexCount()];
            var update = sim.FillMesh(vertices, indices);
            // Fibres per end: 40 per cm² of the rest cross-section, at least the 16 radial segments, at most 256.
            double byArea = Math.Round(40.0 * Math.PI * Math.Pow(sim.RestRadius * 100.0, 2.0));
            int fibres = (int)Math.Min(256.0, Math.Max(16.0, byArea));
            Assert.That(update.BurrIndexCount, Is.EqualTo(2 * fibres * 9));
            Assert.That(MeshChecks.AllFiniteAndUnit(vertices, update.VertexCount), Is.True);
        }

        [Test]
        public void ZoneNeckIsResolvedByTheRefinedRingLayout()
        {
            const float radius = 0.006f;
            var settings = new RopeSettings { RestLength = 2f, SegmentCount = 20, Radius = radius };
            settings.AxialStiffness = 1000f;
            settings.Gravity = Float3.Zero;
            var radiusSettings = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, DefectPosition = 0.33f, Fracture = false };
            var sim = new RopeSimulation(settings, Float3.Zero, new Float3(3.6f, 0f, 0f), radiusSettings);
            sim.Rope.AddPin(0, Float3.Zero);
            sim.Rope.AddPin(20, new Float3(3.6f, 0f, 0f));
            for (int i = 0; i < 5; i++) sim.Step(Step);
            Assert.That(sim.RadiusModel.NeckDepth, Is.EqualTo(1f)); // 1.8× stretch: past onset + growth strain
            sim.FillMesh(new TubeVertex[sim.GetVertexCount()], new int[sim.GetIndexCount()]);
            float smallestRing = float.MaxValue;
            foreach (float r in sim.Mesh.RingRadii) smallestRing = Math.Min(smallestRing, r);
            // Rings adapted to the profile's curvature: the deepest ring sits on the waist (the middle of segment 6)...
            Assert.That(smallestRing, Is.EqualTo(sim.NeckRadius).Within(1e-4f * radius));
            // the adaptive layout draws the neck's stations while it necks (one ring per segment elsewhere on this straight rope)
            var layout = sim.Mesh.Layout;
            double zoneStart = sim.RadiusModel.DefectRestArc - 0.5 * sim.RadiusModel.NeckZoneRestLength;
            double zoneEnd = sim.RadiusModel.DefectRestArc + 0.5 * sim.RadiusModel.NeckZoneRestLength;
            int inZone = 0;
            for (int k = 0; k < layout.RingCount; k++)
            {
                double s = ArcAt(sim.Rope.RestLengths, layout.RingSegments[k], layout.RingFractions[k]);
                if (s > zoneStart && s < zoneEnd) inZone++;
            }
            Assert.That(inZone, Is.GreaterThanOrEqualTo(RingLayout.BaseRingsInZone));
            TestContext.WriteLine("rings: " + layout.RingCount + ", " + inZone + " of them in the neck zone");
            Assert.That(layout.RingCount, Is.LessThan(20 * 4 + 1), "fewer rings than 4 per segment: the straight rope outside the neck needs about one per segment");
            // ...and the drawn profile turns in small steps, where 4 uniform rings per 10 cm segment draw a spike.
            double adaptedTurn = LargestProfileTurn(sim, sim.Mesh.Layout.RingSegments, sim.Mesh.Layout.RingFractions);
            var uniform = new RingLayout(20, 4);
            double uniformTurn = LargestProfileTurn(sim, uniform.RingSegments, uniform.RingFractions);
            TestContext.WriteLine("largest turn of the drawn profile between rings: adapted " + adaptedTurn + " rad, uniform " + uniformTurn + " rad");
            Assert.That(adaptedTurn, Is.LessThan(0.65 * uniformTurn));
            Assert.That(adaptedTurn, Is.LessThan(Math.PI / sim.MeshSettings.RadialSegments), "as round along the waist as around it");
        }

        /// <summary>Largest change of the profile's slope angle atan(dr/ds) (rad) between ring intervals, s = rest arc length.</summary>
        private static double LargestProfileTurn(RopeSimulation sim, ReadOnlySpan<int> segments, ReadOnlySpan<float> fractions)
        {
            var rest = sim.Rope.RestLengths;
            double largest = 0.0, previousAngle = 0.0;
            for (int k = 1; k < segments.Length; k++)
            {
                double s0 = ArcAt(rest, segments[k - 1], fractions[k - 1]), s1 = ArcAt(rest, segments[k], fractions[k]);
                double r0 = sim.RadiusModel.RadiusAt(segments[k - 1], fractions[k - 1]), r1 = sim.RadiusModel.RadiusAt(segments[k], fractions[k]);
                double angle = Math.Atan((r1 - r0) / (s1 - s0));
                if (k > 1) largest = Math.Max(largest, Math.Abs(angle - previousAngle));
                previousAngle = angle;
            }
            return largest;
        }

        private static double ArcAt(ReadOnlySpan<float> rest, int segment, float fraction)
        {
            double s = 0.0;
            for (int j = 0; j < segment; j++) s += rest[j];
            return s + rest[segment] * fraction;
        }

        /// <summary>
        /// Issue 17: after the break's first frame (the topology change), stepping and filling a frayed, broken rope that
        /// lies over a sphere (ring centres pushed out of the collider) allocates nothing, and the drawn tube stays outside
        /// the sphere.
        /// </summary>
        [Test]
        public void BrokenRopeOverASphereFillsWithoutAllocating()
        {
            var settings = Soft(1f, 20, 300f, 0.2f);
            // Pinned 5 cm above the centre of a 10 cm sphere: the rope is pulled over its top.
            var sim = new RopeSimulation(settings, new Float3(-0.5f, 0.15f, 0f), new Float3(0.5f, 0.15f, 0f), new RadiusSettings { PoissonRatio = 0.5f, Fracture = false });
            sim.Rope.AddPin(0, new Float3(-0.5f, 0.05f, 0f));
            sim.Rope.AddPin(20, new Float3(0.5f, 0.05f, 0f));
            sim.Rope.AddCollider(ColliderShape.Sphere(Float3.Zero, 0.1f));
            for (int i = 0; i < 90; i++) sim.Step(Step);
            sim.Rope.BreakSegment(17);
            var vertices = new TubeVertex[sim.GetVertexCount()];
            var indices = new int[sim.GetIndexCount()];
            var first = sim.FillMesh(vertices, indices);
            Assert.That(first.TopologyChanged, Is.True);
            Assert.That(first.BurrIndexCount, Is.EqualTo(2 * 126 * 9), "R = 10 mm: 40 fibres per cm² of πR²");
            double deepest = double.MaxValue;
            for (int k = 0; k < first.TubeIndexCount; k++)
            {
                TubeVertex v = vertices[indices[k]];
                double x = v.PX + sim.Rope.Origin.X, y = v.PY + sim.Rope.Origin.Y, z = v.PZ + sim.Rope.Origin.Z;
                deepest = Math.Min(deepest, Math.Sqrt(x * x + y * y + z * z) - 0.1);
            }
            TestContext.WriteLine("drawn tube to sphere: " + deepest / R + " R");
            Assert.That(deepest, Is.GreaterThan(-0.02 * R), "the drawn tube stays outside the sphere it lies on");
            Assert.That(deepest, Is.LessThan(0.05 * R), "it does lie on the sphere");
            long bytes = SteadyStateAllocation.Bytes(() =>
            {
                sim.Step(Step);
                sim.FillMesh(vertices, indices);
            }, 30);
            Assert.That(bytes, Is.EqualTo(0));
        }

        [Test]
        public void ThinnedRopeLiesLowerOnTheGround()
        {
            // A rope stretched 1.5× between two pins at the height of its thinned radius, r = R/sqrt(1.5) = 0.8165 R
            // for ν = 0.5, sags onto a plane at y = 0: its particles rest at their own (thinned) radius, not at R.
            float r = R / MathF.Sqrt(1.5f);
            var settings = new RopeSettings { RestLength = 1f, SegmentCount = 20, Radius = R };
            settings.YoungsModulus = 1e7f;
            var radius = new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, Necking = false, Fracture = false };
            var sim = new RopeSimulation(settings, new Float3(0f, r, 0f), new Float3(1.5f, r, 0f), radius);
            Assert.That(sim.Rope.ParticleRadius[10], Is.EqualTo(r).Within(1e-4 * R), "radii applied before the first step");
            sim.Rope.AddPin(0, new Float3(0f, r, 0f));
            sim.Rope.AddPin(20, new Float3(1.5f, r, 0f));
            sim.Rope.AddCollider(ColliderShape.Plane(Float3.Zero, new Float3(0f, 1f, 0f), 0.5f));
            double lowest = double.MaxValue, highest = double.MinValue;
            for (int i = 0; i < 90; i++)
            {
                sim.Step(Step);
                if (i < 45) continue;
                for (int p = 5; p <= 15; p++)
                {
                    lowest = Math.Min(lowest, sim.Rope.GetPosition(p).Y);
                    highest = Math.Max(highest, sim.Rope.GetPosition(p).Y);
                }
            }
            TestContext.WriteLine("middle particles between y = " + (lowest / R).ToString("F4") + " R and " + (highest / R).ToString("F4") + " R; thinned radius " + (r / R).ToString("F4") + " R");
            Assert.That(sim.Rope.ParticleRadius[10], Is.EqualTo(r).Within(1e-3 * R));
            Assert.That(lowest, Is.EqualTo(r).Within(0.01 * R));
            Assert.That(highest, Is.EqualTo(r).Within(0.01 * R)); // R = 1.0 would be 18 % higher
        }

        [Test]
        public void WithoutARadiusModelTheRopeKeepsItsRadiusAndTheMeshStillBuilds()
        {
            var settings = Soft(1f, 10, 100f, 0.1f);
            var sim = new RopeSimulation(settings, Float3.Zero, new Float3(1.5f, 0f, 0f));
            sim.Rope.AddPin(0, Float3.Zero);
            sim.Rope.AddPin(10, new Float3(1.5f, 0f, 0f));
            for (int i = 0; i < 10; i++) sim.Step(Step);
            Assert.That(sim.RadiusModel, Is.Null);
            Assert.That(sim.MinRadius, Is.EqualTo(R));
            Assert.That(sim.NeckRadius, Is.EqualTo(R));
            for (int i = 0; i < 11; i++) Assert.That(sim.Rope.ParticleRadius[i], Is.EqualTo(R));
            var vertices = new TubeVertex[sim.GetVertexCount()];
            var indices = new int[sim.GetIndexCount()];
            var update = sim.FillMesh(vertices, indices);
            Assert.That(update.BoundsMin.X, Is.EqualTo(0f).Within(R), "rope-local: the first particle sits at the local origin");
            for (int k = 0; k < sim.Mesh.RingRadii.Length; k++) Assert.That(sim.Mesh.RingRadii[k], Is.EqualTo(R));
        }

        [Test]
        public void StepAndMeshFillAllocateNothing()
        {
            var settings = Soft(2f, 40, 300f, 0.5f);
            var sim = new RopeSimulation(settings, Float3.Zero, new Float3(0f, -2f, 0f), new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, Fracture = false });
            sim.Rope.AddPin(0, Float3.Zero);
            sim.Rope.AddLoad(40, 3f);
            var vertices = new TubeVertex[sim.GetVertexCount()];
            var indices = new int[sim.GetIndexCount()];
            var x = new float[41];
            var y = new float[41];
            var z = new float[41];
            long bytes = SteadyStateAllocation.Bytes(() =>
            {
                sim.Step(Step);
                sim.FillMesh(vertices, indices);
                sim.Rope.Interpolate(0.5f, x, y, z);
                sim.FillMesh(x, y, z, vertices, indices, 0.5f);
                sim.GetVertexCount();
                sim.GetIndexCount();
            }, 20);
            Assert.That(bytes, Is.EqualTo(0));
        }

        [Test]
        public void FillMeshInTheCallersFrameEqualsTheRopeLocalMeshShifted()
        {
            var settings = Soft(1f, 12, 300f, 0.2f);
            var sim = new RopeSimulation(settings, new Float3(1f, 2f, 3f), new Float3(2f, 1.5f, 3f), new RadiusSettings { PoissonRatio = 0.5f, NeckRadiusFraction = 0.8f, BreakStrain = 1000f });
            sim.Rope.AddPin(0, new Float3(1f, 2f, 3f));
            for (int i = 0; i < 20; i++) sim.Step(Step);
            sim.Rope.BreakSegment(5);
            var local = new TubeVertex[sim.GetVertexCount()];
            var shifted = new TubeVertex[local.Length];
            var li = new int[sim.GetIndexCount()];
            var si = new int[li.Length];
            var a = sim.FillMesh(local, li);
            var offset = new Float3(-10f, 4f, 0.5f);
            int n = sim.Rope.ParticleCount;
            float[] x = new float[n], y = new float[n], z = new float[n];
            for (int i = 0; i < n; i++)
            {
                x[i] = sim.Rope.PositionX[i] + offset.X;
                y[i] = sim.Rope.PositionY[i] + offset.Y;
                z[i] = sim.Rope.PositionZ[i] + offset.Z;
            }
            var b = sim.FillMesh(x, y, z, shifted, si);
            Assert.That(b.VertexCount, Is.EqualTo(a.VertexCount));
            Assert.That(b.BurrIndexCount, Is.GreaterThan(0), "the broken flags come from the rope");
            for (int v = 0; v < a.VertexCount; v++)
            {
                Assert.That(shifted[v].PX, Is.EqualTo(local[v].PX + offset.X).Within(1e-5));
                Assert.That(shifted[v].PY, Is.EqualTo(local[v].PY + offset.Y).Within(1e-5));
                Assert.That(shifted[v].PZ, Is.EqualTo(local[v].PZ + offset.Z).Within(1e-5));
                Assert.That(shifted[v].NX, Is.EqualTo(local[v].NX).Within(1e-4));
            }
            for (int k = 0; k < li.Length; k++) Assert.That(si[k], Is.EqualTo(li[k]));
            Assert.That(b.BoundsMin.X, Is.EqualTo(a.BoundsMin.X + offset.X).Within(1e-5));

            // radiusScale scales the ring radii: the rings shrink around the same centres.
            var half = new TubeVertex[local.Length];
            sim.FillMesh(sim.Rope.PositionX, sim.Rope.PositionY, sim.Rope.PositionZ, half, si, 0.5f);
            float full = DistanceFromAxis(local, 1, local[0]);
            Assert.That(DistanceFromAxis(half, 1, half[0]), Is.EqualTo(0.5f * full).Within(1e-3f * full));
        }

        [Test]
        public void FillMeshFarFromTheOriginEqualsTheRopeAtTheOrigin()
        {
            // The rope-local overload keeps full precision far out: the lab adds Rope.Origin once, in double if it likes.
            var near = new RopeSimulation(Soft(1f, 8, 300f, 0.2f), Float3.Zero, new Float3(1f, 0f, 0f), meshSettings: new TubeMeshSettings { RadialSegments = 16 });
            var far = new RopeSimulation(Soft(1f, 8, 300f, 0.2f), new Float3(8192f, -4096f, 16384f), new Float3(8193f, -4096f, 16384f), meshSettings: new TubeMeshSettings { RadialSegments = 16 });
            var a = new TubeVertex[near.GetVertexCount()];
            var b = new TubeVertex[far.GetVertexCount()];
            var ia = new int[near.GetIndexCount()];
            var ib = new int[far.GetIndexCount()];
            var ua = near.FillMesh(a, ia);
            var ub = far.FillMesh(b, ib);
            Assert.That(far.Rope.Origin.X, Is.EqualTo(8192f), "world = Rope.Origin + v");
            Assert.That(ub.VertexCount, Is.EqualTo(ua.VertexCount));
            for (int v = 0; v < ua.VertexCount; v++)
            {
                Assert.That(b[v].PX, Is.EqualTo(a[v].PX).Within(1e-7));
                Assert.That(b[v].PY, Is.EqualTo(a[v].PY).Within(1e-7));
                Assert.That(b[v].PZ, Is.EqualTo(a[v].PZ).Within(1e-7));
            }
        }

        private static float DistanceFromAxis(TubeVertex[] vertices, int index, TubeVertex centre)
        {
            float dx = vertices[index].PX - centre.PX, dy = vertices[index].PY - centre.PY, dz = vertices[index].PZ - centre.PZ;
            return MathF.Sqrt(dx * dx + dy * dy + dz * dz);
        }
    }
}
