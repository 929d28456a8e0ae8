using BenchmarkDotNet.Attributes;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Bench
{
    /// <summary>
    /// A scene of 100 ropes × 64 segments at the default settings (16 substeps × 1 iteration, exact chain),
    /// each pinned at both ends and sagging, stepped once at 1/90 s. ns/unit = per segment-substep.
    /// </summary>
    [MemoryDiagnoser]
    public class SceneBenchmarks : IUnitCount
    {
        private const int RopeCount = 100, SegmentCount = 64;
        private Rope[] ropes;

        [Params(ConstraintSolverKind.GaussSeidel, ConstraintSolverKind.ExactChain)]
        public ConstraintSolverKind Solver { get; set; }

        public double Units => (double)RopeCount * SegmentCount * LegacySettings.Substeps;

        [GlobalSetup]
        public void Setup()
        {
            ropes = new Rope[RopeCount];
            for (int r = 0; r < RopeCount; r++)
            {
                var settings = LegacySettings.Create(2f, SegmentCount, Solver);
                var start = new Float3(r * 0.5f, 2f, 0f);
                var end = new Float3(r * 0.5f + 1.8f, 2f, 0f);
                ropes[r] = new Rope(settings, start, end);
                ropes[r].AddPin(0, start);
                ropes[r].AddPin(SegmentCount, end);
                for (int i = 0; i < 20; i++) ropes[r].Step(1f / 90f);
            }
        }

        [Benchmark]
        public float StepAll()
        {
            float residual = 0f;
            for (int r = 0; r < ropes.Length; r++) residual += ropes[r].Step(1f / 90f).Residual;
            return residual;
        }
    }
}
