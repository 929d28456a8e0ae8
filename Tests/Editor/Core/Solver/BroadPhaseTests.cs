using System;
using System.Collections.Generic;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// The collision broad phase (issue 18 item 3) against the brute-force pass it replaced (every particle against every
    /// collider): the same scene is stepped three times in lockstep — brute force, broad phase with the vector scan, broad
    /// phase with the scalar scan — and every position, velocity, tension and pin force must agree to the bit after every
    /// step. Then: a collider out of reach costs no narrow-phase work, a draped rope only that of the particles at the bar,
    /// and no step allocates.
    /// </summary>
    public sealed class BroadPhaseTests
    {
        private static IEnumerable<string> Scenes()
        {
            foreach (var scene in CollisionScenes.All()) yield return scene.Name;
        }

        [TestCaseSource(nameof(Scenes))]
        public void EveryCollisionSceneStepsToTheBitAsTheBruteForcePass(string name)
        {
            CollisionScenes.Scene scene = null;
            foreach (var candidate in CollisionScenes.All()) if (candidate.Name == name) scene = candidate;
            var lockstep = new Lockstep(scene.Build);
            for (int k = 0; k < scene.Steps; k++) lockstep.Step(rope => scene.BeforeStep(rope, k), k);
            TestContext.WriteLine($"{scene.Name}: {scene.Steps} steps identical; narrow-phase pairs brute {lockstep.BrutePairs}, broad {lockstep.BroadPairs}");
            Assert.That(lockstep.BroadPairs, Is.LessThanOrEqualTo(lockstep.BrutePairs));
        }

        private static IEnumerable<int> Seeds()
        {
            for (int seed = 1; seed <= 24; seed++) yield return seed;
        }

        /// <summary>
        /// Random ropes (segments, length, radius, substeps, iterations, solver, integrator, tension model, pins) among random
        /// colliders of every kind, near and far, that move a little, turn, jump far in one step (into the rope and out of
        /// reach), are removed, added and cleared.
        /// </summary>
        [TestCaseSource(nameof(Seeds))]
        public void RandomScenesStepToTheBitAsTheBruteForcePass(int seed)
        {
            // consecutive seeds give alike first draws: mix them
            var random = new Random((int)(((uint)seed * 2654435761u) ^ 0x5bd1e995u) & int.MaxValue);
            var settings = RopeTestKit.Legacy(
                length: Range(random, 0.5f, 4f), segments: random.Next(6, 97), radius: Range(random, 0.003f, 0.03f),
                substeps: new[] { 1, 2, 4, 8, 16 }[random.Next(5)], iterations: random.Next(1, 4),
                solver: random.Next(2) == 0 ? ConstraintSolverKind.ExactChain : ConstraintSolverKind.GaussSeidel);
            settings.Integrator = random.Next(2) == 0 ? TimeIntegrator.BackwardEuler : TimeIntegrator.Bdf2;
            settings.Tension = random.Next(3) == 0 ? TensionModel.Bilateral : TensionModel.TensionOnly;
            settings.Damping = random.Next(2) == 0 ? 0f : 0.01f;
            Float3 start = RandomPoint(random, 1f);
            Float3 end = start + RandomDirection(random) * (settings.RestLength * Range(random, 0.6f, 1.05f));
            int pins = random.Next(3);
            float compliance = random.Next(2) == 0 ? 0f : 1e-4f;
            int colliders = random.Next(1, 9);
            var shapes = new List<ColliderShape>();
            for (int c = 0; c < colliders; c++) shapes.Add(RandomCollider(random, start, settings.RestLength));
            var placed = new List<Float3>();
            foreach (var shape in shapes) placed.Add(shape.Position);
            var lockstep = new Lockstep(() =>
            {
                var rope = new Rope(settings, start, end);
                if (pins >= 1) rope.AddPin(0, start);
                if (pins >= 2) rope.AddPin(rope.ParticleCount - 1, end, compliance);
                foreach (var shape in shapes) rope.AddCollider(shape);
                return rope;
            });
            const int Steps = 80;
            for (int k = 0; k < Steps; k++)
            {
                // the same events for the three ropes, drawn once per step
                var events = Disturbance(random, placed, start, end, settings.RestLength, pins);
                lockstep.Step(rope => { foreach (var e in events) e(rope); }, k);
            }
            TestContext.WriteLine($"seed {seed}: {settings.SegmentCount} segments, {settings.Substeps}x{settings.Iterations} {settings.Solver} {settings.Integrator} {settings.Tension}, " +
                                  $"{colliders} colliders, {pins} pins: {Steps} steps identical; narrow-phase pairs brute {lockstep.BrutePairs}, broad {lockstep.BroadPairs}");
        }

        /// <summary>
        /// Random collider motion (small moves and turns, jumps in one step through the rope or far out of its reach), removals,
        /// additions, a clear, and pin motion, for one step; <paramref name="placed"/> follows the colliders' positions.
        /// </summary>
        private static List<Action<Rope>> Disturbance(Random random, List<Float3> placed, Float3 start, Float3 end, float length, int pins)
        {
            var events = new List<Action<Rope>>();
            for (int c = 0; c < placed.Count; c++)
            {
                double roll = random.NextDouble();
                if (roll >= 0.34) continue;
                Float3 to = roll < 0.3 ? placed[c] + RandomPoint(random, 0.05f * length)
                    : random.Next(2) == 0 ? Float3.Lerp(start, end, (float)random.NextDouble()) : start + RandomDirection(random) * 50f;
                Quat turn = RandomRotation(random);
                placed[c] = to;
                int index = c;
                events.Add(rope => rope.SetColliderPose(index, to, turn));
            }
            double what = random.NextDouble();
            if (what < 0.02 && placed.Count > 0)
            {
                int index = random.Next(placed.Count);
                placed.RemoveAt(index);
                events.Add(rope => rope.RemoveCollider(index));
            }
            else if (what < 0.045)
            {
                bool clear = what >= 0.04;
                var shape = RandomCollider(random, start, length);
                if (clear) placed.Clear();
                placed.Add(shape.Position);
                events.Add(rope =>
                {
                    if (clear) rope.ClearColliders();
                    rope.AddCollider(shape);
                });
            }
            for (int p = 0; p < pins; p++)
            {
                Float3 target = (p == 0 ? start : end) + RandomPoint(random, 0.1f * length);
                int pin = p;
                events.Add(rope => rope.SetPinTarget(pin, target));
            }
            return events;
        }

        [Test]
        public void CollidersThatJumpTurnAndSweepStepToTheBitAsTheBruteForcePass()
        {
            var lockstep = new Lockstep(() =>
            {
                var rope = new Rope(RopeTestKit.Legacy(length: 2f, segments: 64, radius: 0.01f), new Float3(-1f, 0f, 0f), new Float3(1f, 0f, 0f));
                rope.AddPin(0, new Float3(-1f, 0f, 0f));
                rope.AddPin(rope.ParticleCount - 1, new Float3(1f, 0f, 0f));
                rope.AddCollider(ColliderShape.Sphere(new Float3(0f, 0f, 50f), 0.2f, 0.4f));                              // jumps in and out
                rope.AddCollider(ColliderShape.Box(new Float3(0.5f, -0.4f, 0f), Quat.Identity, new Float3(0.1f, 0.3f, 0.05f), 0.6f)); // turns half a turn a step
                rope.AddCollider(ColliderShape.Plane(new Float3(0f, -0.6f, 0f), new Float3(0f, 1f, 0f), 0.3f));           // tilts
                rope.AddCollider(ColliderShape.Capsule(new Float3(-0.5f, 5f, 0f), Quat.Identity, 0.05f, 0.2f, 0.2f));     // sweeps down at 90 m/s
                return rope;
            });
            for (int k = 0; k < 120; k++)
            {
                lockstep.Step(rope =>
                {
                    rope.SetColliderPose(0, k % 10 == 3 ? new Float3(0.2f, -0.1f, 0f) : new Float3(0f, 0f, 50f), Quat.Identity);
                    rope.SetColliderPose(1, new Float3(0.5f, -0.4f, 0f), Quat.FromAxisAngle(new Float3(0f, 0f, 1f), MathF.PI * 0.5f * (k + 1)));
                    rope.SetColliderPose(2, new Float3(0f, -0.6f + 0.5f * MathF.Sin(0.1f * k), 0f), Quat.FromAxisAngle(new Float3(1f, 0f, 1f), 0.4f * MathF.Sin(0.13f * k)));
                    rope.SetColliderPose(3, new Float3(-0.5f, k % 20 < 10 ? 5f - (k % 20) : -5f, 0f), Quat.FromAxisAngle(new Float3(1f, 0f, 0f), MathF.PI / 2f));
                    rope.SetPinTarget(1, new Float3(1f, 0.3f * MathF.Sin(0.05f * k), 0f));
                }, k);
            }
            TestContext.WriteLine($"120 steps identical; narrow-phase pairs brute {lockstep.BrutePairs}, broad {lockstep.BroadPairs}");
        }

        [Test]
        public void RadiiTheRadiusModelChangesEachStepReachTheBroadPhase()
        {
            // a cord stretched over a bar thins (Poisson), so its collision radii change every step
            var lockstep = new Lockstep(() =>
            {
                var settings = RopeTestKit.Legacy(length: 1.2f, segments: 80, radius: 0.01f, substeps: 8, iterations: 2);
                settings.AxialStiffness = 200f;
                settings.Gravity = Float3.Zero;
                var simulation = new RopeSimulation(settings, new Float3(-0.5f, 0.2f, 0f), new Float3(0.5f, 0.2f, 0f), new HookeRope.Radius.RadiusSettings());
                var rope = simulation.Rope;
                rope.AddPin(0, new Float3(-0.5f, 0.2f, 0f));
                rope.AddPin(rope.ParticleCount - 1, new Float3(0.5f, 0.2f, 0f));
                rope.AddCollider(ColliderShape.Capsule(Float3.Zero, Quat.FromAxisAngle(new Float3(1f, 0f, 0f), MathF.PI / 2f), 0.1f, 0.5f));
                return simulation;
            });
            float first = float.NaN, last = float.NaN;
            for (int k = 0; k < 120; k++)
            {
                lockstep.Step(rope => CollisionScenes.PullDown(rope, k), k);
                if (k == 0) first = lockstep.Reference.ParticleRadius[40];
                last = lockstep.Reference.ParticleRadius[40];
            }
            TestContext.WriteLine($"radius at the bar {first:E4} → {last:E4} m; 120 steps identical");
            Assert.That(last, Is.LessThan(first), "the radius model thinned the cord");
        }

        [Test]
        public void CollidersOutOfReachCostNoNarrowPhaseWork()
        {
            // 10 m hanging from the origin, swinging; colliders at 10–90 m
            var rope = new Rope(RopeTestKit.Legacy(length: 10f, segments: 256), Float3.Zero, new Float3(3.4f, -9.4f, 0f));
            rope.AddPin(0, Float3.Zero);
            rope.AddCollider(ColliderShape.Plane(new Float3(0f, -100f, 0f), new Float3(0f, 1f, 0f)));
            rope.AddCollider(ColliderShape.Sphere(new Float3(0f, -5f, 10f), 1f));
            rope.AddCollider(ColliderShape.Box(new Float3(-8f, -2f, 0f), Quat.FromAxisAngle(new Float3(0f, 1f, 0f), 0.5f), new Float3(1f, 0.5f, 2f)));
            rope.AddCollider(ColliderShape.Capsule(new Float3(12f, -5f, 0f), Quat.Identity, 0.3f, 2f));
            for (int k = 0; k < 90; k++) rope.Step(RopeTestKit.HostStep);
            Assert.That(rope.Collisions.PairsResolved, Is.EqualTo(0), "no particle–collider pair reached the narrow phase");
            rope.Collisions.BruteForce = true;
            rope.Step(RopeTestKit.HostStep);
            // the brute-force pass: 257 particles less the pinned one × 4 colliders × 8 substeps × 2 passes
            Assert.That(rope.Collisions.PairsResolved, Is.EqualTo(256 * 4 * 8 * 2));
        }

        [Test]
        public void ADrapedRopeCostsNarrowPhaseWorkOnlyForTheParticlesAtTheBar()
        {
            // 10 m laid across a bar (capsule r 5 cm along Z); after 3 s both halves hang and a few particles touch the bar
            var rope = new Rope(RopeTestKit.Legacy(length: 10f, segments: 256), new Float3(-5f, 0.06f, 0f), new Float3(5f, 0.06f, 0f));
            rope.AddCollider(ColliderShape.Capsule(Float3.Zero, Quat.FromAxisAngle(new Float3(1f, 0f, 0f), MathF.PI / 2f), 0.05f, 0.5f, 0.5f));
            for (int k = 0; k < 270; k++) rope.Step(RopeTestKit.HostStep);
            int touching = 0;
            for (int i = 0; i < rope.ParticleCount; i++)
                if (rope.ColliderDistance(0, rope.GetPosition(i)) <= rope.ParticleRadius[i] * (1f + CollisionSet.ContactMarginFraction)) touching++;
            long before = rope.Collisions.PairsResolved;
            const int Steps = 30;
            for (int k = 0; k < Steps; k++) rope.Step(RopeTestKit.HostStep);
            double perPass = (rope.Collisions.PairsResolved - before) / (Steps * 8.0 * 2.0);
            TestContext.WriteLine($"{touching} particles within reach of the bar; {perPass:F1} particles tested per pass (brute force: {rope.ParticleCount})");
            Assert.That(touching, Is.GreaterThan(0).And.LessThan(ParticleBlocks.BlockSize), "a few particles rest on the bar");
            // the particles the bar's box reaches: those on it and a few beside it (the box is square, the bar round)
            Assert.That(perPass, Is.GreaterThanOrEqualTo(touching).And.LessThanOrEqualTo(2 * touching + 2));
        }

        [TestCase(true)]
        [TestCase(false)]
        public void BroadPhaseStepsAllocateNothing(bool vectors)
        {
            var rope = new Rope(RopeTestKit.Legacy(length: 2f, segments: 100), new Float3(-1f, 0.3f, 0f), new Float3(1f, 0.3f, 0f));
            rope.Collisions.Blocks.UseVectors = vectors;
            rope.AddCollider(ColliderShape.Plane(Float3.Zero, new Float3(0f, 1f, 0f), 0.5f));
            rope.AddCollider(ColliderShape.Sphere(new Float3(0f, 0.1f, 0f), 0.1f, 0.3f));
            for (int c = 0; c < 8; c++) rope.AddCollider(ColliderShape.Box(new Float3(20f + c, 5f, 0f), Quat.Identity, new Float3(0.5f, 0.5f, 0.5f)));
            void Run(int steps)
            {
                for (int k = 0; k < steps; k++)
                {
                    rope.SetColliderPose(1, new Float3(0.5f * MathF.Sin(0.1f * k), 0.1f, 0f), Quat.FromAxisAngle(new Float3(0f, 1f, 0f), 0.1f * k));
                    rope.Step(RopeTestKit.HostStep);
                }
            }
            Run(20);
            long stepping = long.MaxValue;
            for (int window = 0; window < 3; window++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                Run(15);
                stepping = Math.Min(stepping, GC.GetAllocatedBytesForCurrentThread() - before);
            }
            Assert.That(stepping, Is.EqualTo(0));
        }

        private static float Range(Random random, float low, float high) => low + (float)random.NextDouble() * (high - low);

        private static Float3 RandomDirection(Random random) => RandomPoint(random, 1f).NormalizedOr(new Float3(0f, -1f, 0f));

        private static Float3 RandomPoint(Random random, float scale) =>
            new Float3(Range(random, -scale, scale), Range(random, -scale, scale), Range(random, -scale, scale));

        private static Quat RandomRotation(Random random) =>
            Quat.FromAxisAngle(RandomDirection(random), Range(random, -MathF.PI, MathF.PI));

        /// <summary>A collider of a random kind, size, friction and pose: near the rope (within its length of the start) or 10–100 m away.</summary>
        private static ColliderShape RandomCollider(Random random, Float3 start, float length)
        {
            Float3 at = random.Next(3) == 0 ? start + RandomDirection(random) * Range(random, 10f, 100f) : start + RandomPoint(random, length);
            float friction = random.Next(2) == 0 ? 0f : Range(random, 0f, 1f);
            float size = Range(random, 0.05f, 0.6f) * length;
            switch (random.Next(4))
            {
                case 0: return ColliderShape.Plane(at - new Float3(0f, length, 0f), RandomDirection(random) + new Float3(0f, 1.5f, 0f), friction);
                case 1: return ColliderShape.Sphere(at, size, friction);
                case 2: return ColliderShape.Capsule(at, RandomRotation(random), 0.3f * size, size, friction);
                default: return ColliderShape.Box(at, RandomRotation(random), new Float3(size, 0.5f * size, Range(random, 0.2f, 1f) * size), friction);
            }
        }

        /// <summary>
        /// One scene three times — brute-force pass (the reference), broad phase with the vector scan, broad phase with the
        /// scalar scan — stepped together and compared bit for bit after every step.
        /// </summary>
        private sealed class Lockstep
        {
            private readonly Rope[] ropes = new Rope[3];
            private readonly RopeSimulation[] simulations;

            public Lockstep(Func<Rope> build)
            {
                for (int r = 0; r < 3; r++) ropes[r] = build();
                Configure();
            }

            public Lockstep(Func<RopeSimulation> build)
            {
                simulations = new RopeSimulation[3];
                for (int r = 0; r < 3; r++)
                {
                    simulations[r] = build();
                    ropes[r] = simulations[r].Rope;
                }
                Configure();
            }

            private void Configure()
            {
                ropes[0].Collisions.BruteForce = true;
                ropes[1].Collisions.Blocks.UseVectors = true;
                ropes[2].Collisions.Blocks.UseVectors = false;
            }

            public Rope Reference => ropes[0];

            public long BrutePairs => ropes[0].Collisions.PairsResolved;

            public long BroadPairs => ropes[2].Collisions.PairsResolved;

            public void Step(Action<Rope> before, int step)
            {
                for (int r = 0; r < 3; r++)
                {
                    before(ropes[r]);
                    if (simulations != null) simulations[r].Step(RopeTestKit.HostStep);
                    else ropes[r].Step(RopeTestKit.HostStep);
                }
                for (int r = 1; r < 3; r++) AssertSame(ropes[0], ropes[r], step, r == 1 ? "vector scan" : "scalar scan");
            }

            private static void AssertSame(Rope expected, Rope actual, int step, string path)
            {
                Assert.That(actual.ColliderCount, Is.EqualTo(expected.ColliderCount));
                for (int i = 0; i < expected.ParticleCount; i++)
                {
                    if (Same(expected.PositionX[i], actual.PositionX[i]) && Same(expected.PositionY[i], actual.PositionY[i]) && Same(expected.PositionZ[i], actual.PositionZ[i])
                        && Same(expected.GetVelocity(i), actual.GetVelocity(i)))
                        continue;
                    Assert.Fail($"{path}, step {step}, particle {i}: position {actual.GetPosition(i)} velocity {actual.GetVelocity(i)}, brute force {expected.GetPosition(i)} {expected.GetVelocity(i)}");
                }
                for (int j = 0; j < expected.SegmentCount; j++)
                    if (!Same(expected.Tensions[j], actual.Tensions[j]))
                        Assert.Fail($"{path}, step {step}, segment {j}: tension {actual.Tensions[j]:R} N, brute force {expected.Tensions[j]:R} N");
                for (int p = 0; p < expected.PinCount; p++)
                    if (!Same(expected.GetPinForce(p), actual.GetPinForce(p)))
                        Assert.Fail($"{path}, step {step}, pin {p}: force {actual.GetPinForce(p)}, brute force {expected.GetPinForce(p)}");
            }

            private static bool Same(float a, float b) => BitConverter.SingleToInt32Bits(a) == BitConverter.SingleToInt32Bits(b);

            private static bool Same(Float3 a, Float3 b) => Same(a.X, b.X) && Same(a.Y, b.Y) && Same(a.Z, b.Z);
        }
    }
}
