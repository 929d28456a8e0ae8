using System;
using HookeRope.Mathematics;
using HookeRope.Solver;
using NUnit.Framework;

namespace HookeRope.Tests.Solver
{
    /// <summary>
    /// Issue 18: the <see cref="System.Numerics.Vector{T}"/> paths of the substep's per-particle and per-segment passes
    /// (Rope.Lanes: BDF2 prediction, second-order velocities, position commit, violence test, tensions) give the scalar
    /// loops' bits. Each scene is stepped twice from the same start, with <see cref="VectorPath.Enabled"/> off and on, and
    /// every position, remainder, displacement, double velocity, history, multiplier and tension must match bit for bit
    /// (Rope.StateBits), after every host step, and so must each step's report (the residual, whose largest error the lane
    /// pass forms, and the solve's counts). The scenes cover BDF2 and backward Euler, the exact chain and the
    /// Gauss–Seidel sweep, rigid, moving and compliant pins, a pin in the middle of a block, drag and wind, a collider,
    /// plastic segments, a broken segment, several iterations, and chains shorter than one block or with a tail.
    /// </summary>
    public sealed class VectorPathBitsTests
    {
        const float HostStep = 1f / 90f;
        const int HostSteps = 90;

        bool saved;

        [SetUp]
        public void Remember() => saved = VectorPath.Enabled;

        [TearDown]
        public void Restore() => VectorPath.Enabled = saved;

        static readonly string[] Scenes =
        {
            "goal-lanyard", "bdf2-load-3-iterations", "backward-euler-swing", "bdf2-drag-wind", "bdf2-plane", "plastic-neck",
            "bilateral-softpin", "broken-middle", "moving-pins", "short-5", "tail-13-mid-pin", "gauss-seidel-bdf2",
        };

        /// <summary>A scene by name (see <see cref="Scenes"/>); <paramref name="drive"/> moves its pins before each host step k (or null).</summary>
        static Rope Build(string name, out Action<Rope, int> drive)
        {
            drive = null;
            switch (name)
            {
                case "goal-lanyard":
                {
                    // issue 18's lanyard: 64 segments, defaults (exact chain, BDF2, 8 substeps × 1 iteration), pinned 1.8 m apart
                    var rope = new Rope(new RopeSettings { SegmentCount = 64 }, new Float3(0f, 2f, 0f), new Float3(1.8f, 2f, 0f));
                    rope.AddPin(0, new Float3(0f, 2f, 0f));
                    rope.AddPin(64, new Float3(1.8f, 2f, 0f));
                    return rope;
                }
                case "bdf2-load-3-iterations":
                {
                    var rope = Pinned(RopeTestKit.Legacy(length: 3.2f, segments: 32, iterations: 3), TimeIntegrator.Bdf2, new Float3(0.8f, -3.1f, 0f));
                    rope.AddLoad(32, 80f);
                    return rope;
                }
                case "backward-euler-swing":
                {
                    return Pinned(RopeTestKit.Legacy(length: 2.4f, segments: 24), TimeIntegrator.BackwardEuler, new Float3(2.4f, 0f, 0f));
                }
                case "bdf2-drag-wind":
                {
                    var settings = RopeTestKit.Legacy(length: 3.2f, segments: 32);
                    settings.ViscousDrag = 0.05f;
                    settings.DragCoefficient = 1.2f;
                    settings.Wind = new Float3(0f, 0f, 8f);
                    return Pinned(settings, TimeIntegrator.Bdf2, new Float3(3.2f, 0f, 0f));
                }
                case "bdf2-plane":
                {
                    var rope = Pinned(RopeTestKit.Legacy(length: 4.8f, segments: 48), TimeIntegrator.Bdf2, new Float3(4.8f, 0f, 0f));
                    rope.AddCollider(ColliderShape.Plane(new Float3(0f, -2.5f, 0f), new Float3(0.2f, 1f, 0f).NormalizedOr(new Float3(0f, 1f, 0f)), 0.4f));
                    return rope;
                }
                case "plastic-neck":
                {
                    var settings = new RopeSettings { SegmentCount = 32, RestLength = 3.2f, Integrator = TimeIntegrator.Bdf2, MaterialModel = MaterialModel.ElasticPlastic };
                    var rope = new Rope(settings, Float3.Zero, new Float3(0.64f, -3.2f, 0f));
                    rope.AddPin(0, Float3.Zero);
                    rope.AddLoad(32, 100f);
                    rope.SetLoadState(0, rope.GetPosition(32), new Float3(0f, -6f, 0f));
                    return rope;
                }
                case "bilateral-softpin":
                {
                    var settings = RopeTestKit.Legacy(length: 2.4f, segments: 24);
                    settings.Tension = TensionModel.Bilateral;
                    var rope = Pinned(settings, TimeIntegrator.Bdf2, new Float3(2.4f, 0f, 0f));
                    rope.AddPin(24, new Float3(1.5f, -0.8f, 0.3f), 1e-4f);
                    return rope;
                }
                case "broken-middle":
                {
                    var rope = Pinned(RopeTestKit.Legacy(length: 4f, segments: 40), TimeIntegrator.Bdf2, new Float3(4f, 0f, 0f));
                    rope.AddPin(40, new Float3(4f, 0f, 0f));
                    drive = (r, k) => { if (k == 30) r.BreakSegment(20); };
                    return rope;
                }
                case "moving-pins":
                {
                    var rope = Pinned(RopeTestKit.Legacy(length: 2f, segments: 64), TimeIntegrator.Bdf2, new Float3(1.6f, 0f, 0f));
                    rope.AddPin(64, new Float3(1.6f, 0f, 0f));
                    drive = (r, k) => r.SetPinTarget(0, new Float3(0.3f * MathF.Sin(0.2f * k), 0.1f * k / HostSteps, 0f));
                    return rope;
                }
                case "short-5":
                {
                    return Pinned(RopeTestKit.Legacy(length: 0.5f, segments: 5), TimeIntegrator.Bdf2, new Float3(0.5f, 0f, 0f));
                }
                case "tail-13-mid-pin":
                {
                    var settings = RopeTestKit.Legacy(length: 1.3f, segments: 13, iterations: 2);
                    settings.Integrator = TimeIntegrator.Bdf2;
                    var rope = new Rope(settings, new Float3(-0.65f, 0f, 0f), new Float3(0.65f, 0f, 0f));
                    rope.AddPin(6, new Float3(-0.05f, 0f, 0f));
                    return rope;
                }
                case "gauss-seidel-bdf2":
                {
                    var rope = Pinned(RopeTestKit.Legacy(length: 3.3f, segments: 33, solver: ConstraintSolverKind.GaussSeidel), TimeIntegrator.Bdf2, new Float3(0.5f, -3.2f, 0f));
                    rope.AddLoad(33, 20f);
                    return rope;
                }
                default: throw new ArgumentException("unknown scene " + name, nameof(name));
            }
        }

        /// <summary>A rope of <paramref name="settings"/> under <paramref name="integrator"/> from a rigid pin at the origin to <paramref name="end"/> (rope-local m).</summary>
        static Rope Pinned(RopeSettings settings, TimeIntegrator integrator, Float3 end)
        {
            settings.Integrator = integrator;
            var rope = new Rope(settings, Float3.Zero, end);
            rope.AddPin(0, Float3.Zero);
            return rope;
        }

        /// <summary>
        /// State bits after each host step with the vector paths on (<paramref name="vectors"/>) or off, and the bits of
        /// each step's report (the residual, which the lane path of ComputeResidual forms, and the solve's counts) in
        /// <paramref name="reports"/>.
        /// </summary>
        static ulong[] Run(string name, bool vectors, out ulong[] reports)
        {
            VectorPath.Enabled = vectors;
            Rope rope = Build(name, out Action<Rope, int> drive);
            var bits = new ulong[HostSteps + 1];
            reports = new ulong[HostSteps + 1];
            bits[0] = rope.StateBits();
            for (int k = 0; k < HostSteps; k++)
            {
                drive?.Invoke(rope, k);
                StepReport report = rope.Step(HostStep);
                bits[k + 1] = rope.StateBits();
                reports[k + 1] = ReportBits(report);
            }
            return bits;
        }

        /// <summary>The residual's bits in the high half, a fold of the report's counts in the low half.</summary>
        static ulong ReportBits(StepReport report)
        {
            uint counts = (uint)report.Iterations;
            counts = counts * 31u + (uint)report.Substeps;
            counts = counts * 31u + (uint)report.SolveIterations;
            counts = counts * 31u + (uint)report.LinearSolves;
            counts = counts * 31u + (uint)report.ViolentSubsteps;
            counts = counts * 31u + (uint)report.ShortenedSteps;
            counts = counts * 31u + (uint)report.UnconvergedSubsteps;
            return ((ulong)(uint)BitConverter.SingleToInt32Bits(report.Residual) << 32) | counts;
        }

        [TestCaseSource(nameof(Scenes))]
        public void VectorPathsGiveTheScalarBits(string scene)
        {
            ulong[] scalar = Run(scene, false, out ulong[] scalarReports);
            ulong[] lanes = Run(scene, true, out ulong[] laneReports);
            // the scene moves (the state changes every step), and every step's state and report are the same bits both ways
            Assert.That(scalar[HostSteps], Is.Not.EqualTo(scalar[HostSteps - 1]));
            int residuals = 0;
            for (int k = 0; k <= HostSteps; k++)
            {
                Assert.That(lanes[k], Is.EqualTo(scalar[k]), "host step " + k + " of " + scene);
                Assert.That(laneReports[k], Is.EqualTo(scalarReports[k]), "report of host step " + k + " of " + scene);
                if ((scalarReports[k] >> 32) != 0) residuals++;
            }
            // the residual compared is a reading, not zero throughout
            Assert.That(residuals, Is.GreaterThan(0), "steps with a non-zero residual in " + scene);
        }

        [Test]
        public void VectorPathsAllocateNothingPerStep()
        {
            VectorPath.Enabled = true;
            Rope rope = Build("goal-lanyard", out _);
            // the fewest bytes of several rounds of 10 steps: a round may see the runtime's own (tiered JIT) allocations
            long fewest = long.MaxValue;
            for (int round = 0; round < 8; round++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                for (int k = 0; k < 10; k++) rope.Step(HostStep);
                fewest = Math.Min(fewest, GC.GetAllocatedBytesForCurrentThread() - before);
            }
            Assert.That(fewest, Is.EqualTo(0L), "bytes allocated by 10 steps");
        }
    }
}
