using BenchmarkDotNet.Attributes;
using HookeRope.Mathematics;
using HookeRope.Solver;

namespace HookeRope.Bench
{
    /// <summary>
    /// One host step of a hanging, loaded rope with 1 substep × 10 iterations, so that the constraint
    /// iterations dominate: ns/unit ≈ ns per Gauss–Seidel projection, or per exact-solve segment-iteration
    /// (Thomas solve with its active-set passes, plus the Gauss–Seidel polish sweep).
    /// </summary>
    [MemoryDiagnoser]
    public class ChainBenchmarks : IUnitCount
    {
        private const int IterationCount = 10;
        private Rope rope;

        [Params(16, 64, 256, 1024, 10000)]
        public int Segments { get; set; }

        [Params(ConstraintSolverKind.GaussSeidel, ConstraintSolverKind.ExactChain)]
        public ConstraintSolverKind Solver { get; set; }

        public double Units => (double)Segments * IterationCount;

        [GlobalSetup]
        public void Setup()
        {
            var settings = LegacySettings.Create(10f, Segments, Solver);
            settings.Substeps = 1;
            settings.Iterations = IterationCount;
            rope = new Rope(settings, Float3.Zero, new Float3(0f, -10f, 0f));
            rope.AddPin(0, Float3.Zero);
            rope.AddLoad(Segments, 50f);
            for (int i = 0; i < 20; i++) rope.Step(1f / 90f);
        }

        [Benchmark]
        public float Step() => rope.Step(1f / 90f).Residual;
    }
}
